// Glow of the sun's highlight (thesis §9.3): only pixels near the highlight change, nothing
// changes with the sun behind the viewer, and the glow target follows the view's size.
#include "node/WaterNodeImpl.h"
#include "GLHarness.h"
#include <osgWater/WaterNode>
#include "optics/Srgb.h"
#include "surface/SpectralWaves.h"
#include <algorithm>
#include <cmath>
#include <iostream>

using namespace testing_gl;
using namespace osgWater;

namespace {

osg::ref_ptr<WaterNode> sunnyWater(const osg::Vec3& towardsSun)
{
    osg::ref_ptr<WaterNode> water = new WaterNode;
    water->getSurface()->setWaves({});
    water->getSurface()->setSize(400.0f);
    water->getSettings()->setCausticsEnabled(false);
    water->getSettings()->setSunDirection(towardsSun);
    water->addChild(checkerPlane(-2.0f, 200.0f, 1.0f));
    return water;
}

struct Pair { osg::ref_ptr<osg::Image> off, on, highlight; bool drawn = false; };

// the same frame without and with glow
Pair renderPair(Harness& h, WaterNode* water)
{
    Pair p;
    h.setScene(water);
    h.lookAt(osg::Vec3d(0, 0, 3), osg::Vec3d(0, 10, 0), 45.0);
    water->getSettings()->setGlowEnabled(false);
    h.frame(1.0);
    p.off = h.readColor();
    water->getSettings()->setGlowEnabled(true);
    h.frame(1.0);
    p.on = h.readColor();
    ViewPasses* passes = osgWater::internals(*water).getViewPasses(h.camera());
    p.drawn = passes && passes->getGlowDrawn();
    if (p.drawn) p.highlight = h.readTexture(passes->getGlow()->getHighlightTexture());
    return p;
}

}

TEST(Glow, BlurWeightsAreANormalisedGaussian)
{
    std::vector<float> w = GlowPasses::blurWeights(3.0f);
    ASSERT_EQ(w.size(), 4u); // taps -3..3, the thesis's 7x7 footprint
    double sum = w[0];
    for (size_t i = 1; i < w.size(); ++i) {
        sum += 2.0 * w[i];
        EXPECT_LT(w[i], w[i - 1]);
    }
    EXPECT_NEAR(sum, 1.0, 1e-6);
    EXPECT_NEAR(w[1] / w[0], std::exp(-1.0 / (2.0 * 1.5 * 1.5)), 1e-5); // sigma = radius / 2
    EXPECT_EQ(GlowPasses::blurWeights(0.0f), std::vector<float>{ 1.0f });
    EXPECT_EQ(GlowPasses::blurWeights(NAN), std::vector<float>{ 1.0f });
    EXPECT_EQ(GlowPasses::blurWeights(1e9f).size(), 33u);
}

TEST(Glow, ChangesOnlyPixelsNearTheHighlight)
{
    Harness h(200, 150);
    REQUIRE_GL(h);
    // sun 30 degrees up ahead: its mirror image lies 30 degrees below the horizon, in view
    osg::ref_ptr<WaterNode> water = sunnyWater(osg::Vec3(0.0f, 0.866f, 0.5f));
    Pair p = renderPair(h, water.get());
    ASSERT_TRUE(p.drawn);
    ASSERT_TRUE(p.highlight.valid());
    ASSERT_TRUE(allFinite(p.on.get()));
    EXPECT_EQ(p.highlight->s(), 50); // a quarter of the view per axis
    EXPECT_EQ(p.highlight->t(), 38);

    // hot texels of the highlight pass (above 1/1024), and how far the blur and the bilinear
    // upsampling can carry them: (radius + 1.5) glow texels, in view pixels
    const double scale = 200.0 / p.highlight->s();
    const double reach = (water->getSettings()->getGlowRadius() + 1.5) * scale;
    std::vector<osg::Vec2d> hot;
    for (int j = 0; j < p.highlight->t(); ++j)
        for (int i = 0; i < p.highlight->s(); ++i) {
            const float* v = pixel(p.highlight.get(), i, j);
            if (std::max(v[0], std::max(v[1], v[2])) > 1.0f / 1024.0f) hot.emplace_back((i + 0.5) * scale, (j + 0.5) * scale);
        }
    ASSERT_FALSE(hot.empty());
    ASSERT_LT(hot.size(), size_t(p.highlight->s() * p.highlight->t() / 2)) << "a highlight, not the whole view";
    float maxGain = 0.0f, maxFar = 0.0f, minGain = 0.0f;
    int far = 0;
    for (int y = 0; y < h.height(); ++y)
        for (int x = 0; x < h.width(); ++x) {
            double d2 = 1e30;
            for (const osg::Vec2d& c : hot) d2 = std::min(d2, (c - osg::Vec2d(x + 0.5, y + 0.5)).length2());
            const float* a = pixel(p.off.get(), x, y);
            const float* b = pixel(p.on.get(), x, y);
            for (int ch = 0; ch < 3; ++ch) {
                const float g = b[ch] - a[ch];
                maxGain = std::max(maxGain, g);
                minGain = std::min(minGain, g);
                if (d2 > reach * reach) maxFar = std::max(maxFar, std::fabs(g));
            }
            far += d2 > reach * reach;
        }
    EXPECT_GT(far, h.width() * h.height() / 2) << "most of the view is away from the highlight";
    EXPECT_LE(maxFar, 1.0f / 255.0f) << "glow away from the highlight";
    EXPECT_GT(maxGain, 0.2f) << "no visible glow at the highlight";
    EXPECT_GE(minGain, -1e-6f) << "glow only adds light";
}

// The glow is light: where the view stores sRGB (an 8-bit sRGB target, as a window's framebuffer
// usually is) it is added to the finished image's linear light, each pixel encode(decode(without)
// + glow) within 2.5/255 (two 8-bit images, one glow target texel a pixel). Added to display values
// instead it would be off by more than 0.03 at the highlight's fringe.
TEST(Glow, AddsLinearLightWhereTheViewStoresSrgb)
{
    Harness h(200, 150, GL_SRGB8_ALPHA8);
    REQUIRE_GL(h);
    osg::ref_ptr<WaterNode> water = sunnyWater(osg::Vec3(0.0f, 0.866f, 0.5f));
    water->getSettings()->setGlowResolution(1.0f); // a glow texel a view pixel: no upsampling
    Pair p = renderPair(h, water.get());
    ASSERT_TRUE(p.drawn);
    ViewPasses* passes = osgWater::internals(*water).getViewPasses(h.camera());
    osg::ref_ptr<osg::Image> glow = h.readTexture(passes->getGlow()->getGlowTexture());
    ASSERT_EQ(glow->s(), h.width());
    const float intensity = water->getSettings()->getGlowIntensity();
    double worst = 0.0, displaySum = 0.0;
    int checked = 0;
    for (int y = 0; y < h.height(); ++y)
        for (int x = 0; x < h.width(); ++x) {
            const float* g = pixel(glow.get(), x, y);
            if (std::max(g[0], std::max(g[1], g[2])) < 0.02f) continue;
            const float* off = pixel(p.off.get(), x, y);
            const float* on = pixel(p.on.get(), x, y);
            for (int c = 0; c < 3; ++c) {
                const float expect = optics::encodeSrgb(optics::decodeSrgb(off[c]) + intensity * g[c]);
                worst = std::max(worst, double(std::fabs(on[c] - expect)));
                displaySum = std::max(displaySum, double(std::fabs(std::min(off[c] + intensity * g[c], 1.0f) - expect)));
            }
            ++checked;
        }
    std::cout << checked << " glowing pixels, worst " << worst * 255.0 << "/255; a display-value sum would be "
              << displaySum << " off" << std::endl;
    ASSERT_GT(checked, 20);
    EXPECT_GT(displaySum, 0.03) << "the test scene cannot tell linear from display sums";
    EXPECT_LT(worst, 2.5 / 255.0);
}

TEST(Glow, AnObjectInFrontOfTheHighlightHidesIt)
{
    Harness h(200, 150);
    REQUIRE_GL(h);
    osg::ref_ptr<WaterNode> water = sunnyWater(osg::Vec3(0.0f, 0.866f, 0.5f));
    // a wall 3 m ahead over the left half of the view (x < 0; the eye looks along +y from x = 0):
    // the highlight (5.2 m ahead) shows only right of the view's centre
    water->addChild(emissiveQuad(osg::Vec3(-50, 3, -2), osg::Vec3(0, 3, -2), osg::Vec3(0, 3, 20), osg::Vec3(-50, 3, 20),
                                 osg::Vec4(0.2f, 0.2f, 0.2f, 1)));
    Pair p = renderPair(h, water.get());
    ASSERT_TRUE(p.drawn);
    ASSERT_TRUE(p.highlight.valid());
    int left = 0, right = 0;
    for (int j = 0; j < p.highlight->t(); ++j)
        for (int i = 0; i < p.highlight->s(); ++i) {
            const float* v = pixel(p.highlight.get(), i, j);
            if (std::max(v[0], std::max(v[1], v[2])) <= 1.0f / 1024.0f) continue;
            if (i < p.highlight->s() / 2 - 1) ++left;
            if (i > p.highlight->s() / 2 + 1) ++right;
        }
    EXPECT_GT(right, 0) << "the highlight right of the wall";
    EXPECT_EQ(left, 0) << "the highlight behind the wall";
}

TEST(Glow, NothingWhenTheSunIsBehindTheViewer)
{
    Harness h(200, 150);
    REQUIRE_GL(h);
    osg::ref_ptr<WaterNode> water = sunnyWater(osg::Vec3(0.0f, -0.866f, 0.5f));
    Pair p = renderPair(h, water.get());
    EXPECT_FALSE(p.drawn) << "the highlight cannot be in view: no glow passes";
    float maxDiff = 0.0f;
    for (int y = 0; y < h.height(); ++y)
        for (int x = 0; x < h.width(); ++x)
            for (int ch = 0; ch < 3; ++ch)
                maxDiff = std::max(maxDiff, std::fabs(pixel(p.on.get(), x, y)[ch] - pixel(p.off.get(), x, y)[ch]));
    EXPECT_LE(maxDiff, 1.0f / 255.0f);
    // under water there is no highlight to glow either
    h.lookAt(osg::Vec3d(0, 0, -1), osg::Vec3d(0, 10, 0), 45.0);
    water->getSettings()->setSunDirection(osg::Vec3(0.0f, 0.866f, 0.5f));
    h.frame(1.0);
    EXPECT_FALSE(osgWater::internals(*water).getViewPasses(h.camera())->getGlowDrawn());
}

TEST(Glow, TargetFollowsTheViewportAndTheResolutionSetting)
{
    Harness h(200, 150);
    REQUIRE_GL(h);
    osg::ref_ptr<WaterNode> water = sunnyWater(osg::Vec3(0.0f, 0.866f, 0.5f));
    h.setScene(water.get());
    h.lookAt(osg::Vec3d(0, 0, 3), osg::Vec3d(0, 10, 0), 45.0);
    h.frame(1.0);
    ViewPasses* passes = osgWater::internals(*water).getViewPasses(h.camera());
    ASSERT_TRUE(passes && passes->getGlow());
    EXPECT_EQ(passes->getGlow()->getWidth(), 50);
    EXPECT_EQ(passes->getGlow()->getHeight(), 38);
    h.camera()->setViewport(0, 0, 100, 80); // a resized window
    h.frame(1.1);
    EXPECT_EQ(passes->getGlow()->getWidth(), 25);
    EXPECT_EQ(passes->getGlow()->getHeight(), 20);
    water->getSettings()->setGlowResolution(0.5f);
    h.frame(1.2);
    EXPECT_EQ(passes->getGlow()->getWidth(), 50);
    EXPECT_EQ(passes->getGlow()->getHeight(), 40);
    osg::ref_ptr<osg::Image> img = h.readTexture(passes->getGlow()->getGlowTexture());
    ASSERT_TRUE(img.valid());
    EXPECT_EQ(img->s(), 50);
    EXPECT_TRUE(allFinite(img.get()));
}

// A view's glow passes remade for a new size take the programs the water made already (the program
// library), instead of building and compiling them again
TEST(Glow, PassesRemadeForANewSizeKeepTheirPrograms)
{
    Harness h(200, 150);
    REQUIRE_GL(h);
    osg::ref_ptr<WaterNode> water = sunnyWater(osg::Vec3(0.0f, 0.866f, 0.5f));
    h.setScene(water.get());
    h.lookAt(osg::Vec3d(0, 0, 3), osg::Vec3d(0, 10, 0), 45.0);
    h.frame(1.0);
    ViewPasses* passes = osgWater::internals(*water).getViewPasses(h.camera());
    ASSERT_TRUE(passes && passes->getGlow());
    osg::ref_ptr<GlowPasses> before = passes->getGlow();
    const osg::StateAttribute* program = before->getComposite()->getStateSet()->getAttribute(osg::StateAttribute::PROGRAM);
    const size_t programs = osgWater::internals(*water).getStateSets().getPrograms().size();
    h.camera()->setViewport(0, 0, 100, 80); // a resized window: new glow passes
    h.frame(1.1);
    ASSERT_NE(passes->getGlow(), before.get()) << "the glow passes should have been remade";
    EXPECT_EQ(passes->getGlow()->getComposite()->getStateSet()->getAttribute(osg::StateAttribute::PROGRAM), program);
    EXPECT_EQ(osgWater::internals(*water).getStateSets().getPrograms().size(), programs);
}

// Water too far for its waves to be drawn: each texel of the highlight spans more than every one of
// the wind's tiles, so the cascades read there are the tiles' means (level water) and every slope is
// roughness, sigma^2 the water's mean square slope. The highlight is then the thesis's lobe widened
// by the slopes: pow(cos a, e) is close to a Gaussian of the angle a with variance 1/e per axis; a
// facet sloped by s turns the mirror direction by 2 s, a Gaussian of variance 2 sigma^2 per axis (the
// mean square slope sigma^2 is both axes'); together a lobe of exponent e' = e / (1 + 2 e sigma^2),
// scaled by e'/e to keep its light. Without the roughness the lobe would be e's, a spot 12 times
// brighter and 3.5 times narrower.
TEST(Glow, WaterTooFarForItsWavesGlowsWithTheSlopesLobe)
{
    Harness h(256, 256);
    REQUIRE_GL(h);
    osg::ref_ptr<WaterNode> water = new WaterNode;
    WaterSurface* surface = water->getSurface();
    surface->setSize(20000.0f);
    WindWaves breeze; // 5 m/s over 140 m: waves of 40 cm, tiles of metres
    breeze.fetch = 140.0f;
    surface->setWind(breeze);
    surface->setWaveModel(WaterSurface::WAVES_WIND);
    WaterSettings* s = water->getSettings();
    s->setCausticsEnabled(false);
    const osg::Vec3d L(0.0, 0.5, std::sqrt(0.75)); // the sun 60 degrees up
    s->setSunDirection(L);
    s->setGlowEnabled(true);
    h.setScene(water.get());
    // the sun's mirror image from 6 km up lies 6928 m away along -R, R = (0, -0.5, 0.866)
    const osg::Vec3d eye(0, -3000, 6000), R(-L.x(), -L.y(), L.z());
    h.lookAt(eye, eye - R * (6000.0 / R.z()), 30.0);
    h.frame(2.0);
    ViewPasses* passes = osgWater::internals(*water).getViewPasses(h.camera());
    ASSERT_TRUE(passes && passes->getGlowDrawn());
    osg::ref_ptr<osg::Image> highlight = h.readTexture(passes->getGlow()->getHighlightTexture());
    ASSERT_TRUE(highlight.valid());

    const detail::SpectralWaves* wind = surface->getSpectralWaves();
    ASSERT_NE(wind, nullptr);
    // a highlight texel spans about 6928 m x 0.52 rad / 64 = 57 m; every tile is shorter
    for (unsigned int c = 0; c < wind->cascadeCount(); ++c) EXPECT_LT(1.0 / wind->cascadeScale(c).x(), 40.0) << c;
    const double sigma2 = wind->meanSquareSlope(), e = s->getGlowExponent();
    const double coxMunk = 0.003 + 0.00512 * 5.0;
    EXPECT_NEAR(sigma2, coxMunk, 0.2 * coxMunk);
    const double e1 = e / (1.0 + 2.0 * e * sigma2);

    const osg::Camera* cam = h.camera();
    const osg::Matrixd ndcToLocal = osg::Matrixd::inverse(cam->getViewMatrix() * cam->getProjectionMatrix());
    const osg::Vec3 sun = s->getSunColor();
    double worst = 0.0, peak = 0.0, lit = 0.0;
    for (int j = 0; j < highlight->t(); ++j)
        for (int i = 0; i < highlight->s(); ++i) {
            const osg::Vec3d ndc(2.0 * (i + 0.5) / highlight->s() - 1.0, 2.0 * (j + 0.5) / highlight->t() - 1.0, 0.0);
            const osg::Vec3d dir = ndc * ndcToLocal - eye;
            ASSERT_LT(dir.z(), 0.0);
            const osg::Vec3d P = eye + dir * (-eye.z() / dir.z());
            osg::Vec3d E = eye - P;
            E.normalize();
            const double expected = (e1 / e) * std::pow(std::max(R * E, 0.0), e1) * sun.x();
            const double got = pixel(highlight.get(), i, j)[0];
            worst = std::max(worst, std::fabs(got - expected) / (0.02 * e1 / e + 0.03 * expected));
            peak = std::max(peak, got);
            lit += got > 0.1 * e1 / e;
        }
    // the lobe within 3% (the highlight's half floats, the drawn mesh's waves), plus 2% of its peak
    EXPECT_LT(worst, 1.0);
    EXPECT_NEAR(peak, e1 / e, 0.05 * e1 / e);
    EXPECT_GT(lit, 0.1 * highlight->s() * highlight->t()) << "a wide glitter path, not a spot";
}
