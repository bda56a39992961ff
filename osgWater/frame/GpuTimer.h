/* osgWater - natural water for OpenSceneGraph */
#ifndef OSGWATER_GPUTIMER
#define OSGWATER_GPUTIMER 1

#include <osgWater/Export>
#include <osg/Camera>
#include <osg/Drawable>
#include <osg/buffered_value>
#include <atomic>

namespace osgWater {

//! GPU time of one camera's draw, from two GL timestamp queries (osg::GLExtensions wraps them):
//! timestamps, unlike GL_TIME_ELAPSED queries, may overlap other timers (a second water's caustics
//! drawn between this one's photon and gather passes). The result of frame n is read at frame
//! n + 1, so timing never stalls the pipeline. Install with attach().
class OSGWATER_EXPORT GpuTimer : public osg::Referenced
{
public:
    GpuTimer();
    //! Sets the camera's initial and final draw callbacks to start and stop the query.
    void attach(osg::Camera* camera);
    void detach(osg::Camera* camera);
    //! Times a sequence of cameras drawn one after the other: from first's start to last's end.
    void attach(osg::Camera* first, osg::Camera* last);
    //! Times a drawable's draw (its draw callback: set it once, not while it is being drawn).
    void attach(osg::Drawable* drawable);
    //! Off, begin() and end() do nothing and the last measurement is forgotten (on by default).
    void setEnabled(bool on);
    bool getEnabled() const { return _enabled.load(); }
    //! Last measured GPU time in milliseconds (negative until one is available or without timer queries).
    double getMilliseconds() const { return _ms.load(); }

    void begin(osg::RenderInfo& ri);
    void end(osg::RenderInfo& ri);

protected:
    virtual ~GpuTimer() {}
    std::atomic<double> _ms;
    std::atomic<bool> _enabled{ true };
    // per context (the caustics' timer is drawn by every context that renders them, each in its
    // own draw thread): sized once, so no thread resizes it under another
    struct Query {
        unsigned int ids[2] = { 0, 0 }; // start, stop timestamps
        bool pending = false; // a query ended, its result not read yet
        bool active = false;  // a query begun in this frame
        bool failed = false;
    };
    osg::buffered_object<Query> _queries;
};

}

#endif
