#include "surface/WaveCascades.h"
#include <fftw3.h>
#include <osg/Math>
#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <random>

using namespace osgWater;

namespace {

const double kTwoPi = 2.0 * osg::PI;
// how far a tile may shrink to keep its repeats apart from the other tiles'
const double kSmallestTileScale = 0.8;
// a cascade whose band holds less than this share of the variance is left flat (a millionth: a
// thousandth of the height)
const double kNegligibleShare = 1e-6;

// FFTW's planner is not re-entrant and measuring a plan takes a while: one plan per size for the
// process, made under a lock, executed in place on each surface's own (equally aligned) arrays.
fftwf_plan sharedPlan(unsigned int n)
{
    static std::mutex lock;
    static std::map<unsigned int, fftwf_plan> plans;
    std::lock_guard<std::mutex> guard(lock);
    auto found = plans.find(n);
    if (found != plans.end()) return found->second;
    fftwf_complex* field = fftwf_alloc_complex(size_t(n) * n);
    fftwf_plan plan = fftwf_plan_dft_2d(int(n), int(n), field, field, FFTW_BACKWARD, FFTW_MEASURE); // in place
    fftwf_free(field);
    plans[n] = plan;
    return plan;
}

// the wave's variance per unit wavenumber, every direction together: S(omega) TMA(omega) d omega/dk
double omnidirectional(double k, const spectrum::WindSea& sea, const spectrum::Jonswap& j)
{
    const double w = spectrum::angularFrequency(k, sea.depth);
    return spectrum::jonswapSpectrum(w, j) * spectrum::tmaFactor(w, sea.depth) * spectrum::groupVelocity(k, sea.depth);
}

// int_a^b of the omnidirectional spectrum, trapezoids in log k (the spectrum spans decades)
double integrate(double a, double b, const spectrum::WindSea& sea, const spectrum::Jonswap& j)
{
    if (!(b > a)) return 0.0;
    a = std::max(a, 1e-6 * b);
    const int n = 2000;
    const double step = std::log(b / a) / n;
    double sum = 0.0;
    for (int i = 0; i <= n; ++i) {
        const double k = a * std::exp(i * step);
        sum += (i == 0 || i == n ? 0.5 : 1.0) * omnidirectional(k, sea, j) * k; // dk = k dlog k
    }
    return sum * step;
}

// the wavenumber (rad/m) above which the spectrum's slopes, summed from its longest waves, exceed
// `total`: trapezoids in log k from a thousandth of the peak's wavenumber up to `top`; `top` if they
// never do
double slopesReach(double total, double top, const spectrum::WindSea& sea, const spectrum::Jonswap& j)
{
    const double from = 1e-3 * spectrum::wavenumber(j.peakOmega, sea.depth);
    if (!(from > 0.0) || !(top > from)) return top;
    const int n = 4000;
    const double step = std::log(top / from) / n;
    double held = 0.0, before = 0.0;
    for (int i = 0; i < n; ++i) {
        const double k0 = from * std::exp(i * step), k1 = from * std::exp((i + 1) * step);
        const double a = omnidirectional(k0, sea, j) * k0 * k0 * k0, b = omnidirectional(k1, sea, j) * k1 * k1 * k1;
        before = held;
        held += 0.5 * (a + b) * step; // k^2 F(k) dk = k^3 F(k) dlog k
        if (held >= total) return k0 * std::exp(step * (total - before) / (held - before));
    }
    return top;
}

// the tile whose texels give a wave of wavenumber k exactly SAMPLES_PER_WAVE samples
double tileFor(double kHigh, unsigned int size)
{
    return kTwoPi * size / (WaveCascades::SAMPLES_PER_WAVE * kHigh);
}

// the closest two tiles' repeats come to each other inside the extent: min |m a - n b|, m a and
// n b up to the extent (along each axis; a 2D repeat of both needs both components close)
double repeatGap(double a, double b, double extent)
{
    double gap = extent;
    for (double x = a; x <= extent; x += a) {
        const double n = std::max(1.0, std::round(x / b));
        if (n * b <= extent + b) gap = std::min(gap, std::fabs(x - n * b));
    }
    return gap;
}

}

struct WaveCascades::Plans {
    fftwf_plan plan = nullptr;
    fftwf_complex* fields[4] = { nullptr, nullptr, nullptr, nullptr }; // the packed transforms, in place
    ~Plans()
    {
        for (fftwf_complex* f : fields) fftwf_free(f);
    }
};

std::vector<CascadeBand> WaveCascades::chooseBands(const spectrum::WindSea& sea, double extent, unsigned int size)
{
    std::vector<CascadeBand> bands;
    const spectrum::Jonswap j = spectrum::jonswap(sea.windSpeed, sea.fetch);
    if (!(j.alpha > 0.0) || !(extent > 0.0) || !(sea.depth > 0.0)) return bands;
    const double peakK = spectrum::wavenumber(j.peakOmega, sea.depth);
    // a band's top over its bottom: its longest wave still fits twice in its tile once the tile
    // is shrunk to keep its repeats apart (below)
    const double maxRatio = kSmallestTileScale * size / (2.0 * SAMPLES_PER_WAVE);
    const double shortest = kTwoPi / shortestWave(sea);

    // the first: a tile larger than the water (and than a few peak waves), all it resolves
    CascadeBand first;
    first.tile = std::max(1.25 * extent, 4.0 * kTwoPi / peakK);
    first.kHigh = kTwoPi * size / (SAMPLES_PER_WAVE * first.tile);
    bands.push_back(first);

    // The cascades above it split what lies between it and the shortest wave into equal shares of
    // a measure that is half the height variance and half the slope variance, per log k: heights
    // crowd the peak, slopes spread to the shortest waves, and a tile that held most of either
    // would show its repeats (in the heights far off, in the normals close up).
    const double bottom = first.kHigh, top = std::max(shortest, 2.0 * bottom);
    const int steps = 4000;
    const double logStep = std::log(top / bottom) / steps;
    std::vector<double> heightPart(steps), slopePart(steps);
    double heights = 0.0, slopes = 0.0;
    for (int i = 0; i < steps; ++i) {
        const double k = bottom * std::exp((i + 0.5) * logStep);
        const double perLogK = omnidirectional(k, sea, j) * k;
        heights += heightPart[i] = perLogK * logStep;
        slopes += slopePart[i] = perLogK * k * k * logStep;
    }
    double low = bottom, held = 0.0;
    int i = 0;
    for (unsigned int c = 1; c < CASCADES && i < steps; ++c) {
        const double share = held + (1.0 - held) / (CASCADES - c); // an equal share of what is left
        double high = low;
        while (i < steps) {
            const double k1 = bottom * std::exp((i + 1) * logStep);
            if (k1 > low * maxRatio) break; // as far as this tile resolves
            if (heights > 0.0 && slopes > 0.0) held += 0.5 * (heightPart[i] / heights + slopePart[i] / slopes);
            high = k1;
            ++i;
            if (held >= share * (1.0 - 1e-12) && c + 1 < CASCADES) break;
        }
        if (!(high > low)) high = low * maxRatio; // never an empty band
        bands.push_back({ tileFor(high, size), low, high });
        low = high;
    }
    while (bands.size() < CASCADES) { // the shortest wave reached early: thin bands above it
        bands.push_back({ tileFor(low * 1.5, size), low, low * 1.5 });
        low *= 1.5;
    }

    // tiles that repeat inside the water: shrunk (more texels per wave, never fewer) until no two
    // repeat near each other inside it
    for (size_t c = 2; c < bands.size(); ++c) {
        if (bands[c].tile > extent) continue;
        double bestScale = 1.0, bestGap = -1.0;
        for (double scale = 1.0; scale >= kSmallestTileScale; scale -= 0.005) {
            double gap = extent;
            for (size_t o = 1; o < c; ++o)
                if (bands[o].tile <= extent) gap = std::min(gap, repeatGap(bands[o].tile, scale * bands[c].tile, extent));
            if (gap > bestGap + 1e-9) {
                bestGap = gap;
                bestScale = scale;
            }
        }
        bands[c].tile *= bestScale;
    }
    return bands;
}

double WaveCascades::shortestWave(const spectrum::WindSea& sea)
{
    const spectrum::Jonswap j = spectrum::jonswap(sea.windSpeed, sea.fetch);
    if (!(j.alpha > 0.0) || !(sea.depth > 0.0)) return 0.0;
    return kTwoPi / slopesReach(spectrum::coxMunkSlopeVariance(sea.windSpeed), kTwoPi / SHORTEST_WAVE, sea, j);
}

double WaveCascades::unresolvedSlopeVariance() const
{
    if (!(_binSlopeVariance > 0.0)) return 0.0;
    return std::max(spectrum::coxMunkSlopeVariance(_params.sea.windSpeed) - _binSlopeVariance, 0.0);
}

double WaveCascades::bandVariance(const spectrum::WindSea& sea, const std::vector<CascadeBand>& bands)
{
    const spectrum::Jonswap j = spectrum::jonswap(sea.windSpeed, sea.fetch);
    double v = 0.0;
    for (const CascadeBand& b : bands) v += integrate(std::max(b.kLow, 1e-4 * b.kHigh), b.kHigh, sea, j);
    return v;
}

WaveCascades::WaveCascades(const Params& params)
    : _params(params), _time(0.0), _binVariance(0.0), _binSlopeVariance(0.0), _binCurvatureVariance(0.0), _binStretchVariance{ 0.0, 0.0 }, _maxPhaseSpeed(0.0),
      _plans(new Plans)
{
    unsigned int n = 16;
    while (n < std::min(params.size, 1024u)) n *= 2;
    _params.size = n;
    _bands = chooseBands(_params.sea, _params.extent, n);
    const size_t count = size_t(n) * n;
    _plans->plan = sharedPlan(n);
    for (fftwf_complex*& f : _plans->fields) f = fftwf_alloc_complex(count);

    const int half = int(n / 2);
    auto indexOf = [n](int m, int l) { return unsigned(((l + int(n)) % int(n)) * int(n) + (m + int(n)) % int(n)); };
    std::vector<std::complex<float>> h0(count);
    const double total = bandVariance(_params.sea, _bands);
    const double top = _bands.empty() ? 0.0 : kTwoPi / shortestWave(_params.sea);
    for (size_t c = 0; c < _bands.size(); ++c) {
        Cascade cascade;
        cascade.band = _bands[c];
        cascade.texels.resize(count);
        // a band the spectrum leaves (nearly) empty, as a lake's longest waves, or one above the
        // shortest wave held (left over when the others reach it early: its slopes are roughness):
        // no bins, no transforms, flat texels; nothing reads it
        if (!(cascade.band.kLow < top * (1.0 - 1e-9)) || !(bandVariance(_params.sea, { cascade.band }) >= kNegligibleShare * total)) {
            _cascades.push_back(std::move(cascade));
            continue;
        }
        const double dk = kTwoPi / cascade.band.tile;
        // Box-Muller on the standard engine: the same draws wherever the kit runs
        std::mt19937 engine(_params.seed * 7919u + unsigned(c) * 104729u + 1u);
        auto uniform = [&engine]() { return (double(engine()) + 0.5) / 4294967296.0; };
        std::fill(h0.begin(), h0.end(), std::complex<float>(0.0f));
        std::vector<double> spectrumAt(count, 0.0);
        for (int l = -half + 1; l < half; ++l)
            for (int m = -half + 1; m < half; ++m) {
                const double kx = m * dk, ky = l * dk, k = std::hypot(kx, ky);
                const double r = std::sqrt(-2.0 * std::log(uniform())), a = kTwoPi * uniform();
                if (!(k >= cascade.band.kLow && k < cascade.band.kHigh && k > 0.0)) continue;
                const double s = spectrum::wavenumberSpectrum(kx, ky, _params.sea) * dk * dk;
                // E|h0|^2 = s / 2 (h(k) = h0(k) + conj(h0(-k)) then holds s on average); the
                // normal pair's |r e^ia|^2 averages 2
                const double amplitude = 0.5 * std::sqrt(s);
                h0[indexOf(m, l)] = std::complex<float>(float(amplitude * r * std::cos(a)), float(amplitude * r * std::sin(a)));
                spectrumAt[indexOf(m, l)] = s;
            }
        for (int l = -half + 1; l < half; ++l)
            for (int m = -half + 1; m < half; ++m) {
                const unsigned int i = indexOf(m, l), mirror = indexOf(-m, -l);
                if (h0[i] == 0.0f && h0[mirror] == 0.0f) continue;
                Bin bin;
                bin.index = i;
                bin.h0 = h0[i];
                bin.h0MinusConj = std::conj(h0[mirror]);
                bin.kx = float(m * dk);
                bin.ky = float(l * dk);
                bin.k = std::hypot(bin.kx, bin.ky);
                bin.omega = spectrum::angularFrequency(std::hypot(m * dk, l * dk), _params.sea.depth);
                cascade.bins.push_back(bin);
                _binVariance += spectrumAt[i];
                _binSlopeVariance += spectrumAt[i] * double(bin.k) * bin.k;
                _binCurvatureVariance += spectrumAt[i] * std::pow(double(bin.k), 4);
                const double chop2 = _params.choppiness * _params.choppiness;
                if (bin.k > 0.0f) {
                    _binStretchVariance[0] += chop2 * spectrumAt[i] * std::pow(double(bin.kx), 4) / (double(bin.k) * bin.k);
                    _binStretchVariance[1] += chop2 * spectrumAt[i] * std::pow(double(bin.ky), 4) / (double(bin.k) * bin.k);
                }
                if (bin.k > 0.0f) _maxPhaseSpeed = std::max(_maxPhaseSpeed, bin.omega / bin.k);
            }
        _cascades.push_back(std::move(cascade));
    }
    update(0.0);
}

WaveCascades::~WaveCascades() = default;

void WaveCascades::update(double t)
{
    _time = t;
    for (Cascade& c : _cascades) evaluate(c, t);
}

void WaveCascades::evaluate(Cascade& c, double t)
{
    if (c.bins.empty()) return; // flat, as made
    const size_t count = size_t(_params.size) * _params.size;
    const float chop = float(_params.choppiness);
    const int transforms = chop != 0.0f ? 4 : 2;
    float* f[4];
    for (int i = 0; i < 4; ++i) f[i] = reinterpret_cast<float*>(_plans->fields[i]);
    for (int i = 0; i < transforms; ++i) std::fill(f[i], f[i] + 2 * count, 0.0f);
    // Each field is real, so its spectrum is Hermitian; two of them go through one complex
    // transform as A + i B: (h, dh/dx), (dh/dy, Dx), (Dy, dDx/dx), (dDy/dy, dDx/dy). Written out
    // in real arithmetic: std::complex's products check for NaN and infinity, and cost more than
    // the FFTs.
    for (const Bin& bin : c.bins) {
        const float phase = float(std::fmod(bin.omega * t, kTwoPi)); // exact to double precision at any t
        const float cs = std::cos(phase), sn = std::sin(phase);
        // h = h0(k) e^-iwt + conj(h0(-k)) e^iwt
        const float hr = (bin.h0.real() + bin.h0MinusConj.real()) * cs + (bin.h0.imag() - bin.h0MinusConj.imag()) * sn;
        const float hi = (bin.h0.imag() + bin.h0MinusConj.imag()) * cs + (bin.h0MinusConj.real() - bin.h0.real()) * sn;
        float* a = f[0] + 2 * bin.index;
        a[0] = (1.0f - bin.kx) * hr; // h + i (i kx h)
        a[1] = (1.0f - bin.kx) * hi;
        const float towardsX = chop * bin.kx / bin.k, towardsY = chop * bin.ky / bin.k; // D = i k/|k| h, towards the crests
        float* b = f[1] + 2 * bin.index; // i ky h + i (i kx/|k| h chop)
        b[0] = -towardsX * hr - bin.ky * hi;
        b[1] = bin.ky * hr - towardsX * hi;
        if (transforms == 4) {
            // Dy = i ky/|k| h chop; dDx/dx = -chop kx^2/|k| h, dDy/dy = -chop ky^2/|k| h,
            // dDx/dy = -chop kx ky/|k| h: A + i B with i (c h) = c (-hi + i hr)
            const float xx = chop * bin.kx * bin.kx / bin.k, yy = chop * bin.ky * bin.ky / bin.k;
            const float xy = chop * bin.kx * bin.ky / bin.k;
            float* d = f[2] + 2 * bin.index; // Dy + i dDx/dx
            d[0] = (xx - towardsY) * hi;
            d[1] = (towardsY - xx) * hr;
            float* e = f[3] + 2 * bin.index; // dDy/dy + i dDx/dy
            e[0] = -yy * hr + xy * hi;
            e[1] = -yy * hi - xy * hr;
        }
    }
    for (int i = 0; i < transforms; ++i) fftwf_execute_dft(_plans->plan, _plans->fields[i], _plans->fields[i]);
    for (size_t i = 0; i < count; ++i) {
        Texel& texel = c.texels[i];
        texel.displacement.set(f[1][2 * i + 1], transforms == 4 ? f[2][2 * i] : 0.0f, f[0][2 * i], 0.0f);
        texel.slope.set(f[0][2 * i + 1], f[1][2 * i]);
        if (transforms == 4) texel.jacobian.set(f[2][2 * i + 1], f[3][2 * i], f[3][2 * i + 1]);
    }
}

WaveCascades::Corners WaveCascades::corners(const Cascade& c, double x, double y) const
{
    const unsigned int n = _params.size;
    const double fx = x / c.band.tile * n, fy = y / c.band.tile * n;
    const double ix = std::floor(fx), iy = std::floor(fy);
    const float wx = float(fx - ix), wy = float(fy - iy);
    // n is a power of two: the tile wraps by a mask (two's complement wraps negatives too),
    // not by divisions, which cost more than the rest of a cascade's sample
    const long long mask = n - 1;
    const long long x0 = static_cast<long long>(ix) & mask, y0 = static_cast<long long>(iy) & mask;
    const long long x1 = (x0 + 1) & mask, y1 = (y0 + 1) & mask;
    return Corners{ { &c.texels[y0 * n + x0], &c.texels[y0 * n + x1], &c.texels[y1 * n + x0], &c.texels[y1 * n + x1] },
                    { (1 - wx) * (1 - wy), wx * (1 - wy), (1 - wx) * wy, wx * wy } };
}

WaveCascades::Texel WaveCascades::sample(double x, double y) const
{
    Texel sum;
    for (const Cascade& c : _cascades) {
        if (c.bins.empty()) continue;
        const Corners q = corners(c, x, y);
        for (int i = 0; i < 4; ++i) {
            const Texel& t = *q.texel[i];
            const float w = q.weight[i];
            sum.displacement += t.displacement * w;
            sum.slope += t.slope * w;
            if (_params.choppiness != 0.0) sum.jacobian += t.jacobian * w; // else zero: the height query's hot path skips it
        }
    }
    return sum;
}

double WaveCascades::subTexelSlopeVariance(double x, double y) const
{
    if (!std::isfinite(x) || !std::isfinite(y)) return 0.0;
    // the undisplaced point the water over (x, y) came from: (x, y) itself without chop, where a
    // sample of every cascade would only say so
    osg::Vec2d source(x, y);
    if (_params.choppiness != 0.0) over(x, y, &source);
    double v = 0.0;
    for (const Cascade& c : _cascades) {
        if (c.bins.empty()) continue;
        const Corners q = corners(c, source.x(), source.y());
        osg::Vec2d mean;
        double meanSquare = 0.0;
        for (int i = 0; i < 4; ++i) {
            const osg::Vec2d s(q.texel[i]->slope.x(), q.texel[i]->slope.y());
            mean += s * q.weight[i];
            meanSquare += s.length2() * q.weight[i];
        }
        v += std::max(meanSquare - mean.length2(), 0.0);
    }
    return v;
}

WaveCascades::Texel WaveCascades::directSum(double x, double y, int only) const
{
    double h = 0.0, dx = 0.0, dy = 0.0, sx = 0.0, sy = 0.0, xx = 0.0, yy = 0.0, xy = 0.0;
    for (size_t c = 0; c < _cascades.size(); ++c) {
        if (only >= 0 && size_t(only) != c) continue;
        for (const Bin& bin : _cascades[c].bins) {
            const double phase = bin.omega * _time;
            const std::complex<double> e(std::cos(phase), -std::sin(phase));
            const std::complex<double> hk = std::complex<double>(bin.h0) * e + std::complex<double>(bin.h0MinusConj) * std::conj(e);
            const double kx = bin.kx, ky = bin.ky, along = kx * x + ky * y;
            const std::complex<double> wave = hk * std::complex<double>(std::cos(along), std::sin(along));
            h += wave.real();
            sx -= kx * wave.imag(); // Re(i k h e^ikx)
            sy -= ky * wave.imag();
            dx -= kx / bin.k * wave.imag() * _params.choppiness; // Re(i k/|k| h e^ikx): towards the crests, as Gerstner's
            dy -= ky / bin.k * wave.imag() * _params.choppiness;
            const double chopOverK = _params.choppiness / bin.k * wave.real(); // Re(i k_j i k_i/|k| h e^ikx)
            xx -= kx * kx * chopOverK;
            yy -= ky * ky * chopOverK;
            xy -= kx * ky * chopOverK;
        }
    }
    Texel t;
    t.displacement.set(float(dx), float(dy), float(h), 0.0f);
    t.slope.set(float(sx), float(sy));
    t.jacobian.set(float(xx), float(yy), float(xy));
    return t;
}

WaveCascades::Texel WaveCascades::over(double x, double y, osg::Vec2d* source) const
{
    double qx = x, qy = y;
    Texel s = sample(qx, qy);
    if (source) source->set(qx, qy);
    if (_params.choppiness == 0.0) return s;
    // the undisplaced point q whose displaced place q + D(q) is (x, y): Newton's steps on the
    // residual r = q + D(q) - (x, y) with the sampled Jacobian J = I + grad D (symmetric), three or
    // four samples where the plain fixed point q = (x, y) - D(q) took a dozen; where the crests
    // squeeze J towards singular, the fixed point's step, which the bound on the stretch keeps
    // contracting
    for (int i = 0; i < 32; ++i) {
        const double rx = qx + s.displacement.x() - x, ry = qy + s.displacement.y() - y;
        if (std::fabs(rx) + std::fabs(ry) < 1e-7) break;
        const double xx = 1.0 + s.jacobian.x(), yy = 1.0 + s.jacobian.y(), xy = s.jacobian.z();
        const double det = xx * yy - xy * xy;
        if (det > 0.5) {
            qx -= (yy * rx - xy * ry) / det;
            qy -= (xx * ry - xy * rx) / det;
        } else {
            qx -= rx;
            qy -= ry;
        }
        s = sample(qx, qy);
    }
    if (source) source->set(qx, qy);
    return s;
}

double WaveCascades::height(double x, double y) const
{
    if (!std::isfinite(x) || !std::isfinite(y)) return 0.0;
    return over(x, y).displacement.z();
}

osg::Vec2d WaveCascades::Texel::displacedSlope() const
{
    // the tangents' cross product is (J^-1 grad h) det J in x and y and det J in z, with J the
    // (symmetric) Jacobian I + grad D: the slopes are J^-1 grad h, its inverse the adjugate / det
    const double xx = 1.0 + jacobian.x(), yy = 1.0 + jacobian.y(), xy = jacobian.z();
    const double det = std::max(xx * yy - xy * xy, MIN_STRETCH);
    return osg::Vec2d(yy * slope.x() - xy * slope.y(), xx * slope.y() - xy * slope.x()) / det;
}

osg::Vec3d WaveCascades::normal(double x, double y) const
{
    if (!std::isfinite(x) || !std::isfinite(y)) return osg::Vec3d(0.0, 0.0, 1.0);
    const osg::Vec2d slope = over(x, y).displacedSlope();
    osg::Vec3d n(-slope.x(), -slope.y(), 1.0);
    n.normalize();
    return n;
}
