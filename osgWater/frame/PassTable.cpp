#include "frame/PassTable.h"

using namespace osgWater;

namespace {

bool always(const FrameFacts&) { return true; }
bool causticsToRender(const FrameFacts& f) { return f.caustics && !f.causticsDone; }
bool sunDepthToRender(const FrameFacts& f) { return causticsToRender(f) && f.sunDepthStale; }
bool photonsToRender(const FrameFacts& f) { return causticsToRender(f) && !f.causticsInScene; }
bool reflectionWanted(const FrameFacts& f) { return f.waterInView && f.reflectionEnabled; }
bool refractionWanted(const FrameFacts& f) { return f.waterInView && f.refractionEnabled; }
bool waterInView(const FrameFacts& f) { return f.waterInView; }
bool eyeBelow(const FrameFacts& f) { return f.eyeBelow; }
bool glowWanted(const FrameFacts& f) { return f.waterInView && f.glowInView; }
bool environmentToRender(const FrameFacts& f) { return f.environment && f.environmentStale; }

// what the water program reads
const unsigned kWaterInputs = RES_REFLECTION | RES_REFRACTION | RES_ENVIRONMENT | RES_WAVES;

// The frame, top to bottom. Pre-render rows draw in this order (renderOrder), overlay rows after
// the scene's bins in this order (renderBin). RES_WAVES: the programs that draw the surface or read
// it (the photons' grid, the screen's procedural caustics, the virtual vertices, the highlight, the
// water program).
const PassRow kTable[PASS_COUNT] = {
    // id                   name               stage               reads                        writes                 litScene perView wanted
    { PASS_ENVIRONMENT,    "environment",     STAGE_PRE_RENDER, 0,                            RES_ENVIRONMENT,       false, false, environmentToRender },
    { PASS_SUN_DEPTH,      "sun depth",       STAGE_PRE_RENDER, 0,                            RES_SUN_DEPTH,         false, false, sunDepthToRender },
    { PASS_PHOTONS,        "photons",         STAGE_PRE_RENDER, RES_SUN_DEPTH | RES_WAVES,    RES_PHOTONS,           false, false, photonsToRender },
    { PASS_GATHER,         "gather",          STAGE_PRE_RENDER, RES_PHOTONS | RES_WAVES,      RES_CAUSTICS,          false, false, photonsToRender },
    { PASS_REFLECTION,     "reflection",      STAGE_PRE_RENDER, 0,                            RES_REFLECTION,        true,  true,  reflectionWanted },
    { PASS_REFRACTION,     "refraction",      STAGE_PRE_RENDER, RES_WAVES,                    RES_REFRACTION,        true,  true,  refractionWanted },
    { PASS_GLOW_HIGHLIGHT, "glow highlight",  STAGE_PRE_RENDER, RES_WAVES,                    RES_GLOW_HIGHLIGHT,    false, true,  glowWanted },
    { PASS_GLOW_BLUR_H,    "glow blur x",     STAGE_PRE_RENDER, RES_GLOW_HIGHLIGHT,           RES_GLOW_HALF_BLURRED, false, true,  always },
    { PASS_GLOW_BLUR_V,    "glow blur y",     STAGE_PRE_RENDER, RES_GLOW_HALF_BLURRED,        RES_GLOW,              false, true,  always },
    { PASS_SURFACE,        "surface",         STAGE_UNDERLAY,   kWaterInputs,                 RES_VIEW_IMAGE,        false, true,  waterInView },
    { PASS_SCENE,          "scene",           STAGE_VIEW,       0,                            RES_VIEW_IMAGE,        true,  false, always },
    { PASS_BACKDROP,       "backdrop",        STAGE_OVERLAY,    0,                            RES_VIEW_IMAGE,        false, true,  eyeBelow },
    { PASS_CAP,            "near-plane cap",  STAGE_OVERLAY,    kWaterInputs,                 RES_VIEW_IMAGE,        false, true,  waterInView },
    { PASS_GLOW_COMPOSITE, "glow composite",  STAGE_OVERLAY,    RES_GLOW,                     RES_VIEW_IMAGE,        false, true,  glowWanted },
};

// the first bin after the scene's own (OSG's opaque 0 and transparent 10, and room for a user's)
const int kFirstOverlayBin = 19;
// just before the scene's opaque bin
const int kUnderlayBin = -1;

}

const PassRow* osgWater::passTable()
{
    return kTable;
}

const char* osgWater::passName(PassId id)
{
    return id >= 0 && id < PASS_COUNT ? kTable[id].name : "";
}

const PassRow& osgWater::passRow(PassId id)
{
    return kTable[id];
}

PassPlan osgWater::planPasses(const FrameFacts& f)
{
    // backwards from the view's image: a row runs when it is wanted and a running row after it
    // (or the image) reads what it writes; then what it reads is needed in turn
    const bool seesUnderWater = f.waterInView || f.eyeBelow;
    unsigned needed = RES_VIEW_IMAGE;
    PassPlan plan;
    for (int i = PASS_COUNT - 1; i >= 0; --i) {
        const PassRow& row = kTable[i];
        if (!(row.writes & needed) || !row.wanted(f)) continue;
        plan._runs |= 1u << row.id;
        unsigned reads = row.reads;
        // a scene pass reads the caustics where it sees below the water, or, reflective, above it;
        // caustics the scene program makes itself read the waves
        if (row.litScene && f.caustics && (seesUnderWater || f.reflectedCaustics))
            reads |= RES_CAUSTICS | RES_SUN_DEPTH | (f.causticsInScene ? RES_WAVES : 0u);
        needed |= reads;
        plan._reads |= reads;
    }
    return plan;
}

bool PassPlan::usesViewPasses() const
{
    for (int i = 0; i < PASS_COUNT; ++i)
        if (runs(PassId(i)) && kTable[i].perView) return true;
    return false;
}

std::string PassPlan::describe() const
{
    std::string s;
    for (int i = 0; i < PASS_COUNT; ++i)
        if (runs(PassId(i))) s += (s.empty() ? "" : ", ") + std::string(kTable[i].name);
    return s;
}

const char* osgWater::gpuTimeLabel(PassId id)
{
    switch (id) {
    case PASS_PHOTONS: return "photons + gather";
    case PASS_GLOW_BLUR_H: return "glow blur";
    case PASS_ENVIRONMENT: // drawn once in a while: no timer of its own
    case PASS_GATHER:
    case PASS_GLOW_BLUR_V:
    case PASS_SCENE:
    case PASS_COUNT: return nullptr;
    default: return kTable[id].name;
    }
}

int osgWater::renderOrder(PassId id)
{
    return int(id);
}

int osgWater::renderBin(PassId id)
{
    if (kTable[id].stage == STAGE_UNDERLAY) return kUnderlayBin;
    int bin = kFirstOverlayBin;
    for (int i = 0; i < id; ++i)
        if (kTable[i].stage == STAGE_OVERLAY) ++bin;
    return bin;
}
