/* osgWater - natural water for OpenSceneGraph */
#ifndef OSGWATER_PASSTABLE
#define OSGWATER_PASSTABLE 1

#include <osgWater/Export>
#include <osgWater/Statistics>
#include <string>

//! The frame's passes in the order they draw, each with what it reads and writes and when it is
//! wanted: the one place that says which passes run and in what order. WaterNode::cull plans a
//! frame with planPasses() and walks the table; render orders, render bins and texture units
//! come from here. A new pass is a new row (and a case in WaterNode::cullPass).
namespace osgWater {

// the rows, in drawing order: PassId (public, <osgWater/Statistics>)

//! What passes read and write (bit masks).
enum PassResource : unsigned {
    RES_SUN_DEPTH = 1u << 0,      //!< the sun's depth map (underwater shadows, photon search)
    RES_PHOTONS = 1u << 1,
    RES_CAUSTICS = 1u << 2,       //!< the caustics texture
    RES_REFLECTION = 1u << 3,     //!< the reflection colour texture
    RES_REFRACTION = 1u << 4,     //!< the refraction colour and depth textures
    RES_GLOW_HIGHLIGHT = 1u << 5,
    RES_GLOW_HALF_BLURRED = 1u << 6,
    RES_GLOW = 1u << 7,
    RES_VIEW_IMAGE = 1u << 8,     //!< the view's own image: what every frame is for
    RES_ENVIRONMENT = 1u << 9,    //!< the environment cube map
    RES_WAVES = 1u << 10          //!< the waves as of the frame's time: the wind's cascade textures and the
                                  //!< sum's phases, an input no row writes (the view's cull brings them up
                                  //!< to the frame when a running row reads them)
};

//! Where a pass draws.
enum PassStage {
    STAGE_PRE_RENDER, //!< its own render-to-texture camera, before the view (render order from the table)
    STAGE_UNDERLAY,   //!< in the view, opaque, in a bin of its own before the scene's (render bin -1)
    STAGE_VIEW,       //!< in the view, in the scene's own render bins
    STAGE_OVERLAY     //!< in the view, in a bin of its own after everything the scene draws
};

//! The texture units of the kit's shaders, named once.
enum TextureUnit {
    UNIT_BASE = 0,             //!< the scene's own texture (a white texel when it has none)
    UNIT_REFLECTION = 1,
    UNIT_REFRACTION = 2,
    UNIT_REFRACTION_DEPTH = 3, //!< also the sun's depth map in the photon pass (the same search reads it)
    UNIT_CAUSTICS = 4,
    UNIT_SUN_DEPTH = 5,        //!< also the sun's shade map in the photon pass
    UNIT_ENVIRONMENT = 6,      //!< the environment cube map (the water program)
    UNIT_REFLECTED_CAUSTICS = 7, //!< the reflective caustics and their mirrored sun depth map (the scene program)
    UNIT_REFLECTED_SUN_DEPTH = 8,
    UNIT_REFLECTION_DEPTH = 9, //!< the reflection pass's depth (the water program's mirror search)
    UNIT_SUN_SHADE = 10,       //!< the sun's shade map (the scene program's procedural caustics)
    UNIT_WAVES = 11,           //!< the wind's wave cascades (every program that reads the waves)
    UNIT_WAVE_HEIGHTS = 12,    //!< their heights alone, level 0 (the sight ray's search), choppy with the displacement
    UNIT_WAVE_JACOBIANS = 13,  //!< choppy, the displacement's derivatives
    UNIT_PASS_INPUT = 0        //!< a screen pass's input (photons to splat, highlight to blur, glow to add)
};

//! What a view is and has this frame, gathered once per view before the table is walked.
struct OSGWATER_EXPORT FrameFacts {
    bool waterInView = false;      //!< the surface's box is in the view frustum
    bool eyeBelow = false;         //!< the eye is under the animated surface
    bool reflectionEnabled = true; //!< the settings' switches
    bool refractionEnabled = true;
    bool caustics = false;         //!< caustics wanted and possible (sun up, something under the water)
    bool reflectedCaustics = false; //!< with them, reflective caustics on what stands above the water
    bool causticsInScene = false;  //!< the scene program makes the caustics itself (procedural, per pixel):
                                   //!< no photons, no gather, only the sun's depth map
    bool causticsDone = false;     //!< this context holds caustics valid for this frame already: another
                                   //!< view rendered them this frame, or an earlier frame did and only
                                   //!< time passed, less than the waves need to move them visibly
    bool sunDepthStale = true;     //!< the sun's depth map must be drawn again on this context
    bool glowInView = false;       //!< the sun's highlight can be in view (and no debug output)
    bool environment = false;      //!< the water reads an environment cube map the kit draws
    bool environmentStale = false; //!< that map must be drawn (again) on this context
};

//! One row of the table.
struct OSGWATER_EXPORT PassRow {
    PassId id;
    const char* name;
    PassStage stage;
    unsigned reads;   //!< resources read whenever the pass runs
    unsigned writes;
    bool litScene;    //!< draws the scene under SceneLighting: reads the caustics and the sun's
                      //!< depth map when the view can see below the water
    bool perView;     //!< uses this view's own passes (ViewPasses); the shared caustics and the
                      //!< view's scene need only the view's lighting
    bool (*wanted)(const FrameFacts&); //!< whether the pass can change this frame's image
};

//! The table, PASS_COUNT rows in drawing order.
OSGWATER_EXPORT const PassRow* passTable();
OSGWATER_EXPORT const PassRow& passRow(PassId id);

//! The passes one view runs this frame: the wanted rows whose output a later running row (or
//! the view's image) reads. A pass nothing reads is not run.
class OSGWATER_EXPORT PassPlan
{
public:
    bool runs(PassId id) const { return (_runs >> id) & 1u; }
    //! Whether a running row needs this view's own passes (PassRow::perView).
    bool usesViewPasses() const;
    unsigned bits() const { return _runs; }
    //! Whether a running row reads any of `resources` (PassResource bits), the caustics and the
    //! sun's depth map included where a lit scene pass sees them.
    bool reads(unsigned resources) const { return (_reads & resources) != 0; }
    std::string describe() const; //!< names of the passes that run, in order (tests, logs)
private:
    friend OSGWATER_EXPORT PassPlan planPasses(const FrameFacts& facts);
    unsigned _runs = 0;
    unsigned _reads = 0;
};

OSGWATER_EXPORT PassPlan planPasses(const FrameFacts& facts);

// gpuTimeLabel(): public, <osgWater/Statistics>

//! Render order of a pre-render pass (its row's place: earlier rows draw first).
OSGWATER_EXPORT int renderOrder(PassId id);
//! Render bin of an underlay pass (-1: before the scene's opaque bin 0; a sky drawn without a depth
//! test must draw in a lower bin) or an overlay pass (after the scene's own bins, in the table's order).
OSGWATER_EXPORT int renderBin(PassId id);

}

#endif
