// Work the frame skips because it cannot change the image: each skip is checked twice, that the
// pass did not run, and that the image equals (within 1/255) the frame with skipping off, where
// every planned pass runs in full.
#include "node/WaterNodeImpl.h"
#include "GLHarness.h"
#include "passes/GlowPasses.h"
#include "surface/SpectralWaves.h"
#include <osgWater/WaterNode>
#include <algorithm>
#include <cmath>
#include <iostream>

using namespace testing_gl;
using namespace osgWater;

namespace {

// the largest channel difference over two read-back images of the same size
float largestDifference(const osg::Image* a, const osg::Image* b)
{
    float d = 0.0f;
    for (int y = 0; y < a->t(); ++y)
        for (int x = 0; x < a->s(); ++x)
            for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(pixel(a, x, y)[c] - pixel(b, x, y)[c]));
    return d;
}

osg::ref_ptr<WaterNode> wavyLake()
{
    osg::ref_ptr<WaterNode> water = new WaterNode;
    water->getSurface()->setWaves({ makeWave(1.0f, 0.3f, 6.0f, 0.1f), makeWave(-0.4f, 1.0f, 3.5f, 0.05f) });
    water->getSurface()->setSize(200.0f);
    water->getSettings()->setGlowEnabled(false);
    water->getSettings()->setCausticsEnabled(false);
    water->addChild(checkerPlane(-2.0f, 200.0f, 1.0f));
    return water;
}

struct SkipFrames { osg::ref_ptr<osg::Image> full, skipped; };

// the same frame with skipping off, then on
SkipFrames renderBothWays(Harness& h, WaterNode* water, double t)
{
    SkipFrames f;
    water->setSkippingEnabled(false);
    h.frame(t);
    f.full = h.readColor();
    water->setSkippingEnabled(true);
    h.frame(t);
    f.skipped = h.readColor();
    return f;
}

}

TEST(Skips, TheCapIsNotDrawnWhenTheNearPlaneCannotReachTheWater)
{
    Harness h(160, 120);
    REQUIRE_GL(h);
    osg::ref_ptr<WaterNode> water = wavyLake();
    h.setScene(water.get());
    h.lookAt(osg::Vec3d(0, 0, 3), osg::Vec3d(0, 10, 0));
    const UnderwaterView* uv = osgWater::internals(*water).getUnderwaterView();
    const unsigned drawsBefore = uv->getCapDraws(), skipsBefore = uv->getCapSkips();
    const SkipFrames f = renderBothWays(h, water.get(), 1.0);
    EXPECT_EQ(uv->getCapDraws(), drawsBefore + 1) << "skipping off: the planned cap is drawn";
    EXPECT_EQ(uv->getCapSkips(), skipsBefore + 1) << "3 m above the crests the near plane cannot reach them";
    EXPECT_LE(largestDifference(f.full.get(), f.skipped.get()), 1.0f / 255.0f);

    // an eye among the crests: the near plane reaches the water, the cap is drawn
    h.lookAt(osg::Vec3d(0, 0, 0.02), osg::Vec3d(0, 10, 0.02));
    const unsigned draws = uv->getCapDraws();
    h.frame(1.0);
    EXPECT_EQ(uv->getCapDraws(), draws + 1);
}

TEST(Skips, APassCompilesCausticsAndFogOnlyWhereTheyCanChangeItsPixels)
{
    Harness h(160, 120);
    REQUIRE_GL(h);
    osg::ref_ptr<WaterNode> water = wavyLake();
    water->getSettings()->setCausticsEnabled(true);
    h.setScene(water.get());
    auto has = [](osg::Camera* c, const char* define) { return c->getStateSet()->getDefinePair(define) != nullptr; };

    // from above: the reflection keeps the air (no caustics, no fog), the refraction the water
    // below, which the water shader itself fades (caustics, no fog)
    h.lookAt(osg::Vec3d(0, 0, 3), osg::Vec3d(0, 10, -1));
    h.frame(1.0);
    ViewPasses* p = osgWater::internals(*water).getViewPasses(h.camera());
    ASSERT_TRUE(p);
    ASSERT_TRUE(osgWater::internals(*water).getCausticsCamera()) << "the sun is up and a bed lies under the water";
    EXPECT_FALSE(has(p->getReflectionCamera(), "OSGWATER_CAUSTICS"));
    EXPECT_FALSE(has(p->getReflectionCamera(), "OSGWATER_FOG"));
    EXPECT_TRUE(has(p->getRefractionCamera(), "OSGWATER_CAUSTICS"));
    EXPECT_FALSE(has(p->getRefractionCamera(), "OSGWATER_FOG"));

    // from below: the reflection shows the water through water, the refraction the air
    h.lookAt(osg::Vec3d(0, 0, -1), osg::Vec3d(0, 10, 1));
    h.frame(1.0);
    EXPECT_TRUE(has(p->getReflectionCamera(), "OSGWATER_CAUSTICS"));
    EXPECT_TRUE(has(p->getReflectionCamera(), "OSGWATER_FOG"));
    EXPECT_FALSE(has(p->getRefractionCamera(), "OSGWATER_CAUSTICS"));
    EXPECT_FALSE(has(p->getRefractionCamera(), "OSGWATER_FOG"));
}

TEST(Skips, CausticsAreReusedUntilTheWavesCanHaveMovedThem)
{
    Harness h(160, 120);
    REQUIRE_GL(h);
    osg::ref_ptr<WaterNode> water = wavyLake();
    WaterSettings* s = water->getSettings();
    s->setCausticsEnabled(true);
    s->setCausticsGather(WaterSettings::GATHER_CPU); // every context has it: no automatic choice to wait for
    s->setAttenuation(0.05f);
    // a lit bed, which the caustics light
    water->replaceChild(water->getChild(0), litQuad(osg::Vec3(-20, -20, -2), osg::Vec3(20, -20, -2),
                                                    osg::Vec3(20, 20, -2), osg::Vec3(-20, 20, -2)));
    h.setScene(water.get());
    h.lookAt(osg::Vec3d(0, -1, 4), osg::Vec3d(0, 0, -2));
    auto rendered = [&] { return osgWater::internals(*water).getViewPasses(h.camera())->getPlan().runs(PASS_PHOTONS); };

    // the surface where it was: the caustics of the last frame are the caustics of this one
    const SkipFrames f = renderBothWays(h, water.get(), 1.0);
    EXPECT_FALSE(rendered()) << "the same time, the same waves, the same sun";
    EXPECT_LE(largestDifference(f.full.get(), f.skipped.get()), 1.0f / 255.0f);

    // waves moving: reused within the hold time, rendered again after it
    const double hold = water->getCausticsHoldTime();
    ASSERT_GT(hold, 0.0);
    ASSERT_TRUE(std::isfinite(hold));
    // half a texel (the default tolerance) at the fastest wave's phase speed
    const osg::Vec3d& window = osgWater::internals(*water).getCausticsCamera()->getWindow();
    const double texel = std::max(window.x(), window.y()) / osgWater::internals(*water).getCausticsCamera()->getResolution();
    EXPECT_NEAR(hold, 0.5 * texel / water->getSurface()->getMaxPhaseSpeed(), 1e-9);
    h.frame(1.0 + 0.9 * hold);
    EXPECT_FALSE(rendered());
    h.frame(1.0 + 1.1 * hold);
    EXPECT_TRUE(rendered());

    // anything else they depend on: rendered again at once
    s->setSunDirection(osg::Vec3(0.2f, 0.1f, 0.97f));
    h.frame(1.0 + 1.1 * hold);
    EXPECT_TRUE(rendered()) << "the sun moved";

    // a tile's texels are the tile's: half of one of those
    s->setCausticsTileSize(2.0f);
    h.frame(1.0 + 1.1 * hold);
    const double tileTexel = 2.0 / osgWater::internals(*water).getCausticsCamera()->getResolution();
    EXPECT_NEAR(water->getCausticsHoldTime(), 0.5 * tileTexel / water->getSurface()->getMaxPhaseSpeed(), 1e-9);
    s->setCausticsTileSize(0.0f);

    // still water: kept however much time passes
    water->getSurface()->setWaves({});
    h.frame(5.0);
    EXPECT_TRUE(rendered()) << "the waves changed";
    EXPECT_TRUE(std::isinf(water->getCausticsHoldTime()));
    h.frame(50.0);
    EXPECT_FALSE(rendered());
}

// The wind's cascades cost a few milliseconds of FFTs and a texture upload a frame: a frame that
// neither draws nor reads the waves (the water out of view, the eye well above them) does neither,
// and the first frame that sees them again draws them as of its own time.
TEST(Skips, TheWindsWavesAreEvaluatedOnlyForAFrameThatDrawsOrReadsThem)
{
    auto windLake = [] {
        osg::ref_ptr<WaterNode> water = wavyLake();
        water->getSurface()->setSize(140.0f);
        water->getSurface()->setWaveModel(WaterSurface::WAVES_WIND);
        return water;
    };
    const osg::Vec3d eye(0, -30, 4);
    const osg::Vec3d atWater(0, 0, -1), atSky(0, -60, 30);
    Harness h(160, 120);
    REQUIRE_GL(h);
    osg::ref_ptr<WaterNode> water = windLake();
    h.setScene(water.get());
    h.lookAt(eye, atWater);
    h.frame(1.0);
    const detail::SpectralWaves* wind = water->getSurface()->getSpectralWaves();
    ASSERT_NE(wind, nullptr);
    EXPECT_EQ(wind->textureTime(), 1.0);
    const unsigned int uploads = wind->heightTexture()->getImage(0)->getModifiedCount();

    h.lookAt(eye, atSky); // the water out of view, the eye 4 m over waves of centimetres
    h.frame(2.0);
    h.frame(3.0);
    EXPECT_EQ(osgWater::internals(*water).getPassPlan(h.camera()).describe(), "scene");
    EXPECT_EQ(wind->evaluatedTime(), 1.0) << "the cascades were evaluated for a frame that shows no waves";
    EXPECT_EQ(wind->heightTexture()->getImage(0)->getModifiedCount(), uploads) << "the texture was filled for nothing";
    // a query still answers for the time it asks
    const double z = water->getSurfaceHeightAt(3.0, 4.0, 3.0);
    EXPECT_EQ(wind->evaluatedTime(), 3.0);

    h.lookAt(eye, atWater); // the waves of this frame, though a query brought the cascades here first
    h.frame(3.0);
    EXPECT_EQ(wind->textureTime(), 3.0);
    EXPECT_GT(wind->heightTexture()->getImage(0)->getModifiedCount(), uploads);
    osg::ref_ptr<osg::Image> resumed = h.readColor();

    // the same frame from a lake whose waves were drawn on every frame
    Harness h2(160, 120);
    osg::ref_ptr<WaterNode> always = windLake();
    h2.setScene(always.get());
    h2.lookAt(eye, atWater);
    for (double t : { 1.0, 2.0, 3.0 }) h2.frame(t);
    EXPECT_EQ(always->getSurfaceHeightAt(3.0, 4.0, 3.0), z);
    EXPECT_LE(largestDifference(resumed.get(), h2.readColor().get()), 1.0f / 255.0f);
}

namespace {
// a small highlight 25 degrees below the horizon, in view from (0, 0, 3) towards (0, 10, 0)
osg::ref_ptr<WaterNode> glowingLake()
{
    osg::ref_ptr<WaterNode> water = new WaterNode;
    water->getSurface()->setWaves({ makeWave(1.0f, 0.2f, 5.0f, 0.01f) });
    water->getSurface()->setSize(400.0f);
    WaterSettings* s = water->getSettings();
    s->setCausticsEnabled(false);
    s->setSunDirection(osg::Vec3(0.1f, 0.9f, 0.42f));
    s->setGlowExponent(2000.0f);
    s->setGlowIntensity(4.0f);
    water->addChild(checkerPlane(-2.0f, 200.0f, 1.0f));
    return water;
}
}

TEST(Skips, TheGlowIsDrawnOnlyWhereTheHighlightCanReach)
{
    Harness h(200, 150);
    REQUIRE_GL(h);
    osg::ref_ptr<WaterNode> water = glowingLake(); // a small highlight: a small part of the view
    WaterSettings* s = water->getSettings();
    h.setScene(water.get());
    h.lookAt(osg::Vec3d(0, 0, 3), osg::Vec3d(0, 10, 0));

    s->setGlowEnabled(false);
    h.frame(1.0);
    osg::ref_ptr<osg::Image> noGlow = h.readColor();
    s->setGlowEnabled(true);
    const SkipFrames f = renderBothWays(h, water.get(), 1.0);
    ASSERT_TRUE(osgWater::internals(*water).getViewPasses(h.camera())->getGlowDrawn());
    EXPECT_GT(largestDifference(noGlow.get(), f.full.get()), 0.05f) << "the glow must show for the test to mean anything";

    const GlowPasses* g = osgWater::internals(*water).getViewPasses(h.camera())->getGlow();
    const osg::Vec4i& reach = g->getGlowTexels();
    EXPECT_LT(reach.z() * reach.w(), g->getWidth() * g->getHeight() / 2) << "the highlight covers little of the view";
    const osg::Viewport* vp = g->getHighlightCamera()->getViewport();
    EXPECT_LT(vp->width() * vp->height(), 0.75 * g->getWidth() * g->getHeight()) << "the highlight pass draws a part";
    EXPECT_LE(largestDifference(f.full.get(), f.skipped.get()), 1.0f / 255.0f);
}

// The composite adds the glow in horizontal bands, each drawn only where the last blur counted a
// texel bright enough to show (GlowBands): its fragments are exactly the pixels of the bands whose
// rows of the blurred glow hold light, and the image is the one with every band drawn.
TEST(Skips, TheGlowIsAddedOnlyInTheBandsItReaches)
{
    Harness h(200, 160);
    REQUIRE_GL(h);
    osg::ref_ptr<WaterNode> water = glowingLake();
    // a wall 4 m ahead hides the highlight's lower half: rows the highlight's cone reaches, dark
    water->addChild(litQuad(osg::Vec3(-20, 4, -2), osg::Vec3(20, 4, -2), osg::Vec3(20, 4, 0.8f), osg::Vec3(-20, 4, 0.8f)));
    water->setPassTimingEnabled(true);
    h.setScene(water.get());
    h.lookAt(osg::Vec3d(0, 0, 3), osg::Vec3d(0, 10, 0));
    auto frames = [&] {
        for (int i = 0; i < 3; ++i) h.frame(1.0); // measures are read a frame late
        return h.readColor();
    };
    water->setSkippingEnabled(false);
    osg::ref_ptr<osg::Image> full = frames();
    const GlowPasses* g = osgWater::internals(*water).getViewPasses(h.camera())->getGlow();
    ASSERT_NE(g, nullptr);
    // every band drawn: the shader's invocations per pixel (the bands' quads add helper pixels
    // along their diagonals, which a rasteriser shades in 2 x 2 blocks)
    const osg::Scissor* sc = g->getCompositeScissor();
    const double perPixel = g->getCompositeMeasure().fragments / double(sc->width() * sc->height());
    EXPECT_GE(perPixel, 1.0);
    EXPECT_LT(perPixel, 1.3);

    water->setSkippingEnabled(true);
    osg::ref_ptr<osg::Image> banded = frames();
    osg::ref_ptr<osg::Image> glow = h.readTexture(g->getGlowTexture());
    ASSERT_TRUE(glow.valid());
    const int B = GlowBands::BANDS, H = glow->t();
    std::vector<bool> lit(B, false);
    for (int k = 0; k < B; ++k) {
        // the rows whose centres the band's counted quad covers
        const double r0 = std::max(0.0, double(k) * H / B - GlowBands::MARGIN), r1 = std::min(double(H), double(k + 1) * H / B + GlowBands::MARGIN);
        for (int y = 0; y < H; ++y)
            if (y + 0.5 >= r0 && y + 0.5 < r1)
                for (int x = 0; x < glow->s(); ++x)
                    if (std::max({ pixel(glow.get(), x, y)[0], pixel(glow.get(), x, y)[1], pixel(glow.get(), x, y)[2] }) > 0.0f)
                        lit[k] = true;
    }
    // the composite's pixels: those of its scissor in a lit band (band k holds the view's rows whose
    // centres lie in [k, k + 1) view heights / B)
    const int viewHeight = int(h.camera()->getViewport()->height());
    double pixels = 0.0;
    std::vector<bool> inReach(B, false);
    for (int y = sc->y(); y < sc->y() + sc->height(); ++y) {
        const int k = std::min(B - 1, int(std::floor((y + 0.5) * B / viewHeight)));
        inReach[k] = true;
        if (lit[k]) pixels += sc->width();
    }
    int bandsInReach = 0, litBands = 0;
    for (int k = 0; k < B; ++k) {
        bandsInReach += inReach[k];
        litBands += inReach[k] && lit[k];
    }
    EXPECT_GT(litBands, 0) << "the glow must show for the test to mean anything";
    EXPECT_LT(litBands, bandsInReach) << "a band the highlight's cone reaches but its light does not";
    std::cout << litBands << " of " << bandsInReach << " bands lit, " << g->getCompositeMeasure().fragments << " fragments for "
              << pixels << " pixels\n";
    EXPECT_NEAR(g->getCompositeMeasure().fragments, perPixel * pixels, 0.05 * perPixel * pixels);
    EXPECT_LE(largestDifference(full.get(), banded.get()), 1.0f / 255.0f);
}
