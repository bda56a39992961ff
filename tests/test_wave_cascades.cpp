// The wind sea's FFT cascades (surface/WaveCascades) against the spectrum they realise: their bands
// tile the wavenumbers without gap, every texel is the direct sum over the cascade's bins, the
// realised variance is the spectrum's integral, nothing repeats inside the water (autocorrelation and
// the strongest bins of a window's spectrum), the height query meets the choppy surface and its
// normal is the displaced surface's, and bad
// parameters give a flat or finite sea. No GPU.
#include "surface/WaveCascades.h"
#include <gtest/gtest.h>
#include <fftw3.h>
#include <osg/Math>
#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <limits>
#include <random>

using namespace osgWater;

namespace {

// a breeze on the demo's lake: 5 m/s over its 140 m, the water as wide
WaveCascades::Params lakeBreeze()
{
    WaveCascades::Params p;
    p.sea.windSpeed = 5.0;
    p.sea.fetch = 140.0;
    p.extent = 140.0;
    return p;
}

// a fresh wind on a large lake: 10 m/s over 5 km, a 500 m square of it drawn
WaveCascades::Params freshWind()
{
    WaveCascades::Params p;
    p.sea.windSpeed = 10.0;
    p.sea.fetch = 5000.0;
    p.sea.windDirection = 0.6;
    p.extent = 500.0;
    return p;
}

// the correlation of the height with itself shifted by s, over `points` random points of the water
double autocorrelation(const WaveCascades& w, const osg::Vec2d& s, const std::vector<osg::Vec2d>& points)
{
    double ab = 0.0, aa = 0.0, bb = 0.0;
    for (const osg::Vec2d& p : points) {
        const double a = w.sample(p.x(), p.y()).displacement.z(), b = w.sample(p.x() + s.x(), p.y() + s.y()).displacement.z();
        ab += a * b;
        aa += a * a;
        bb += b * b;
    }
    return ab / std::sqrt(aa * bb);
}

// the mean of the cascades' texels' h^2: the realised height variance (the cascades are independent)
double realisedVariance(const WaveCascades& w)
{
    double v = 0.0;
    for (unsigned int c = 0; c < w.bands().size(); ++c) {
        double sum = 0.0;
        for (const WaveCascades::Texel& t : w.texels(c)) sum += double(t.displacement.z()) * t.displacement.z();
        v += sum / w.texels(c).size();
    }
    return v;
}

}

TEST(WaveCascades, BandsTileTheWavenumbersAndTheFirstTileCoversTheWater)
{
    for (const WaveCascades::Params& p : { lakeBreeze(), freshWind() }) {
        const std::vector<CascadeBand> bands = WaveCascades::chooseBands(p.sea, p.extent, p.size);
        ASSERT_EQ(bands.size(), WaveCascades::CASCADES);
        EXPECT_EQ(bands.front().kLow, 0.0);
        EXPECT_GT(bands.front().tile, p.extent); // the longest waves never repeat inside the water
        for (size_t c = 0; c < bands.size(); ++c) {
            const CascadeBand& b = bands[c];
            EXPECT_LT(b.kLow, b.kHigh) << c;
            if (c > 0) EXPECT_DOUBLE_EQ(b.kLow, bands[c - 1].kHigh) << "a gap or overlap below cascade " << c;
            // its shortest wave spans SAMPLES_PER_WAVE texels or more; its longest fits twice in its tile
            EXPECT_GE(2.0 * osg::PI / b.kHigh, WaveCascades::SAMPLES_PER_WAVE * b.tile / p.size * (1.0 - 1e-9)) << c;
            if (c > 0) EXPECT_GE(b.tile, 2.0 * (2.0 * osg::PI / b.kLow) * (1.0 - 1e-9)) << c;
        }
        // the tail reaches the shortest wave held, or nearly as far as its tile can
        const CascadeBand& tail = bands.back();
        const double shortest = 2.0 * osg::PI / WaveCascades::shortestWave(p.sea);
        EXPECT_LE(tail.kHigh, shortest * (1.0 + 1e-9));
        if (tail.kHigh < shortest * (1.0 - 1e-9)) EXPECT_GE(tail.kHigh / tail.kLow, p.size / (4.0 * WaveCascades::SAMPLES_PER_WAVE));
    }
}

// Cox and Munk's mean square slope, 0.003 + 0.00512 U, holds every wave down to the capillaries:
// the slopes the texels realise plus the roughness left for the shading make it, within 20%, for a
// breeze to a fresh wind on the small lake (where JONSWAP's tail would overshoot it) and a large one
TEST(WaveCascades, TheSlopesHeldAndTheRoughnessMakeCoxMunksTotal)
{
    for (WaveCascades::Params p : { lakeBreeze(), freshWind() })
        for (double wind : { 2.0, 5.0, 10.0 }) {
            p.sea.windSpeed = wind;
            const double coxMunk = 0.003 + 0.00512 * wind;
            WaveCascades w(p);
            w.update(3.0);
            double realised = 0.0; // the cascades are independent: their slopes' variances add
            for (unsigned int c = 0; c < w.bands().size(); ++c) {
                double sum = 0.0;
                for (const WaveCascades::Texel& t : w.texels(c)) sum += double(t.slope.length2());
                realised += sum / w.texels(c).size();
            }
            const double total = realised + w.unresolvedSlopeVariance();
            EXPECT_NEAR(total, coxMunk, 0.2 * coxMunk) << wind << " m/s over " << p.sea.fetch << " m";
            EXPECT_LE(realised, 1.2 * coxMunk) << wind << " m/s over " << p.sea.fetch << " m";
            EXPECT_GE(w.unresolvedSlopeVariance(), 0.0);
            const double shortest = WaveCascades::shortestWave(p.sea);
            EXPECT_GE(shortest, WaveCascades::SHORTEST_WAVE);
            EXPECT_NEAR(2.0 * osg::PI / w.bands().back().kHigh, shortest, 1e-9 * shortest);
            std::cout << wind << " m/s over " << p.sea.fetch << " m: slopes held " << realised << ", roughness "
                      << w.unresolvedSlopeVariance() << ", Cox-Munk " << coxMunk << ", shortest wave " << shortest << " m\n";
        }
}

// What the bilinear interpolation between texels hides of the slopes (the shaders' roughness under a
// texel, and the reference's facets): nothing at a texel's own sample, and over the water, beside the
// interpolated slopes' own variance, exactly what the texels hold: the mean over points of
// |interpolated slope|^2 + the hidden variance is the texels' mean |slope|^2 (the cascades'
// interpolated slopes are uncorrelated, so the sum over cascades holds too)
TEST(WaveCascades, WhatTheInterpolationHidesMakesUpTheTexelsSlopes)
{
    WaveCascades w(lakeBreeze());
    w.update(3.0);
    double texels = 0.0;
    for (unsigned int c = 0; c < w.bands().size(); ++c) {
        if (!w.holdsWaves(c)) continue;
        double sum = 0.0;
        for (const WaveCascades::Texel& t : w.texels(c)) sum += double(t.slope.length2());
        texels += sum / w.texels(c).size();
    }
    ASSERT_GT(texels, 0.0);
    // at a sample of the finest cascade's texels, its own share is 0 (the others' is not)
    const unsigned int finest = unsigned(w.bands().size()) - 1;
    const double texel = w.bands()[finest].tile / w.params().size;
    EXPECT_EQ(w.subTexelSlopeVariance(0.0, 0.0), 0.0) << "every cascade's texel (0, 0) is sampled there";
    EXPECT_GT(w.subTexelSlopeVariance(0.5 * texel, 0.5 * texel), 0.0);
    std::mt19937 engine(11);
    std::uniform_real_distribution<double> place(-70.0, 70.0);
    double shown = 0.0, hidden = 0.0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
        const double x = place(engine), y = place(engine);
        shown += double(w.sample(x, y).slope.length2());
        const double v = w.subTexelSlopeVariance(x, y);
        ASSERT_GE(v, 0.0);
        hidden += v;
    }
    shown /= n;
    hidden /= n;
    std::cout << "texels' slopes " << texels << ": interpolated " << shown << " + hidden " << hidden << "\n";
    EXPECT_GT(hidden, 0.05 * texels) << "the finest waves are a texel or two long: interpolation hides a share of them";
    EXPECT_NEAR(shown + hidden, texels, 0.02 * texels);
}

TEST(WaveCascades, EveryTexelIsTheDirectSumOverItsCascadesBins)
{
    WaveCascades::Params p = freshWind();
    p.size = 32; // the direct sum is over every bin: small tiles keep it quick
    p.choppiness = 1.0;
    WaveCascades w(p);
    std::mt19937 engine(3);
    for (double t : { 0.0, 1.0e5 + 0.37 }) { // a day on, omega t far beyond 2 pi: no precision lost
        w.update(t);
        unsigned int held = 0;
        for (unsigned int c = 0; c < w.bands().size(); ++c) {
            if (!w.holdsWaves(c)) continue; // flat (below)
            ++held;
            const double tile = w.bands()[c].tile;
            double scale = 0.0;
            for (const WaveCascades::Texel& texel : w.texels(c)) scale = std::max(scale, double(std::fabs(texel.displacement.z())));
            ASSERT_GT(scale, 0.0) << c;
            for (int k = 0; k < 40; ++k) {
                const unsigned int i = engine() % p.size, j = engine() % p.size;
                const WaveCascades::Texel& fft = w.texels(c)[j * p.size + i];
                const WaveCascades::Texel direct = w.directSum(i * tile / p.size, j * tile / p.size, int(c));
                // float FFT against double sums: 1e-4 of the cascade's largest height
                for (int f = 0; f < 3; ++f)
                    EXPECT_NEAR(fft.displacement[f], direct.displacement[f], 1e-4 * scale) << "cascade " << c << " field " << f << " t " << t;
                for (int f = 0; f < 2; ++f)
                    EXPECT_NEAR(fft.slope[f], direct.slope[f], 1e-4 * scale * w.bands()[c].kHigh) << "cascade " << c << " slope " << f;
                for (int f = 0; f < 3; ++f)
                    EXPECT_NEAR(fft.jacobian[f], direct.jacobian[f], 1e-4 * scale * w.bands()[c].kHigh) << "cascade " << c << " jacobian " << f;
            }
        }
        EXPECT_GE(held, WaveCascades::CASCADES - 1);
    }
}

// A band the spectrum leaves nearly empty (a lake's waves longer than its first tile resolves) is
// left flat and untransformed; the others hold the variance
TEST(WaveCascades, ABandWithoutWavesIsLeftFlat)
{
    WaveCascades w(lakeBreeze());
    w.update(2.0);
    ASSERT_FALSE(w.holdsWaves(0)); // 5 m/s over 140 m: nothing longer than 2.7 m to speak of
    for (const WaveCascades::Texel& t : w.texels(0)) ASSERT_EQ(t.displacement.z(), 0.0f);
    for (unsigned int c = 1; c < w.bands().size(); ++c) EXPECT_TRUE(w.holdsWaves(c)) << c;
    EXPECT_LT(WaveCascades::bandVariance(lakeBreeze().sea, { w.bands()[0] }), 1e-6 * w.binVariance());
}

TEST(WaveCascades, TheRealisedVarianceIsTheSpectrumsIntegral)
{
    for (WaveCascades::Params p : { lakeBreeze(), freshWind() }) {
        const double expected = WaveCascades::bandVariance(p.sea, WaveCascades::chooseBands(p.sea, p.extent, p.size));
        ASSERT_GT(expected, 0.0);
        double realised = 0.0;
        const int seeds = 8;
        for (int seed = 1; seed <= seeds; ++seed) {
            p.seed = seed;
            WaveCascades w(p);
            // the grid of bins holds the spectrum's integral (the bands' rings on a square lattice)
            EXPECT_NEAR(w.binVariance(), expected, 0.03 * expected) << "seed " << seed;
            w.update(7.0 * seed);
            realised += realisedVariance(w) / seeds;
        }
        EXPECT_NEAR(realised, expected, 0.05 * expected) << p.sea.windSpeed << " m/s";
    }
}

TEST(WaveCascades, NothingRepeatsInsideTheWater)
{
    for (const WaveCascades::Params& p : { lakeBreeze(), freshWind() }) {
        WaveCascades w(p);
        w.update(11.0);
        std::mt19937 engine(5);
        std::uniform_real_distribution<double> across(-0.5 * p.extent, 0.5 * p.extent);
        std::vector<osg::Vec2d> points(1500);
        for (osg::Vec2d& q : points) q.set(across(engine), across(engine));
        // repeats of every cascade's tile from 20 m to the water's size, in x, y and both (up to
        // 300 of each, at random, where a short tile repeats thousands of times)
        std::vector<osg::Vec2d> shifts;
        for (const CascadeBand& b : w.bands()) {
            std::vector<osg::Vec2d> repeats;
            for (int m = 0; m * b.tile <= p.extent; ++m)
                for (int n = -int(p.extent / b.tile); n * b.tile <= p.extent; ++n) {
                    const osg::Vec2d s(m * b.tile, n * b.tile);
                    if (s.length() >= 20.0 && s.length() <= p.extent) repeats.push_back(s);
                }
            std::shuffle(repeats.begin(), repeats.end(), engine);
            shifts.insert(shifts.end(), repeats.begin(), repeats.begin() + std::min<size_t>(repeats.size(), 300));
        }
        // and shifts at random
        std::uniform_real_distribution<double> angle(0.0, 2.0 * osg::PI), distance(20.0, p.extent);
        for (int k = 0; k < 200; ++k) {
            const double a = angle(engine), d = distance(engine);
            shifts.emplace_back(d * std::cos(a), d * std::sin(a));
        }
        double worst = 0.0;
        osg::Vec2d worstShift;
        for (const osg::Vec2d& s : shifts) {
            const double r = autocorrelation(w, s, points);
            if (r > worst) {
                worst = r;
                worstShift = s;
            }
        }
        EXPECT_LT(worst, 0.5) << "at a shift of (" << worstShift.x() << ", " << worstShift.y() << ") m, over " << shifts.size() << " shifts";
        // the slopes (the normals, seen close up) at each tile's first repeats, along x: no tile holds most of them
        for (const CascadeBand& b : w.bands())
            for (double s : { b.tile, 2.0 * b.tile }) {
                if (s < 1.0 || s > p.extent) continue;
                double ab = 0.0, aa = 0.0, bb = 0.0;
                for (const osg::Vec2d& q : points) {
                    const double a = w.sample(q.x(), q.y()).slope.x(), c = w.sample(q.x() + s, q.y()).slope.x();
                    ab += a * c;
                    aa += a * a;
                    bb += c * c;
                }
                EXPECT_LT(ab / std::sqrt(aa * bb), 0.6) << "the slopes at a shift of " << s << " m";
            }
    }
}

TEST(WaveCascades, TheFiftyStrongestBinsOfAWindowHoldLittleOfItsVariance)
{
    // the height query over a 128 m window, 1024^2 samples, and its 2D spectrum
    WaveCascades w(lakeBreeze());
    w.update(3.0);
    const int n = 1024;
    const double window = 128.0;
    fftwf_complex* field = fftwf_alloc_complex(size_t(n) * n);
    double mean = 0.0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const double h = w.height((i + 0.5) * window / n - 0.5 * window, (j + 0.5) * window / n - 0.5 * window);
            field[j * n + i][0] = float(h);
            field[j * n + i][1] = 0.0f;
            mean += h / (double(n) * n);
        }
    for (int k = 0; k < n * n; ++k) field[k][0] -= float(mean);
    fftwf_plan plan = fftwf_plan_dft_2d(n, n, field, field, FFTW_FORWARD, FFTW_ESTIMATE);
    fftwf_execute(plan);
    std::vector<double> power(size_t(n) * n);
    double total = 0.0;
    for (int k = 0; k < n * n; ++k) total += power[k] = double(field[k][0]) * field[k][0] + double(field[k][1]) * field[k][1];
    fftwf_destroy_plan(plan);
    fftwf_free(field);
    std::partial_sort(power.begin(), power.begin() + 50, power.end(), std::greater<double>());
    double strongest = 0.0;
    for (int k = 0; k < 50; ++k) strongest += power[k];
    ASSERT_GT(total, 0.0);
    EXPECT_LE(strongest / total, 0.40);
}

TEST(WaveCascades, TheHeightQueryMeetsTheChoppySurface)
{
    WaveCascades::Params p = freshWind();
    p.choppiness = 1.0;
    WaveCascades w(p);
    w.update(20.0);
    std::mt19937 engine(9);
    std::uniform_real_distribution<double> across(-100.0, 100.0);
    double moved = 0.0;
    for (int k = 0; k < 500; ++k) {
        // the undisplaced point q lands at q + D(q), at the height h(q)
        const double qx = across(engine), qy = across(engine);
        const WaveCascades::Texel at = w.sample(qx, qy);
        const double x = qx + at.displacement.x(), y = qy + at.displacement.y();
        moved = std::max(moved, std::hypot(double(at.displacement.x()), double(at.displacement.y())));
        EXPECT_NEAR(w.height(x, y), at.displacement.z(), 1e-6) << "over (" << x << ", " << y << ")";
    }
    EXPECT_GT(moved, 0.1); // the waves do move the surface sideways, by more than the tolerance
}

// The choppy surface's normal is its tangents' cross product: the displaced point
// (q + D(q), h(q)) differenced along q from the direct sums, against the slopes the texels'
// derivatives give (displacedSlope) and the height query's normal over the displaced point
TEST(WaveCascades, TheChoppyNormalIsTheDisplacedSurfacesTangentsCross)
{
    WaveCascades::Params p = freshWind();
    p.size = 32; // direct sums over every bin
    p.choppiness = 1.0;
    WaveCascades w(p);
    w.update(7.0);
    auto displaced = [&w](double x, double y) {
        const WaveCascades::Texel t = w.directSum(x, y);
        return osg::Vec3d(x + t.displacement.x(), y + t.displacement.y(), t.displacement.z());
    };
    std::mt19937 engine(5);
    std::uniform_real_distribution<double> across(-200.0, 200.0);
    // m: a fiftieth of a radian of the shortest wave held (about 5 cm), so the central differences'
    // own error, (k e)^2 / 6 of a slope, stays under 1e-4, and the float sums' rounding over 2e too
    const double e = 2e-4;
    double worst = 0.0, tilted = 0.0;
    int tested = 0;
    for (int k = 0; k < 200; ++k) {
        const double x = across(engine), y = across(engine);
        const WaveCascades::Texel t = w.directSum(x, y);
        const double stretch = (1.0 + t.jacobian.x()) * (1.0 + t.jacobian.y()) - double(t.jacobian.z()) * t.jacobian.z();
        if (stretch < 2.0 * WaveCascades::MIN_STRETCH) continue; // near a fold, where the slopes are clamped
        ++tested;
        osg::Vec3d n = (displaced(x + e, y) - displaced(x - e, y)) ^ (displaced(x, y + e) - displaced(x, y - e));
        n.normalize();
        const osg::Vec2d slope = t.displacedSlope();
        osg::Vec3d fromTexel(-slope.x(), -slope.y(), 1.0);
        fromTexel.normalize();
        worst = std::max(worst, (n - fromTexel).length());
        tilted = std::max(tilted, (n - osg::Vec3d(osg::Vec3d(-t.slope.x(), -t.slope.y(), 1.0) / osg::Vec3d(-t.slope.x(), -t.slope.y(), 1.0).length())).length());
    }
    ASSERT_GT(tested, 150);
    std::cout << tested << " points: the texels' normal " << worst << " from the differenced one, the undisplaced slopes' "
              << tilted << "\n";
    EXPECT_LT(worst, 1e-3);
    EXPECT_GT(tilted, 1e-2); // the undisplaced slopes are not the displaced surface's

    // the query's normal over a displaced point is the texel's there (sampled, not summed)
    for (int k = 0; k < 50; ++k) {
        const double qx = across(engine), qy = across(engine);
        const WaveCascades::Texel at = w.sample(qx, qy);
        const osg::Vec2d slope = at.displacedSlope();
        osg::Vec3d expected(-slope.x(), -slope.y(), 1.0);
        expected.normalize();
        const osg::Vec3d n = w.normal(qx + at.displacement.x(), qy + at.displacement.y());
        EXPECT_LT((n - expected).length(), 1e-4) << qx << ", " << qy;
    }
}

// The bounds the shaders and the queries step by hold for the choppy surface: its slopes stay under
// six deviations of the tiles' (the steepest lie mid-flank, where the displacement hardly squeezes
// the water), the displacement's derivatives under six of theirs
TEST(WaveCascades, TheChoppySurfacesSlopesAndSqueezeStayInsideTheirBounds)
{
    for (double wind : { 2.0, 5.0, 10.0 }) {
        WaveCascades::Params p = lakeBreeze();
        p.sea.windSpeed = wind;
        p.choppiness = 1.0;
        WaveCascades w(p);
        w.update(5.0);
        const double slopeBound = 6.0 * std::sqrt(w.binSlopeVariance()), stretchBound = 6.0 * std::sqrt(w.binStretchVariance());
        std::mt19937 engine(11);
        std::uniform_real_distribution<double> across(-70.0, 70.0);
        double steepest = 0.0, squeezed = 0.0;
        for (int k = 0; k < 50000; ++k) {
            const WaveCascades::Texel t = w.sample(across(engine), across(engine));
            steepest = std::max(steepest, t.displacedSlope().length());
            for (int f = 0; f < 3; ++f) squeezed = std::max(squeezed, double(std::fabs(t.jacobian[f])));
        }
        std::cout << wind << " m/s: steepest " << steepest << " of " << slopeBound << ", most squeezed " << squeezed << " of "
                  << stretchBound << "\n";
        EXPECT_LT(steepest, slopeBound) << wind;
        EXPECT_LT(squeezed, stretchBound) << wind;
        EXPECT_GT(squeezed, 0.1 * stretchBound) << wind; // the derivatives are there
    }
}

TEST(WaveCascades, TheSameSeedGivesTheSameSeaAndAnotherADifferentOne)
{
    WaveCascades a(lakeBreeze()), b(lakeBreeze());
    WaveCascades::Params other = lakeBreeze();
    other.seed = 2;
    WaveCascades c(other);
    for (WaveCascades* w : { &a, &b, &c }) w->update(4.5);
    EXPECT_EQ(a.height(3.0, -7.0), b.height(3.0, -7.0));
    EXPECT_NE(a.height(3.0, -7.0), c.height(3.0, -7.0));
}

TEST(WaveCascades, BadParametersGiveAFlatOrFiniteSea)
{
    // no wind, no fetch, no water: no bands and a flat surface
    for (int bad = 0; bad < 4; ++bad) {
        WaveCascades::Params p = lakeBreeze();
        if (bad == 0) p.sea.windSpeed = 0.0;
        if (bad == 1) p.sea.fetch = 0.0;
        if (bad == 2) p.sea.depth = 0.0;
        if (bad == 3) p.sea.windSpeed = std::nan("");
        WaveCascades w(p);
        EXPECT_TRUE(w.bands().empty()) << bad;
        w.update(1.0);
        EXPECT_EQ(w.height(1.0, 2.0), 0.0) << bad;
        EXPECT_EQ(w.normal(1.0, 2.0), osg::Vec3d(0.0, 0.0, 1.0)) << bad;
    }
    // a huge fetch, shallow water, a tiny extent, a non-finite query: finite everywhere
    WaveCascades::Params p = freshWind();
    p.sea.fetch = 1.0e9;
    p.sea.depth = 0.3;
    p.extent = 1.0e-3;
    p.choppiness = 1.0;
    WaveCascades w(p);
    w.update(1.0e9);
    for (double x : { 0.0, 17.3, -1.0e6 }) {
        EXPECT_TRUE(std::isfinite(w.height(x, 2.0))) << x;
        const osg::Vec3d n = w.normal(x, 2.0);
        EXPECT_TRUE(std::isfinite(n.x()) && std::isfinite(n.y()) && n.z() > 0.0) << x;
    }
    EXPECT_EQ(w.height(std::nan(""), std::numeric_limits<double>::infinity()), 0.0);
    EXPECT_EQ(w.normal(std::nan(""), 1.0), osg::Vec3d(0.0, 0.0, 1.0));
}
