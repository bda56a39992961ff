/* osgWater - natural water for OpenSceneGraph */
#ifndef OSGWATER_WATERSTATESETS
#define OSGWATER_WATERSTATESETS 1

#include <osgWater/Export>
#include <osgWater/Statistics>
#include "shaders/ProgramLibrary.h"
#include <osg/StateSet>
#include <osg/TextureCubeMap>
#include <mutex>

namespace osgWater {

class WaterSettings;
class WaterSurface;
namespace detail { class SpectralWaves; }


//! The StateSets shared by every view: the scene program for the WaterNode's children, the water
//! program with the settings' uniforms and defines, and the guest program that replaces it where
//! the water is drawn inside another water's pass (above the water StateSet: same uniforms). Refreshed from the settings and
//! surface when their revisions change, and from the time every frame.
class OSGWATER_EXPORT WaterStateSets
{
public:
    WaterStateSets();

    osg::StateSet* getSceneStateSet() const { return _scene.get(); }
    osg::StateSet* getWaterStateSet() const { return _water.get(); }
    osg::StateSet* getGuestStateSet() const { return _guest.get(); }
    //! The water's programs, shared by every pass that asks for the same one.
    ProgramLibrary& getPrograms() const { return *_programs; }
    //! The view's surface pass's render bin (PASS_SURFACE: before the scene's).
    osg::StateSet* getSurfaceBinStateSet() const { return _surfaceBin.get(); }

    //! Uniforms and defines from settings and surface (call when either changed).
    void applySettings(const WaterSettings& settings, const WaterSurface& surface, DebugOutput debug);
    //! The waves as of simulation time t: the sum's phases, the wind's cascade textures. Views
    //! call it from their culls (in parallel, each for the frame's time) when a pass reads them.
    void applyTime(const WaterSurface& surface, double t);
    //! The plane-offset lookups' planes: height above the level for the reflection, depth below it
    //! for the refraction, metres.
    void applyLookupPlanes(const osg::Vec2f& heightDepth);
    //! The environment cube map the water program reads (OSGWATER_ENVIRONMENT), or none.
    void setEnvironmentMap(osg::TextureCubeMap* map);

    void resizeGLObjectBuffers(unsigned int maxSize);
    void releaseGLObjects(osg::State* state) const;

private:
    //! The wind's texture, scales and define, or none (the sum of sines).
    void applyWind(detail::SpectralWaves* wind);

    osg::ref_ptr<ProgramLibrary> _programs; // first: the state sets below take theirs from it
    osg::ref_ptr<osg::StateSet> _scene, _water, _guest, _surfaceBin;
    std::mutex _timeLock; // applyTime from the views' culls
};

}

#endif
