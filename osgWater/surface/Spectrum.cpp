#include "surface/Spectrum.h"
#include <osg/Math>
#include <algorithm>
#include <cmath>

using namespace osgWater;

namespace {

// (g k + (sigma/rho) k^3) tanh(k h) = omega^2, and its derivative in k
double omegaSquared(double k, double depth)
{
    return (spectrum::kGravity * k + spectrum::kTensionOverDensity * k * k * k) * std::tanh(k * depth);
}

double omegaSquaredSlope(double k, double depth)
{
    const double kh = k * depth;
    const double sech = kh > 20.0 ? 0.0 : 1.0 / std::cosh(kh); // cosh overflows long before it matters
    return (spectrum::kGravity + 3.0 * spectrum::kTensionOverDensity * k * k) * std::tanh(kh)
           + (spectrum::kGravity * k + spectrum::kTensionOverDensity * k * k * k) * depth * sech * sech;
}

}

double spectrum::angularFrequency(double k, double depth)
{
    if (!(k > 0.0) || !(depth > 0.0)) return 0.0;
    return std::sqrt(omegaSquared(k, depth));
}

double spectrum::groupVelocity(double k, double depth)
{
    const double w = angularFrequency(k, depth);
    return w > 0.0 ? omegaSquaredSlope(k, depth) / (2.0 * w) : 0.0;
}

double spectrum::wavenumber(double omega, double depth)
{
    if (!(omega > 0.0) || !(depth > 0.0)) return 0.0;
    // deep gravity waves first, or shallow water's omega = k sqrt(g h) where that is the larger k
    double k = std::max(omega * omega / kGravity, omega / std::sqrt(kGravity * std::min(depth, 1.0e6)));
    for (int i = 0; i < 50; ++i) {
        const double f = omegaSquared(k, depth) - omega * omega, slope = omegaSquaredSlope(k, depth);
        if (!(slope > 0.0)) break;
        const double next = std::max(k - f / slope, 0.5 * k); // omega^2 is convex in k: no overshoot below
        if (std::fabs(next - k) <= 1e-14 * k) return next;
        k = next;
    }
    return k;
}

spectrum::Jonswap spectrum::jonswap(double windSpeed, double fetch)
{
    Jonswap j;
    if (!(windSpeed > 0.0) || !(fetch > 0.0) || !std::isfinite(windSpeed) || !std::isfinite(fetch)) return j;
    j.alpha = 0.076 * std::pow(windSpeed * windSpeed / (fetch * kGravity), 0.22);
    j.peakOmega = 22.0 * std::cbrt(kGravity * kGravity / (windSpeed * fetch));
    return j;
}

double spectrum::coxMunkSlopeVariance(double windSpeed)
{
    if (!(windSpeed > 0.0) || !std::isfinite(windSpeed)) return 0.0;
    return 0.003 + 0.00512 * windSpeed;
}

double spectrum::jonswapSpectrum(double omega, const Jonswap& j)
{
    if (!(omega > 0.0) || !(j.alpha > 0.0) || !(j.peakOmega > 0.0)) return 0.0;
    const double ratio = j.peakOmega / omega;
    const double sigma = omega <= j.peakOmega ? 0.07 : 0.09;
    const double d = (omega - j.peakOmega) / (sigma * j.peakOmega);
    const double r = std::exp(-0.5 * d * d);
    return j.alpha * kGravity * kGravity / std::pow(omega, 5.0) * std::exp(-1.25 * std::pow(ratio, 4.0))
           * std::pow(j.gamma, r);
}

double spectrum::tmaFactor(double omega, double depth)
{
    if (!(depth > 0.0) || !(omega > 0.0)) return 0.0;
    const double wh = omega * std::sqrt(std::min(depth, kDeep) / kGravity);
    if (wh <= 1.0) return 0.5 * wh * wh;
    if (wh <= 2.0) return 1.0 - 0.5 * (2.0 - wh) * (2.0 - wh);
    return 1.0;
}

double spectrum::spreadExponent(double omega, double peakOmega, double windSpeed, double swell)
{
    if (!(omega > 0.0) || !(peakOmega > 0.0) || !(windSpeed > 0.0)) return 0.0;
    const double sp = 11.5 * std::pow(kGravity / (peakOmega * windSpeed), 2.5);
    const double ratio = omega / peakOmega;
    const double s = ratio <= 1.0 ? sp * std::pow(ratio, 5.0) : sp * std::pow(ratio, -2.5);
    const double w = std::min(std::max(swell, 0.0), 1.0);
    return s + 16.0 * std::tanh(peakOmega / omega) * w * w;
}

double spectrum::directionalSpread(double theta, double s)
{
    s = std::max(s, 0.0);
    // Q(s) = 2^(2s - 1) Gamma(s + 1)^2 / (pi Gamma(2s + 1)), through logarithms: s reaches hundreds
    const double logQ = (2.0 * s - 1.0) * std::log(2.0) + 2.0 * std::lgamma(s + 1.0) - std::log(osg::PI) - std::lgamma(2.0 * s + 1.0);
    const double c = std::fabs(std::cos(0.5 * theta));
    if (c <= 0.0) return s > 0.0 ? 0.0 : std::exp(logQ);
    return std::exp(logQ + 2.0 * s * std::log(c));
}

double spectrum::meanCosine(double s)
{
    s = std::max(s, 0.0);
    return s / (s + 1.0);
}

double spectrum::wavenumberSpectrum(double kx, double ky, const WindSea& sea)
{
    const double k = std::hypot(kx, ky);
    if (!(k > 0.0)) return 0.0;
    const double omega = angularFrequency(k, sea.depth);
    const Jonswap j = jonswap(sea.windSpeed, sea.fetch);
    const double s = spreadExponent(omega, j.peakOmega, sea.windSpeed, sea.swell);
    const double blend = std::min(std::max(sea.spread, 0.0), 1.0);
    const double theta = std::atan2(ky, kx) - sea.windDirection;
    const double D = (1.0 - blend) * directionalSpread(theta, s) + blend / (2.0 * osg::PI);
    return jonswapSpectrum(omega, j) * tmaFactor(omega, sea.depth) * groupVelocity(k, sea.depth) * D / k;
}
