/* osgWater - natural water for OpenSceneGraph */
#ifndef OSGWATER_WATERNODEIMPL
#define OSGWATER_WATERNODEIMPL 1

#include <osgWater/WaterNode>
#include "frame/WaterStateSets.h"
#include "frame/ViewPasses.h"
#include "caustics/CausticsScheduler.h"
#include "passes/EnvironmentMap.h"
#include "frame/SceneBounds.h"
#include "passes/UnderwaterView.h"
#include "frame/PassTable.h"
#include "frame/SceneLighting.h"
#include "frame/PassMeter.h"
#include <atomic>
#include <map>
#include <set>
#include <string>

namespace osgWater {

//! WaterNode's private implementation: the per-view frame, its facts and cull steps, the shared
//! caustics and environment passes, the states. The node forwards to it; tests reach it through
//! internals().
class OSGWATER_EXPORT WaterNodeImpl
{
public:
    explicit WaterNodeImpl(WaterNode& node);
    WaterNodeImpl(WaterNode& node, const WaterNodeImpl& other, const osg::CopyOp& copyop);

    static WaterNodeImpl& of(const WaterNode& node) { return *node._impl; }

    // --- white-box access (tests, the benchmark's probes): not part of the public API
    //! The passes a camera's view uses (after its first cull), or nullptr.
    ViewPasses* getViewPasses(osg::Camera* camera) const { return _views.find(camera); }
    //! The passes the view of `camera` ran on its last frame.
    PassPlan getPassPlan(osg::Camera* camera) const { return _views.getPlan(camera); }
    //! The caustics passes (shared by all views; created on the first frame that needs them), or nullptr.
    CausticsCamera* getCausticsCamera() const { return _caustics.getCamera(); }
    //! The reflective caustics' passes, or nullptr.
    CausticsCamera* getReflectedCausticsCamera() const { return _caustics.getReflectedCamera(); }
    //! The passes drawing the environment map, or nullptr (off, or the user's map).
    EnvironmentMap* getEnvironmentPasses() const { return _environment.get(); }
    //! The near-plane cap and the underwater backdrop (shared by all views).
    UnderwaterView* getUnderwaterView() const { return _underwater.get(); }
    //! Shared states: the scene program (children) and the water program (surface).
    WaterStateSets& getStateSets() { return _states; }

    // --- what WaterNode forwards to
    void setSettings(WaterSettings* settings);
    void setSurface(WaterSurface* surface);
    void setDebugOutput(DebugOutput d);
    void setPassTimingEnabled(bool on);
    PassMeasure getPassMeasure(osg::Camera* camera, PassId pass) const;
    ViewReport getViewReport(osg::Camera* camera) const;
    void setSkippingEnabled(bool on);
    double getCausticsHoldTime() const;
    WaterSettings::CausticsGather getActiveCausticsGather() const;
    void setEnvironmentMap(osg::TextureCubeMap* map);
    osg::TextureCubeMap* getEnvironmentMap() const;
    void dirtyEnvironmentMap();
    double getSurfaceHeightAt(double x, double y, double t, osg::Vec3d* normal = nullptr) const;
    double eyeHeightAboveSurface(const osg::Vec3d& eye, double t) const;
    void traverse(osg::NodeVisitor& nv);
    void resizeGLObjectBuffers(unsigned int maxSize);
    void releaseGLObjects(osg::State* state) const;

    //! What one view is and has this frame (gathered once, read by every step of cull).
    struct ViewFrame {
        PassContext ctx;
        FrameFacts facts;
        osg::StateSet* lighting = nullptr; //!< the view's own SceneLighting
        ViewPasses* passes = nullptr;      //!< the view's passes, when any runs
        CausticsSupport support;
        unsigned int contextID = 0, frameNumber = 0;
        double time = 0.0; //!< simulation time of the frame
    };

    void cull(osgUtil::CullVisitor& cv);
    //! Inside another water's pass: the children and the surface under the guest program, no passes.
    void cullAsGuest(osgUtil::CullVisitor& cv);
    //! Says once that a non-uniform scale above the node distorts distances and the sun.
    void warnIfScaledUnevenly(const osg::Matrixd& view);
    //! A line-segment intersector meets the animated surface (the grid's CPU geometry is flat).
    void intersectSurface(osgUtil::IntersectionVisitor& iv);
    ViewFrame gatherFacts(osgUtil::CullVisitor& cv);
    ViewPasses* viewPasses(osgUtil::CullVisitor& cv, const ViewFrame& v);
    SceneLighting sceneLighting(const ViewFrame& v, const PassPlan& plan) const;
    void cullPass(PassId pass, osgUtil::CullVisitor& cv, const ViewFrame& v);
    void refreshStates();
    //! Whether each pass ran and its last GPU time, into the view's osg::Stats for this frame.
    void recordPassStats(osgUtil::CullVisitor& cv, const ViewFrame& v, const PassPlan& plan) const;
    //! In the update traversal: the children's boxes and the lit water (the caustics' window), and
    //! the plane-offset lookups' planes.
    void updateSceneFacts(const osg::BoundingSphere& children);
    //! How far above the level the water reaches, with the clip offset: the underwater passes keep
    //! what lies below level + clearance (the caustics, the lit water, every pass's context).
    double clearance() const;
    //! In the update traversal: the environment map in use, the drawn one made or resized and aimed.
    void updateEnvironment(const osg::BoundingSphere& children);
    //! This view draws the environment map on its context, unless another view did since it went stale.
    bool claimEnvironment(unsigned int contextID);
    //! The glow passes sized for this view (when the plan runs them).
    void prepareGlow(osgUtil::CullVisitor& cv, const ViewFrame& v);
    //! What a context can render into (asked once per context).
    CausticsSupport support(unsigned int contextID);
    //! A target size the context can allocate (GL_MAX_TEXTURE_SIZE), saying once when it is not `size`.
    int fitTexture(const char* what, int size, const CausticsSupport& support);

    WaterNode& _node; //!< the node this implements: its children are the scene
    osg::ref_ptr<WaterSettings> _settings;
    osg::ref_ptr<WaterSurface> _surface;
    DebugOutput _debug;
    bool _passTiming = false;
    osg::ref_ptr<PassMeter> _surfaceMeter; // the grid's draw (a user mesh is the user's: not timed)
    bool _skipping = true;
    std::atomic<double> _simulationTime{ 0.0 };
    WaterStateSets _states;
    mutable ViewPassesMap _views;
    unsigned int _settingsRevision, _surfaceRevision;
    const void* _appliedSettings;
    const void* _appliedSurface;

    osg::ref_ptr<UnderwaterView> _underwater;
    mutable OpenThreads::Mutex _supportMutex;
    CausticsScheduler _caustics; // one set of passes for all views (after _states, which it reads)
    std::map<unsigned int, CausticsSupport> _support; // context -> what it can do (asked once)
    osg::Vec2f _lookupPlanes{ 1.0f, 1.0f }; // in use: reflection plane height, refraction plane depth
    std::set<std::string> _fitWarnings; // what fitTexture() has said already
    std::atomic<bool> _warnedUnevenScale{ false };
    // the environment cube map: the user's, or drawn from the scene (its passes)
    osg::ref_ptr<osg::TextureCubeMap> _userEnvironment;
    osg::ref_ptr<EnvironmentMap> _environment;
    mutable OpenThreads::Mutex _environmentMutex; // the per-context drawn marks
};

//! The private implementation of a node (tests and the benchmark's probes).
inline WaterNodeImpl& internals(const WaterNode& node) { return WaterNodeImpl::of(node); }

}

#endif
