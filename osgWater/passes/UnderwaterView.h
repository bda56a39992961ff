/* osgWater - natural water for OpenSceneGraph */
#ifndef OSGWATER_UNDERWATERVIEW
#define OSGWATER_UNDERWATERVIEW 1

#include <osgWater/Export>
#include <osg/Geode>
#include "frame/PassMeter.h"
#include <atomic>

namespace osgWater {

class ProgramLibrary;

//! What a view needs beyond its passes when the eye is near or under the surface (thesis §7.5):
//! - the near-plane cap: where the eye's ray crosses the surface before the near plane (a camera
//!   on or just off the water), the surface is shaded at the crossing (shaders/cap.frag), so a
//!   frame never shows a hole in the water, only the waterline itself;
//! - the underwater backdrop: under water, pixels that meet nothing show the water colour.
//! Both are full-screen triangles, shared by all views (per-view data comes from ViewPasses),
//! drawn by the pass table's rows PASS_BACKDROP and PASS_CAP.
class OSGWATER_EXPORT UnderwaterView : public osg::Referenced
{
public:
    explicit UnderwaterView(ProgramLibrary& programs);

    osg::Geode* getCap() const { return _cap.get(); }
    osg::Geode* getBackdrop() const { return _backdrop.get(); }

    //! The band the animated surface stays in: the cap is drawn only when the near plane OSG
    //! computed for the frame reaches it (nearPlaneReachesWater, decided at draw time).
    void setWaveBand(double level, double waveBound);
    //! Off: the cap is drawn whenever the view plans it (the reference its skip is tested against).
    void setCapSkipping(bool on) { _skipping = on; }
    //! Cap draws skipped and drawn since construction (all views).
    unsigned int getCapSkips() const { return _capSkips.load(); }
    unsigned int getCapDraws() const { return _capDraws.load(); }

    //! GPU times of the cap and the backdrop, ms (negative until measured or while timing is off).
    PassMeasure getCapMeasure() const { return _capMeter->getMeasure(); }
    PassMeasure getBackdropMeasure() const { return _backdropMeter->getMeasure(); }
    void setTimingEnabled(bool on);

    void resizeGLObjectBuffers(unsigned int maxSize);
    void releaseGLObjects(osg::State* state) const;

protected:
    virtual ~UnderwaterView() {}
    class CapSkip;
    bool capNeeded(const osg::Matrixd& modelView, const osg::Matrixd& projection) const;
    osg::ref_ptr<osg::Geode> _cap, _backdrop;
    osg::ref_ptr<PassMeter> _capMeter, _backdropMeter;
    std::atomic<double> _level{ 0.0 }, _waveBound{ 0.0 };
    std::atomic<bool> _skipping{ true };
    mutable std::atomic<unsigned int> _capSkips{ 0 }, _capDraws{ 0 };
};

}

#endif
