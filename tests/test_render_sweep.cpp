// Stability sweep: at least 10,000 configurations rendered at 64 x 64, every output read
// back (final image and every target of every pass) and checked for NaN/Inf and GL errors. Each
// axis's edge values are listed explicitly and cycled with coprime strides, so every edge value
// meets many values of every other axis; the rest are drawn from a fixed-seed generator.
#include "node/WaterNodeImpl.h"
#include "GLHarness.h"
#include <osgWater/WaterNode>
#include <osg/GL>
#include <osg/Timer>
#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>

using namespace testing_gl;
using namespace osgWater;

namespace {

// --- scenes: what the water reflects and refracts ------------------------------------------------
enum SceneKind { LAKE, EMPTY, ALL_ABOVE, ALL_BELOW, DEGENERATE_MESH, NUM_SCENES };
const char* sceneName(int s)
{
    static const char* names[] = { "lake", "empty", "all above", "all below", "degenerate mesh" };
    return names[s];
}

osg::Geometry* degenerateMesh()
{
    // zero-area triangles, duplicate vertices, collinear vertices, and one ordinary triangle
    osg::Geometry* g = new osg::Geometry;
    osg::Vec3Array* v = new osg::Vec3Array;
    const osg::Vec3 p[] = { { -20, -20, 0 }, { 20, -20, 0 }, { 20, 20, 0.1f }, // ordinary
                            { 1, 1, 0 }, { 1, 1, 0 }, { 1, 1, 0 },            // one point three times
                            { -5, 0, 0 }, { 0, 0, 0 }, { 5, 0, 0 },            // collinear
                            { 3, 3, 0 }, { 3, 3, 0 }, { 4, 4, 0 } };           // duplicate pair
    for (const osg::Vec3& q : p) v->push_back(q);
    g->setVertexArray(v);
    osg::Vec3Array* n = new osg::Vec3Array;
    for (size_t i = 0; i < v->size(); ++i) n->push_back(i < 3 ? osg::Vec3(0, 0, 1) : osg::Vec3(0, 0, 0)); // zero normals too
    g->setNormalArray(n, osg::Array::BIND_PER_VERTEX);
    g->addPrimitiveSet(new osg::DrawArrays(GL_TRIANGLES, 0, GLsizei(v->size())));
    return g;
}

void buildScene(WaterNode* water, int kind)
{
    water->removeChildren(0, water->getNumChildren());
    water->getSurface()->setMesh(kind == DEGENERATE_MESH ? degenerateMesh() : nullptr);
    const osg::Vec4 orange(1, 0.5f, 0, 1);
    switch (kind) {
    case LAKE:
    case DEGENERATE_MESH:
        water->addChild(checkerPlane(-2.0f, 60.0f, 1.0f));
        water->addChild(emissiveQuad(osg::Vec3(-1, 5, -2), osg::Vec3(1, 5, -2), osg::Vec3(1, 5, 2), osg::Vec3(-1, 5, 2), orange));
        break;
    case ALL_ABOVE:
        water->addChild(emissiveQuad(osg::Vec3(-10, 8, 3), osg::Vec3(10, 8, 3), osg::Vec3(10, 8, 9), osg::Vec3(-10, 8, 9), orange));
        break;
    case ALL_BELOW:
        water->addChild(checkerPlane(-2.0f, 60.0f, 1.0f));
        water->addChild(emissiveQuad(osg::Vec3(-1, 5, -2), osg::Vec3(1, 5, -2), osg::Vec3(1, 5, -0.5f), osg::Vec3(-1, 5, -0.5f), orange));
        break;
    default: break; // EMPTY: the water alone
    }
}

// --- the axes ------------------------------------------------------------------------------------
// Expensive ones (new targets, recompiled programs) change per group of configurations...
struct Group {
    int scene, steps; // steps 0: one-step lookup (or the plane offset, with planeLookups)
    bool bracketed;    // with steps: the bracketed search (else the thesis's iterative one)
    bool virtualVertices; // with steps, not bracketed: virtual vertices instead of the search
    bool planeLookups; // the plane-offset refraction (when steps is 0) and reflection lookups
    bool offsetReflection; // without planeLookups: the thesis's offset reflection lookup, else the search
    WaterSettings::FresnelModel fresnel;
    WaterSettings::UnderwaterModel underwater;
    int gather;       // -1 caustics off, else a CausticsGather
    bool areaMesh;    // the caustics by the area-ratio mesh (else photon splatting), supersampled every other time
    bool procedural;  // the caustics by the procedural construction (no photons)
    bool perPixel;    // with it, the screen-space variant
    bool reflective;  // reflective caustics too
    float tile;       // tileable caustics' tile (0: off)
    bool environment; // the environment cube map (drawn from the scene)
    int textureSize, photonGrid, viewport;
    bool rotation, apparentEye, glow, reflection, refraction;
    DebugOutput debug;
    float wind; // m/s: the wind's waves (one group in three), else < 0: the sum of sines
    float choppiness; // theirs
};
// ... cheap ones (uniforms, the camera, the waves) per configuration.
struct Config {
    double eyeHeight, pitch, yaw, x, sunElevation, ior, time, amplitude, nearPlane;
};

const double kEyeHeights[] = { -1000, -100, -10, -1, -0.3, -1e-6, 0, 1e-6, 0.3, 1, 10, 100, 1000 };
const double kPitches[] = { -90, -89.99, -60, -10, -0.01, 0, 0.01, 10, 60, 89.99, 90 };
const double kSunElevations[] = { -30, -0.01, 0, 0.01, 1, 30, 60, 89.99, 90 };
const double kIORs[] = { 1.0, 1.0001, 1.1, 1.333, 1.5, 2.0, 2.5 };
const double kTimes[] = { 0, 1e-6, 1, 1000, 86400, 1e6, 9999999.999, 1e7 };
const double kAmplitudes[] = { 0, 0.075, 0.5, 3.0 }; // total; 3 m is more than the 2 m depth
const double kNearPlanes[] = { 0.001, 0.05, 1, 10 };  // 1 and 10 cut the surface near a low eye
const int kTextureSizes[] = { 16, 64, 8192 };          // 8192: clamped to 4096 and to the context
const int kViewports[] = { 1, 64, 8192 };              // 8192: far beyond the 64 x 64 target

template <class T, size_t N> T pick(const T (&a)[N], size_t i) { return a[i % N]; }

std::vector<Group> groups()
{
    std::vector<Group> g;
    const WaterSettings::FresnelModel fresnel[] = { WaterSettings::FRESNEL_SCHLICK, WaterSettings::FRESNEL_POWER,
                                                    WaterSettings::FRESNEL_EXACT, WaterSettings::FRESNEL_RECIPROCAL };
    const WaterSettings::UnderwaterModel under[] = { WaterSettings::UNDERWATER_PHYSICAL, WaterSettings::UNDERWATER_THESIS };
    const int gathers[] = { -1, WaterSettings::GATHER_CPU, WaterSettings::GATHER_POINTS_COPY,
                            WaterSettings::GATHER_POINTS_TEXTURE, WaterSettings::GATHER_AUTO };
    const DebugOutput debug[] = { DEBUG_NONE, DEBUG_NONE, DEBUG_NONE, DEBUG_BOTTOM_HIT, DEBUG_REFLECTION_LOOKUP,
                                  DEBUG_FRESNEL, DEBUG_SURFACE };
    for (size_t i = 0; i < 100; ++i) {
        Group x;
        x.scene = int(i % NUM_SCENES);
        x.steps = int((i * 7) % 9);
        x.planeLookups = i % 3 == 1;
        x.bracketed = i % 4 == 3;
        x.virtualVertices = i % 4 == 1;
        x.offsetReflection = i % 2 == 0;
        x.fresnel = pick(fresnel, i / 5);
        x.underwater = pick(under, i / 3);
        x.gather = pick(gathers, i / 2);
        x.areaMesh = i % 4 >= 2; // with every gather (which changes every other group)
        x.procedural = !x.areaMesh && i % 8 == 1;
        x.perPixel = x.procedural && i % 16 == 9;
        x.reflective = i % 5 == 2;
        x.tile = i % 7 == 4 ? 3.0f : 0.0f;
        x.environment = i % 6 == 3;
        // huge targets (8192: clamped to 4096 by the settings, then to the context) cost seconds a
        // frame on a software rasteriser: one group each, the others alternate tiny and small
        x.textureSize = i == 10 ? 8192 : (i % 2 ? 16 : 64);
        x.photonGrid = i == 25 ? 8192 : (i % 3 ? 16 : 64);
        x.viewport = (i == 40 || i == 91) ? 8192 : (i % 7 == 3 ? 1 : 64);
        x.rotation = i % 4 != 1;
        x.apparentEye = i % 3 != 2; // with the rotation: moved to the apparent eye, or the thesis's
        x.glow = i % 6 != 2;
        x.reflection = i % 19 != 5;
        x.refraction = i % 23 != 7;
        x.debug = pick(debug, i / 7);
        // the wind's waves: still air, a breeze, a fresh wind, a gale (the cascades are made per
        // group; each configuration moves them to its time)
        const float winds[] = { 0.0f, 2.0f, 5.0f, 12.0f, 40.0f };
        x.wind = i % 3 == 2 ? pick(winds, i / 3) : -1.0f;
        const float choppiness[] = { 0.0f, 1.0f, 0.5f };
        x.choppiness = pick(choppiness, i / 2);
        g.push_back(x);
    }
    return g;
}

// configurations per group: the 4 groups with huge targets get 2 each, the 96 others 105 each:
// 10,088 in all
size_t configsIn(const Group& g) { return (g.textureSize > 4096 || g.photonGrid > 4096 || g.viewport > 4096) ? 2 : 105; }

Config config(size_t n, std::mt19937& rng)
{
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Config c;
    // edge values on most configurations, a random value from the axis's range on the others
    const bool random = n % 4 == 3;
    c.eyeHeight = random ? (u(rng) * 2 - 1) * std::pow(10.0, u(rng) * 3) : pick(kEyeHeights, n);
    c.pitch = random ? u(rng) * 179.98 - 89.99 : pick(kPitches, n / 2 + n);
    c.yaw = u(rng) * 360.0;
    c.x = (u(rng) * 2 - 1) * 20.0;
    c.sunElevation = random ? u(rng) * 120 - 30 : pick(kSunElevations, 3 * n + 1);
    c.ior = random ? 1.0 + 1.5 * u(rng) : pick(kIORs, 5 * n + 2);
    c.time = random ? u(rng) * 1e7 : pick(kTimes, 7 * n + 3);
    c.amplitude = pick(kAmplitudes, 11 * n + 1);
    c.nearPlane = pick(kNearPlanes, 13 * n);
    return c;
}

std::vector<Wave> scaledWaves(double total)
{
    std::vector<Wave> w = defaultWaves();
    double sum = 0;
    for (const Wave& x : w) sum += x.amplitude;
    for (Wave& x : w) x.amplitude = float(x.amplitude * total / sum);
    return total == 0 ? std::vector<Wave>() : w;
}

std::string describe(const Group& g, const Config& c)
{
    std::ostringstream s;
    s << sceneName(g.scene) << ", "
      << (g.steps ? (g.bracketed ? "bracketed " : g.virtualVertices ? "virtual vertices " : "iterative ") + std::to_string(g.steps)
                  : std::string(g.planeLookups ? "plane" : "one-step"))
      << (g.planeLookups ? ", plane reflection" : g.offsetReflection ? ", offset reflection" : ", reflection search")
      << ", fresnel " << g.fresnel << ", underwater " << g.underwater << ", gather " << g.gather << (g.areaMesh ? " (mesh)" : "") << (g.procedural ? (g.perPixel ? " (procedural per pixel)" : " (procedural)") : "") << (g.reflective ? " (reflective)" : "") << (g.tile > 0.0f ? " (tiled)" : "") << (g.environment ? ", environment map" : "") << ", textures "
      << g.textureSize << ", photons " << g.photonGrid << ", viewport " << g.viewport << ", rotation " << g.rotation
      << (g.rotation && !g.apparentEye ? " (thesis)" : "")
      << ", glow " << g.glow << ", debug " << g.debug << (g.wind >= 0.0f ? ", wind " + std::to_string(g.wind) + " m/s, choppiness " + std::to_string(g.choppiness) : std::string())
      << "; eye height " << c.eyeHeight << ", pitch " << c.pitch
      << ", yaw " << c.yaw << ", sun " << c.sunElevation << ", IOR " << c.ior << ", t " << c.time << ", amplitude "
      << c.amplitude << ", near " << c.nearPlane;
    return s.str();
}

void apply(WaterNode* water, const Group& g)
{
    WaterSettings* s = water->getSettings();
    s->setRefractionLookup(g.steps ? (g.bracketed ? WaterSettings::BRACKETED
                                      : g.virtualVertices ? WaterSettings::VIRTUAL_VERTICES : WaterSettings::ITERATIVE)
                           : g.planeLookups ? WaterSettings::PLANE_OFFSET : WaterSettings::ONE_STEP);
    s->setReflectionLookup(g.planeLookups ? WaterSettings::REFLECTION_PLANE
                           : g.offsetReflection ? WaterSettings::REFLECTION_OFFSET : WaterSettings::REFLECTION_SEARCH);
    s->setSearchSteps(std::max(g.steps, 1));
    s->setFresnelModel(g.fresnel);
    s->setUnderwaterModel(g.underwater);
    s->setCausticsEnabled(g.gather >= 0);
    if (g.gather >= 0) s->setCausticsGather(WaterSettings::CausticsGather(g.gather));
    s->setCausticsMethod(g.areaMesh ? WaterSettings::CAUSTICS_AREA_MESH
                         : g.procedural ? (g.perPixel ? WaterSettings::CAUSTICS_PROCEDURAL_SCREEN : WaterSettings::CAUSTICS_PROCEDURAL)
                                        : WaterSettings::CAUSTICS_PHOTONS);
    s->setCausticsSupersampling(g.areaMesh && g.steps % 2 == 1);
    s->setReflectiveCaustics(g.reflective);
    s->setCausticsTileSize(g.tile);
    s->setEnvironmentMapEnabled(g.environment);
    s->setReflectionTextureSize(g.textureSize);
    s->setRefractionTextureSize(g.textureSize);
    s->setCausticsResolution(g.textureSize);
    s->setPhotonGridSize(g.photonGrid);
    s->setRefractionCameraRotation(g.rotation);
    s->setRefractionCameraApparentEye(g.apparentEye);
    s->setGlowEnabled(g.glow);
    s->setReflectionEnabled(g.reflection);
    s->setRefractionEnabled(g.refraction);
    water->setDebugOutput(g.debug);
    if (g.wind >= 0.0f) {
        WindWaves wind;
        wind.speed = g.wind;
        wind.direction.set(0.3f, 1.0f);
        wind.choppiness = g.choppiness;
        water->getSurface()->setWind(wind);
    }
    water->getSurface()->setWaveModel(g.wind >= 0.0f ? WaterSurface::WAVES_WIND : WaterSurface::WAVES_SUM);
}

void apply(Harness& h, WaterNode* water, const Group& g, const Config& c)
{
    WaterSettings* s = water->getSettings();
    s->setWaterIOR(float(c.ior));
    const double e = osg::DegreesToRadians(c.sunElevation);
    s->setSunDirection(osg::Vec3(float(std::cos(e) * 0.6), float(std::cos(e) * 0.8), float(std::sin(e))));
    water->getSurface()->setWaves(scaledWaves(c.amplitude));
    // the camera from yaw and pitch (not lookAt: straight up and down are exact here)
    const osg::Vec3d eye(c.x, -3.0, c.eyeHeight);
    const osg::Matrixd world = osg::Matrixd::rotate(osg::DegreesToRadians(90.0 + c.pitch), osg::Vec3d(1, 0, 0))
                               * osg::Matrixd::rotate(osg::DegreesToRadians(c.yaw), osg::Vec3d(0, 0, 1))
                               * osg::Matrixd::translate(eye);
    h.camera()->setViewMatrix(osg::Matrixd::inverse(world));
    h.camera()->setProjectionMatrixAsPerspective(50.0, 1.0, c.nearPlane, 5000.0);
    h.camera()->setViewport(0, 0, g.viewport, g.viewport);
}

struct Outputs {
    std::vector<std::pair<std::string, osg::Texture2D*>> list;
};

Outputs outputsOf(Harness& h, WaterNode* water)
{
    Outputs o;
    if (ViewPasses* p = osgWater::internals(*water).getViewPasses(h.camera())) {
        o.list.push_back({ "reflection", p->getReflectionCamera()->getColorTexture() });
        o.list.push_back({ "refraction", p->getRefractionCamera()->getColorTexture() });
        o.list.push_back({ "refraction depth", p->getRefractionCamera()->getDepthTexture() });
        if (GlowPasses* g = p->getGlow()) {
            o.list.push_back({ "glow highlight", g->getHighlightTexture() });
            o.list.push_back({ "glow", g->getGlowTexture() });
        }
    }
    if (CausticsCamera* c = osgWater::internals(*water).getCausticsCamera()) {
        o.list.push_back({ "sun depth", c->getDepthTexture() });
        o.list.push_back({ "photons", c->getPhotonTexture() });
        o.list.push_back({ "caustics", c->getCausticsTexture() });
    }
    if (CausticsCamera* r = osgWater::internals(*water).getReflectedCausticsCamera()) {
        o.list.push_back({ "reflected sun depth", r->getDepthTexture() });
        o.list.push_back({ "reflected photons", r->getPhotonTexture() });
        o.list.push_back({ "reflective caustics", r->getCausticsTexture() });
    }
    return o;
}

// what went wrong in this frame, or "" (every output finite, no GL error). Targets larger than any
// size this group uses are an earlier group's (passes not culled this frame keep them), checked
// when they were drawn: re-reading a stale 4096^2 target every frame would take hours.
std::string check(Harness& h, WaterNode* water, const Group& g)
{
    const int largest = std::max({ std::min(g.textureSize, 4096), std::min(g.photonGrid, 4096), g.viewport });
    h.context()->makeCurrent();
    const GLenum err = glGetError();
    if (err != GL_NO_ERROR) return "GL error " + std::to_string(err);
    osg::ref_ptr<osg::Image> img = h.readColor();
    if (!img.valid() || !allFinite(img.get())) return "final image not finite";
    for (const auto& t : outputsOf(h, water).list) {
        if (!t.second || std::max(t.second->getTextureWidth(), t.second->getTextureHeight()) > largest) continue;
        osg::ref_ptr<osg::Image> out = h.readTexture(t.second);
        if (out.valid() && !allFinite(out.get())) return t.first + " not finite";
    }
    return "";
}

}

TEST(RenderSweep, TenThousandConfigurationsGiveNoNaNInfOrGLError)
{
    const char* limit = std::getenv("OSGWATER_SWEEP_LIMIT"); // developers: a shorter sweep
    const size_t maxConfigs = limit ? size_t(std::atoll(limit)) : size_t(-1);
    Harness h(64, 64);
    REQUIRE_GL(h);
    osg::ref_ptr<WaterNode> water = new WaterNode;
    water->getSurface()->setSize(80.0f);
    h.setScene(water.get());
    std::mt19937 rng(20261122);
    size_t total = 0, failed = 0;
    std::vector<std::string> firstFailures;
    const std::vector<Group> all = groups();
    const char* first = std::getenv("OSGWATER_SWEEP_FIRST"); // developers: start at this group
    for (size_t gi = first ? size_t(std::atoll(first)) : 0; gi < all.size(); ++gi) {
        const Group& g = all[gi];
        const osg::Timer_t start = osg::Timer::instance()->tick();
        buildScene(water.get(), g.scene);
        apply(water.get(), g);
        for (size_t i = 0; i < configsIn(g) && total < maxConfigs; ++i, ++total) {
            const Config c = config(total, rng);
            apply(h, water.get(), g, c);
            h.frame(c.time);
            const std::string why = check(h, water.get(), g);
            if (!why.empty()) {
                ++failed;
                if (firstFailures.size() < 12) firstFailures.push_back(why + " [" + describe(g, c) + "]");
            }
        }
        const double seconds = osg::Timer::instance()->delta_s(start, osg::Timer::instance()->tick());
        if (seconds > 5.0) std::cout << "group " << gi << ": " << seconds << " s" << std::endl;
    }
    std::cout << total << " configurations rendered, " << failed << " failed" << std::endl;
    if (!limit) EXPECT_GE(total, 10000u);
    EXPECT_EQ(failed, 0u);
    for (const std::string& f : firstFailures) ADD_FAILURE() << f;
}
