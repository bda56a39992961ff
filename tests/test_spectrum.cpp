// The physics of wind waves (surface/Spectrum) against closed forms: dispersion in its deep,
// shallow and capillary limits, JONSWAP's parameters, peak and integral, TMA's depth factor, the
// directional spreading's normalisation and mean cosine, and the wavenumber spectrum's integral.
// No GPU.
#include "surface/Spectrum.h"
#include <gtest/gtest.h>
#include <osg/Math>
#include <cmath>

using namespace osgWater::spectrum;

namespace {
const double kPi = osg::PI;

// the trapezoid rule on [a, b] with n panels
template <class F> double integrate(F f, double a, double b, int n)
{
    const double h = (b - a) / n;
    double s = 0.5 * (f(a) + f(b));
    for (int i = 1; i < n; ++i) s += f(a + i * h);
    return s * h;
}
}

TEST(Spectrum, DispersionMeetsItsDeepShallowAndCapillaryLimits)
{
    // deep gravity wave: omega^2 = g k (+ the tension's 7.4e-5 k^3)
    EXPECT_NEAR(angularFrequency(1.0, kDeep), 3.1321037658, 1e-9);
    // shallow water, k h = 0.02: omega = k sqrt(g h) within 1e-4 of the tanh
    EXPECT_NEAR(angularFrequency(0.01, 2.0), 0.0442915166, 1e-9);
    EXPECT_NEAR(angularFrequency(0.01, 2.0), 0.01 * std::sqrt(kGravity * 2.0), 1e-5);
    // a capillary ripple, 6 mm long: the tension dominates, omega^2 = g k + (sigma/rho) k^3
    EXPECT_NEAR(angularFrequency(1000.0, kDeep), 289.4995682, 1e-6);
    // the inverse, and the group velocity as the derivative (central differences)
    for (double depth : { 0.5, 3.0, kDeep })
        for (double k : { 0.05, 0.7, 12.0, 400.0 }) {
            const double w = angularFrequency(k, depth);
            EXPECT_NEAR(wavenumber(w, depth), k, 1e-9 * k) << k << " at " << depth << " m";
            const double dk = 1e-6 * k;
            EXPECT_NEAR(groupVelocity(k, depth), (angularFrequency(k + dk, depth) - angularFrequency(k - dk, depth)) / (2 * dk),
                        1e-6 * groupVelocity(k, depth)) << k << " at " << depth << " m";
        }
    // deep gravity waves: the group travels at half the phase speed
    EXPECT_NEAR(groupVelocity(0.1, kDeep), 0.5 * angularFrequency(0.1, kDeep) / 0.1, 1e-3);
    EXPECT_EQ(angularFrequency(0.0, 1.0), 0.0);
    EXPECT_EQ(angularFrequency(1.0, 0.0), 0.0);
    EXPECT_EQ(wavenumber(-1.0, 1.0), 0.0);
}

TEST(Spectrum, JonswapHasHasselmannsParametersPeakAndIntegral)
{
    // a 10 m/s wind over 100 km: alpha = 0.076 (U^2/(F g))^0.22, omega_p = 22 (g^2/(U F))^(1/3)
    const Jonswap j = jonswap(10.0, 1.0e5);
    EXPECT_NEAR(j.alpha, 0.0100611219, 1e-9);
    EXPECT_NEAR(j.peakOmega, 1.0081736733, 1e-9);
    EXPECT_DOUBLE_EQ(j.gamma, 3.3);
    // at the peak: alpha g^2 omega_p^-5 e^(-5/4) gamma
    EXPECT_NEAR(jonswapSpectrum(j.peakOmega, j), 0.8789284065, 1e-8);
    // the peak is the maximum
    EXPECT_GT(jonswapSpectrum(j.peakOmega, j), jonswapSpectrum(0.97 * j.peakOmega, j));
    EXPECT_GT(jonswapSpectrum(j.peakOmega, j), jonswapSpectrum(1.03 * j.peakOmega, j));
    // with gamma 1 it is Pierson-Moskowitz's form, whose integral is alpha g^2 / (5 omega_p^4)
    Jonswap pm = j;
    pm.gamma = 1.0;
    const double variance = integrate([&](double w) { return jonswapSpectrum(w, pm); }, 0.05, 60.0, 200000);
    EXPECT_NEAR(variance, 0.1874446336, 1e-4 * 0.1874446336);
    // no wind, no fetch, NaN: no waves
    EXPECT_EQ(jonswap(0.0, 1000.0).alpha, 0.0);
    EXPECT_EQ(jonswap(5.0, 0.0).alpha, 0.0);
    EXPECT_EQ(jonswap(NAN, 1000.0).alpha, 0.0);
    EXPECT_EQ(jonswapSpectrum(1.0, jonswap(0.0, 1.0)), 0.0);
}

TEST(Spectrum, TmaFactorFollowsKitaigorodskiisThreePieces)
{
    // omega_h = omega sqrt(h / g): h = g makes omega_h = omega
    EXPECT_NEAR(tmaFactor(0.5, kGravity), 0.125, 1e-12);
    EXPECT_NEAR(tmaFactor(1.0, kGravity), 0.5, 1e-12);
    EXPECT_NEAR(tmaFactor(1.5, kGravity), 0.875, 1e-12);
    EXPECT_NEAR(tmaFactor(2.0, kGravity), 1.0, 1e-12);
    EXPECT_EQ(tmaFactor(3.0, kGravity), 1.0);
    EXPECT_EQ(tmaFactor(0.1, kDeep), 1.0);
    EXPECT_EQ(tmaFactor(1.0, 0.0), 0.0);
}

TEST(Spectrum, DirectionalSpreadIsNormalisedWithMeanCosineSOverSPlusOne)
{
    for (double s : { 0.0, 0.1, 1.0, 4.5, 30.0, 300.0 }) {
        const double total = integrate([&](double t) { return directionalSpread(t, s); }, -kPi, kPi, 20000);
        const double mean = integrate([&](double t) { return std::cos(t) * directionalSpread(t, s); }, -kPi, kPi, 20000);
        // tolerance: the trapezoid rule's error at the cusp |theta - pi|^(2s) upwind (7e-6 at s = 0.1)
        EXPECT_NEAR(total, 1.0, 2e-5) << "s " << s;
        EXPECT_NEAR(mean, meanCosine(s), 2e-5) << "s " << s;
    }
    EXPECT_NEAR(meanCosine(1.0), 0.5, 1e-15);
    // the spreading narrows away from the peak, and the swell narrows it further
    const double wp = 1.0, U = 10.0;
    const double sp = 11.5 * std::pow(kGravity / (wp * U), 2.5);
    EXPECT_NEAR(spreadExponent(wp, wp, U, 0.0), sp, 1e-12);
    EXPECT_NEAR(spreadExponent(0.5 * wp, wp, U, 0.0), sp * std::pow(0.5, 5.0), 1e-12);
    EXPECT_NEAR(spreadExponent(2.0 * wp, wp, U, 0.0), sp * std::pow(2.0, -2.5), 1e-12);
    EXPECT_NEAR(spreadExponent(wp, wp, U, 1.0), sp + 16.0 * std::tanh(1.0), 1e-12);
}

TEST(Spectrum, TheWavenumberSpectrumIntegratesToTheFrequencySpectrumsVariance)
{
    // over the plane of wavenumber vectors, S(k) integrates to the integral of S(omega) TMA(omega):
    // the Jacobian d omega/dk / k and the normalised spreading carry the variance over exactly
    for (double depth : { kDeep, 2.0 }) {
        WindSea sea;
        sea.windSpeed = 6.0;
        sea.fetch = 2000.0;
        sea.depth = depth;
        sea.windDirection = 0.7;
        const Jonswap j = jonswap(sea.windSpeed, sea.fetch);
        const double expected = integrate([&](double w) { return jonswapSpectrum(w, j) * tmaFactor(w, depth); }, 0.2, 60.0, 100000);
        // polar, over log k (the peak is narrow): the same band of frequencies, every direction
        const double got = integrate([&](double u) {
            const double k = std::exp(u);
            return k * k * integrate([&](double t) { return wavenumberSpectrum(k * std::cos(t), k * std::sin(t), sea); }, -kPi, kPi, 360);
        }, std::log(wavenumber(0.2, depth)), std::log(wavenumber(60.0, depth)), 4000);
        EXPECT_NEAR(got, expected, 1e-3 * expected) << "depth " << depth;
        // downwind holds more than upwind
        const double k = wavenumber(j.peakOmega, depth);
        EXPECT_GT(wavenumberSpectrum(k * std::cos(0.7), k * std::sin(0.7), sea),
                  10.0 * wavenumberSpectrum(-k * std::cos(0.7), -k * std::sin(0.7), sea));
    }
    EXPECT_EQ(wavenumberSpectrum(0.0, 0.0, WindSea()), 0.0);
}
