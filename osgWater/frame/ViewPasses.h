/* osgWater - natural water for OpenSceneGraph */
#ifndef OSGWATER_VIEWPASSES
#define OSGWATER_VIEWPASSES 1

#include "passes/ReflectionCamera.h"
#include "passes/RefractionCamera.h"
#include "frame/PassMeter.h"
#include "passes/GlowPasses.h"
#include "frame/PassTable.h"
#include "shaders/ProgramLibrary.h"
#include <osg/StateSet>
#include <osg/Vec2i>
#include <osg/observer_ptr>
#include <OpenThreads/Mutex>
#include <map>

namespace osgWater {

//! Everything one view needs of its own: its pass cameras, their textures, the StateSet with the
//! view's own scene lighting and the one with the water shader's per-view inputs. Created in cull
//! on the view's first frame, so several views in a CompositeViewer never share a texture or a
//! uniform that changes per view.
class OSGWATER_EXPORT ViewPasses : public osg::Referenced
{
public:
    //! `lighting`: the view's own SceneLighting StateSet (ViewPassesMap::getLighting()).
    ViewPasses(osg::Group* scene, osg::StateSet* sceneState, osg::StateSet* waterState, ProgramLibrary* programs,
               osg::StateSet* lighting, const osg::Vec2i& reflectionSize, const osg::Vec2i& refractionSize);

    //! Aims the passes `plan` runs, applies `lighting` to each of them, and sets the water shader's
    //! inputs, its defines following what runs. (The view's own lighting is the caller's.)
    void update(const PassContext& ctx, const PassPlan& plan, const SceneLighting& lighting);

    ReflectionCamera* getReflectionCamera() const { return _reflection.get(); }
    RefractionCamera* getRefractionCamera() const { return _refraction.get(); }
    //! The view's SceneLighting, pushed above the WaterNode's children in the view itself.
    osg::StateSet* getLightingStateSet() const { return _lighting.get(); }
    //! The water shader's per-view inputs: the pass textures, this view's pass matrices, the
    //! defines OSGWATER_EYE_BELOW, OSGWATER_EYE_AMONG_WAVES, OSGWATER_NO_REFLECTION, OSGWATER_NO_REFRACTION.
    osg::StateSet* getWaterInputs() const { return _waterInputs.get(); }

    //! Whether the targets have these sizes (width, height).
    bool matchesSizes(const osg::Vec2i& reflectionSize, const osg::Vec2i& refractionSize) const;

    //! This view's glow passes for a width x height target, made (or remade, when the view's size
    //! changed) on demand; the previous ones are released.
    GlowPasses* getOrCreateGlow(int width, int height, bool floatTargets);
    //! The glow passes of the last frame that had a glow, or nullptr.
    GlowPasses* getGlow() const { return _glow.get(); }
    //! The passes the last frame ran for this view.
    const PassPlan& getPlan() const { return _plan; }
    //! Whether the last frame drew the glow.
    bool getGlowDrawn() const { return _plan.runs(PASS_GLOW_COMPOSITE); }
    //! Whether the last frame's eye was under the surface (the wave height at the eye).
    bool getEyeBelow() const { return _eyeBelow; }

    //! Measure the passes' GPU time (GL timer queries); read with the getters below.
    void setTimingEnabled(bool on);
    //! Last GPU time of each pass in ms (negative when not measured).
    PassMeasure getReflectionMeasure() const { return _reflectionMeter->getMeasure(); }
    PassMeasure getRefractionMeasure() const { return _refractionMeter->getMeasure(); }

    void resizeGLObjectBuffers(unsigned int maxSize);
    void releaseGLObjects(osg::State* state) const;

protected:
    virtual ~ViewPasses() {}
    osg::Group* _scene; // the WaterNode: outlives its passes
    osg::ref_ptr<osg::StateSet> _sceneState, _waterState;
    osg::ref_ptr<ProgramLibrary> _programs; // the water's: the glow passes take theirs from it
    osg::ref_ptr<ReflectionCamera> _reflection;
    osg::ref_ptr<RefractionCamera> _refraction;
    osg::ref_ptr<osg::StateSet> _lighting, _waterInputs;
    osg::ref_ptr<PassMeter> _reflectionMeter, _refractionMeter;
    osg::ref_ptr<GlowPasses> _glow;
    PassPlan _plan;
    bool _timing = false, _eyeBelow = false;
};

//! The per-view map: keyed by the camera whose cull visits the water, guarded by a mutex for
//! multi-threaded culling, and pruned when a camera goes away. Every view has its own lighting
//! StateSet; a view gets passes only once one of them runs.
class OSGWATER_EXPORT ViewPassesMap
{
public:
    //! This camera's own SceneLighting StateSet (DYNAMIC), made on its first cull.
    osg::StateSet* getLighting(osg::Camera* camera);
    //! This camera's passes, made (or remade, when a texture size changed) on demand.
    ViewPasses* get(osg::Camera* camera, osg::Group* scene, osg::StateSet* sceneState, osg::StateSet* waterState,
                    ProgramLibrary* programs, const osg::Vec2i& reflectionSize, const osg::Vec2i& refractionSize);
    //! The passes a camera's view ran on its last frame (none before its first).
    void setPlan(osg::Camera* camera, const PassPlan& plan);
    PassPlan getPlan(osg::Camera* camera) const;
    //! What the camera's view did on its last frame (ViewReport's view fields), under the lock.
    void report(osg::Camera* camera, ViewReport& r) const;
    //! Existing passes of a camera, or nullptr.
    ViewPasses* find(osg::Camera* camera) const;
    //! Views holding passes.
    size_t size() const;
    void clear();

    void resizeGLObjectBuffers(unsigned int maxSize);
    void releaseGLObjects(osg::State* state) const;

private:
    struct Entry {
        osg::observer_ptr<osg::Camera> camera;
        osg::ref_ptr<osg::StateSet> lighting;
        osg::ref_ptr<ViewPasses> passes;
        PassPlan plan; // the camera's last frame's
    };
    Entry& entry(osg::Camera* camera); // call with _mutex held
    mutable OpenThreads::Mutex _mutex;
    std::map<const osg::Camera*, Entry> _map;
};

}

#endif
