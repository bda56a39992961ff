/* osgWater - natural water for OpenSceneGraph */
#ifndef OSGWATER_CAUSTICSSCHEDULER
#define OSGWATER_CAUSTICSSCHEDULER 1

#include "caustics/CausticsCamera.h"
#include "frame/PassTable.h"
#include "frame/SceneBounds.h"
#include "frame/SceneLighting.h"
#include <osgWater/Statistics>
#include <OpenThreads/Mutex>
#include <atomic>
#include <functional>
#include <map>

namespace osgWater {

class WaterNode;
class WaterStateSets;

//! One water's caustics, shared by every view and context: aimed once per frame (by whichever view
//! culls first), rendered once per frame and context (by whichever view claims them), and reused on
//! later frames while the waves cannot have moved them visibly. Owns the refractive caustics'
//! passes and, when on and something stands above the water, the reflective ones; everything here
//! is guarded by one mutex, so views may cull in parallel.
class OSGWATER_EXPORT CausticsScheduler
{
public:
    //! `water`: the node whose children are the scene and whose settings and surface the caustics
    //! follow; `states`: its scene and water state sets.
    CausticsScheduler(WaterNode& water, WaterStateSets& states);

    //! A target size the context can allocate (what, size) -> size.
    using FitTexture = std::function<int(const char*, int)>;

    //! In the update traversal: the children's boxes and the lit water (the caustics' window), which
    //! the rays along the sun are walked for only when `walkLitWater`; returns the lit water.
    LitWater updateScene(const osg::BoundingSphere& children, double keepBelow, bool walkLitWater);

    //! A view's cull: aims the passes if this frame has not yet (made or remade at the sizes the
    //! context can hold), then says in `facts` whether this context has caustics for this frame
    //! already and whether its sun depth maps are stale.
    void prepare(unsigned int frame, unsigned int contextID, double time, double clearance,
                 const CausticsSupport& support, const FitTexture& fit, FrameFacts& facts);
    //! This view renders the frame's caustics on its context, unless another view claimed them
    //! first. The first claim of a frame that gathers resolves the gather.
    bool claim(unsigned int frame, unsigned int contextID, double time, const FrameFacts& facts, const PassPlan& plan,
               const CausticsSupport& support);
    //! The caustics' part of a pass's lighting, when this frame has them on this context.
    void light(const FrameFacts& facts, SceneLighting& lighting) const;
    //! Accepts a caustics row's cameras (PASS_SUN_DEPTH, PASS_PHOTONS, PASS_GATHER).
    void cull(PassId pass, osgUtil::CullVisitor& cv, const FrameFacts& facts);

    //! How long, in simulation seconds, rendered caustics are reused while the waves move.
    double getHoldTime() const;
    //! The passes' GPU times and fragments (PASS_SUN_DEPTH, PASS_PHOTONS: photons and gather);
    //! negative without passes.
    PassMeasure getMeasure(PassId pass) const;
    //! The caustics' fields of a view report.
    void report(ViewReport& r) const;
    WaterSettings::CausticsGather getActiveGather() const;
    void setTimingEnabled(bool on);

    //! The passes (white-box: tests, the benchmark's probes), or nullptr.
    CausticsCamera* getCamera() const { return _caustics.get(); }
    CausticsCamera* getReflectedCamera() const { return _reflected.get(); }

    void resizeGLObjectBuffers(unsigned int maxSize);
    void releaseGLObjects(osg::State* state) const;

private:
    void aim(unsigned int frame, double clearance, const CausticsSupport& support, const FitTexture& fit);
    //! Whether caustics rendered at time `renderedAt` for aim `aim` still hold at time `t`: nothing
    //! but time changed and the waves moved their pattern by at most the settings' motion tolerance
    //! in caustics texels.
    bool stillHold(unsigned int aim, double renderedAt, double t) const;
    double holdTime() const; // getHoldTime() with the mutex held

    WaterNode& _water;
    WaterStateSets& _states;
    bool _timing = false;
    mutable OpenThreads::Mutex _mutex;
    osg::ref_ptr<CausticsCamera> _caustics;
    osg::ref_ptr<CausticsCamera> _reflected; // the reflective caustics' passes, when on
    bool _needed = false;                    // this frame's verdict
    bool _reflectedNeeded = false;
    unsigned int _aimedFrame = ~0u;          // the frame they were aimed for
    unsigned int _gatherResolved = ~0u;      // the frame whose gather was chosen
    // what the caustics depend on besides time: a new number whenever it changes
    struct AimKey {
        const void* camera = nullptr;
        const void* reflectedCamera = nullptr;
        const void* settingsObject = nullptr;
        const void* surfaceObject = nullptr;
        unsigned int settings = ~0u, surface = ~0u, depth = ~0u, reflectedDepth = ~0u;
        bool operator!=(const AimKey& o) const
        {
            return camera != o.camera || reflectedCamera != o.reflectedCamera || settingsObject != o.settingsObject ||
                   surfaceObject != o.surfaceObject || settings != o.settings || surface != o.surface ||
                   depth != o.depth || reflectedDepth != o.reflectedDepth;
        }
    } _aimKey;
    unsigned int _aim = 0;
    struct Rendered { unsigned int frame = ~0u, aim = ~0u; double time = 0.0; };
    mutable std::map<unsigned int, Rendered> _rendered; // context -> last rendering
    SceneBoxes _sceneBoxes;                             // the children's box and the lit water
    std::atomic<bool> _warnedTile{ false }; // the waves do not repeat over the caustics tile (said once)
};

}

#endif
