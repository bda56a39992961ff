/* osgWater - natural water for OpenSceneGraph */
#ifndef OSGWATER_PASSMETER
#define OSGWATER_PASSMETER 1

#include <osgWater/Export>
#include <osg/Camera>
#include <osg/Drawable>
#include <osg/buffered_value>
#include <atomic>

namespace osgWater {

//! What one pass cost the GPU on its last measured frame; negative where not measured.
struct PassMeasure {
    double milliseconds = -1.0;
    //! Fragment shader invocations: the work the pass asked of the rasteriser, which unlike its time
    //! does not depend on the machine's load.
    double fragments = -1.0;
    //! Two passes measured as one (each negative where the other was not measured: the one that was).
    PassMeasure operator+(const PassMeasure& o) const;
};

//! GPU time and fragment shader invocations of one camera's draw (or a drawable's). The time comes
//! from two GL timestamp queries (osg::GLExtensions wraps them): timestamps, unlike GL_TIME_ELAPSED
//! queries, may overlap other meters (a second water's caustics drawn between this one's photon
//! and gather passes). The fragments come from a GL_FRAGMENT_SHADER_INVOCATIONS query
//! (GL_ARB_pipeline_statistics_query, core in GL 4.6), which may not: while another meter counts
//! on the same context, this one does not, and keeps its last count. Results of frame n are read
//! at frame n + 1, so measuring never stalls the pipeline. Install with attach().
class OSGWATER_EXPORT PassMeter : public osg::Referenced
{
public:
    PassMeter();
    //! Sets the camera's initial and final draw callbacks to start and stop the queries.
    void attach(osg::Camera* camera);
    void detach(osg::Camera* camera);
    //! Measures a sequence of cameras drawn one after the other: from first's start to last's end.
    void attach(osg::Camera* first, osg::Camera* last);
    //! Measures a drawable's draw (its draw callback: set it once, not while it is being drawn).
    void attach(osg::Drawable* drawable);
    //! Off, begin() and end() do nothing and the last measurement is forgotten (on by default).
    void setEnabled(bool on);
    bool getEnabled() const { return _enabled.load(); }
    //! Last measured GPU time in milliseconds (negative until one is available or without timer queries).
    double getMilliseconds() const { return _ms.load(); }
    //! Last counted fragment shader invocations (negative until counted or without the queries).
    double getFragments() const { return _fragments.load(); }
    PassMeasure getMeasure() const { return { getMilliseconds(), getFragments() }; }

    void begin(osg::RenderInfo& ri);
    void end(osg::RenderInfo& ri);
    //! Hands the context's query names (every context's without a state) to OSG for deletion in
    //! its next draw; the meter makes new ones when it next measures there.
    void releaseGLObjects(osg::State* state) const;

protected:
    //! Hands every context's query names to OSG for deletion in that context's next draw.
    virtual ~PassMeter();
    std::atomic<double> _ms, _fragments;
    std::atomic<bool> _enabled{ true };
    // per context (the caustics' meter is drawn by every context that renders them, each in its
    // own draw thread): sized once, so no thread resizes it under another
    struct Query {
        unsigned int ids[3] = { 0, 0, 0 }; // start, stop timestamps; fragment invocations
        bool pending = false;  // queries ended, their results not read yet
        bool counted = false;  // ... and the fragments among them
        bool active = false;   // queries begun in this frame
        bool counting = false; // ... and the fragments' among them
        bool failed = false;   // no timer queries
    };
    mutable osg::buffered_object<Query> _queries;
    //! The results of the queries `q` ended, where they are in (else `q` stays pending).
    void readLastFrame(osg::GLExtensions& ext, Query& q);
};

}

#endif
