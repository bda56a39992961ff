/* osgWater - natural water for OpenSceneGraph */
#ifndef OSGWATER_CAUSTICSCAMERA
#define OSGWATER_CAUSTICSCAMERA 1

#include "frame/PassCamera.h"
#include "caustics/PhotonCamera.h"
#include "caustics/PhotonGather.h"
#include "shaders/ProgramLibrary.h"
#include "frame/PassMeter.h"
#include <osg/BoundingBox>
#include <map>
#include <vector>

namespace osgUtil { class CullVisitor; }

namespace osgWater {

class WaterSettings;

//! What the context can do for caustics (decided once per context).
struct OSGWATER_EXPORT CausticsSupport {
    bool floatTargets = true;   //!< float colour attachments (else 16-bit normalised + CPU gather)
    bool pixelBuffers = true;   //!< buffer objects as pixel-pack targets (GATHER_POINTS_COPY)
    bool vertexTextures = true; //!< texelFetch in the vertex shader (GATHER_POINTS_TEXTURE)
    int maxTextureSize = 4096;  //!< GL_MAX_TEXTURE_SIZE: every pass target is clamped to it

    //! From the context's GL version and extensions; OSGWATER_NO_FLOAT_TARGETS=1 in the
    //! environment pretends float targets are missing (to exercise the fallback).
    static CausticsSupport detect(unsigned int contextID);
    //! Whether this context can run a gather method (GATHER_AUTO: no).
    bool supports(WaterSettings::CausticsGather method) const;
};

//! The caustics of the water (thesis ch. 8): an orthographic camera along the sun covering the
//! water's bounds. It renders pass 1 itself (the depth of the underwater scene seen from the sun,
//! depth only), with a second depth-only camera for what shades the water (the whole scene seen
//! from the sun), and owns pass 2 (PhotonCamera) and pass 3 (PhotonGather). The result depends on the
//! sun and the water, not on the viewer: WaterNode aims it once per frame and renders it once per
//! frame and context, for all views (the pass table's rows PASS_SUN_DEPTH, PASS_PHOTONS, PASS_GATHER).
class OSGWATER_EXPORT CausticsCamera : public PassCamera
{
public:
    //! `reflected`: the reflective caustics (WaterSettings::setReflectiveCaustics): the scene above
    //! the water mirrored in the water plane takes the underwater scene's place, and the photons
    //! are the sun's reflection (PhotonCamera::setSun with a mirror).
    CausticsCamera(osg::Group* scene, osg::StateSet* sceneState, osg::StateSet* waterState, ProgramLibrary& programs,
                   int resolution, int gridSize, bool floatTargets, bool reflected = false);

    //! This frame's inputs, in the water's local frame.
    struct Frame {
        osg::Vec3 towardsSun;
        osg::BoundingBox water;        //!< the surface's bounds (only x, y are used)
        osg::BoundingBox scene;        //!< the children's bounds
        osg::BoundingBox litWater;     //!< where sunlight can enter the water and land (findLitWater())
        double level = 0.0;
        double clearance = 0.0;        //!< wave amplitude + clip offset
        double tile = 0.0;             //!< tileable caustics: the tile's side (0: off)
        double tileBedZ = 0.0;         //!< ... and the flat bed they are computed over
        osg::Node* surface = nullptr;
        const WaterSettings* settings = nullptr;
    };

    //! Whether caustics can show at all: the sun above the horizon and something under the water.
    static bool needed(const Frame& f);
    //! Whether reflective caustics can show: the sun above the horizon and something above the water.
    static bool reflectedNeeded(const Frame& f);
    bool isReflected() const { return _reflected; }
    //! The tile of tileable caustics for a frame: its lower corner, the tile centred on the
    //! water's middle (where the surface is sampled; the lookup wraps from there).
    static osg::Vec2d tileOrigin(const Frame& f);

    //! The box the sun's passes cover: the water's extent cut to the scene's, from the scene's
    //! lowest point up to the crests, or, `focused`, the lit water's box (where light can land;
    //! when no ray finds lit water, say under a sky dome wound outwards, the unfocused box).
    static osg::BoundingBox lightBox(const Frame& f, bool focused);
    //! The reflective caustics' box: the water's extent cut to the scene's, from the scene's top
    //! mirrored in the water plane up to the crests.
    static osg::BoundingBox reflectedBox(const Frame& f);
    //! How wide the focused box is against the unfocused one (its larger side over the other's;
    //! 1 when the settings do not focus): the passes' side counts shrink by it.
    static double focusRatio(const Frame& f);
    //! How wide a caustics tile is against the unfocused window (at most 1): a tile keeps the
    //! texel and photon spacing the settings give that window.
    static double tileRatio(const Frame& f);

    //! Aims the three passes (call only when needed(), once per frame: every view and context
    //! shares what it sets).
    void update(const Frame& f);

    //! Culls the cameras of one of the caustics rows of the pass table (PASS_SUN_DEPTH: the sun's
    //! depth map and, for refractive untiled caustics, its shade map; PASS_PHOTONS; PASS_GATHER).
    void cullPass(PassId pass, osg::NodeVisitor& cv);
    //! The sun's depth and shade maps depend on the sun and the scene, not on the waves: they need
    //! drawing on a context only when the sun's frustum changed, after dirtyDepth(), or when the
    //! context released them.
    bool depthStale(unsigned int contextID) const;
    //! Records that this frame draws the depth maps on that context.
    void markDepthDrawn(unsigned int contextID);
    //! Redraw the sun's depth maps next frame (the scene changed within its bounds).
    void dirtyDepth() { ++_depthVersion; }
    //! A new number whenever the sun's frustum changed or dirtyDepth() was called.
    unsigned int getDepthVersion() const { return _depthVersion; }
    //! Whether the last frame that rendered caustics drew the depth map (tests, statistics).
    bool getDepthDrawn() const { return _depthDrawn; }

    //! What the scene shader needs to apply the caustics (valid after update()).
    const CausticsLighting& getLighting() const { return _lighting; }

    osg::Texture2D* getCausticsTexture() const { return _gather->getCausticsTexture(); }
    //! What stands above the water seen from the sun (the whole scene, unclipped, the depth map's
    //! window): the photons under it are dark. Null for the reflective caustics.
    osg::Texture2D* getShadeTexture() const { return _shade.valid() ? _shade->getDepthTexture() : nullptr; }
    //! The shade map's projection: the depth map's window, its near plane at the scene's top.
    static osg::Matrixd shadeProjection(const osg::Matrixd& sunView, const osg::Matrixd& depthProjection,
                                        const osg::BoundingBox& box, const osg::BoundingBox& scene);
    osg::Texture2D* getPhotonTexture() const { return _photons->getPhotonTexture(); }
    PhotonCamera* getPhotonCamera() const { return _photons.get(); }
    PhotonGather* getGather() const { return _gather.get(); }
    int getResolution() const { return _gather->getResolution(); }
    int getGridSize() const { return _photons->getGridSize(); }
    bool hasFloatTargets() const { return _floatTargets; }
    bool matches(int resolution, int gridSize, bool floatTargets) const;

    //! Sun camera side lengths in metres (the window the caustics texture covers) and depth range.
    const osg::Vec3d& getWindow() const { return _window; }
    //! A caustics texel's side in metres: over the sun's window, or over the tile when tiled.
    double getTexelSize() const;

    //! The one place the gather path is decided, on a frame that renders the caustics: the
    //! setting where the context supports it (else the first supported of points (texture), points
    //! (copy), CPU, said once); GATHER_AUTO runs each supported path a few such frames first,
    //! timed on the GPU, and keeps the fastest (points are fastest on GPUs, the CPU gather on
    //! software rasterisers: measured, not guessed), and chooses again when the caustics method or
    //! the supersampling changes. Sets the gather pass to it, for that method and supersampling.
    WaterSettings::CausticsGather resolveGather(const WaterSettings& settings, const CausticsSupport& support);
    //! The method resolveGather() chose last (GATHER_AUTO before the first).
    WaterSettings::CausticsGather getActiveGather() const { return _activeGather; }
    //! Whether GATHER_AUTO has made its choice.
    bool isAutoGatherSettled() const { return _autoChoice >= 0; }

    //! GPU time of the photon and gather passes together, ms (negative until measured).
    double getMilliseconds() const { return _meter->getMilliseconds(); }
    //! The same with their fragments.
    PassMeasure getMeasure() const { return _meter->getMeasure(); }
    //! GPU time and fragments of the sun's depth pass (its depth map and shade map; negative until
    //! measured or while timing is off).
    PassMeasure getDepthMeasure() const;
    //! Time the sun's depth pass (the photon and gather passes are always timed: the automatic
    //! gather chooses by their time).
    void setTimingEnabled(bool on);

    void resizeGLObjectBuffers(unsigned int maxSize) override;
    void releaseGLObjects(osg::State* state = 0) const override;

protected:
    virtual ~CausticsCamera() {}
    static osg::StateSet* depthOnlyState(ProgramLibrary& programs);
    WaterSettings::CausticsGather autoGather(const CausticsSupport& support);

    bool _floatTargets, _reflected, _tiled = false, _saidTiledMesh = false;
    double _tileSide = 0.0;
    osg::ref_ptr<PassCamera> _shade;
    osg::ref_ptr<PhotonCamera> _photons;
    osg::ref_ptr<PhotonGather> _gather;
    CausticsLighting _lighting;
    osg::ref_ptr<PassMeter> _meter, _depthMeter, _shadeMeter;
    osg::Vec3d _window;
    osg::Matrixd _depthView, _depthProj, _shadeProj;
    unsigned int _depthVersion = 1;
    std::map<unsigned int, unsigned int> _depthDone; // context -> version drawn
    bool _depthDrawn = false;
    WaterSettings::CausticsGather _activeGather = WaterSettings::GATHER_AUTO;
    // GATHER_AUTO trials: method index, frame within the trial, GPU times seen
    unsigned int _trial = 0, _trialFrame = 0;
    std::vector<std::vector<double>> _trialMs;
    int _autoChoice = -1;
};

}

#endif
