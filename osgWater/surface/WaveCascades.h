/* osgWater - natural water for OpenSceneGraph */
#ifndef OSGWATER_WAVECASCADES
#define OSGWATER_WAVECASCADES 1

#include "surface/Spectrum.h"
#include <osgWater/Export>
#include <osg/Vec2f>
#include <osg/Vec3d>
#include <osg/Vec4f>
#include <algorithm>
#include <complex>
#include <memory>
#include <vector>

namespace osgWater {

//! One cascade's share of the spectrum: a square tile of side `tile` metres sampled `size` x `size`
//! times, holding the wavenumbers kLow <= |k| < kHigh.
struct CascadeBand {
    double tile = 0.0, kLow = 0.0, kHigh = 0.0;
};

//! A wind sea realised by FFT cascades (Tessendorf's synthesis): each cascade owns one band of
//! wavenumbers and is a periodic tile of heights, horizontal displacements and slopes, evaluated at
//! any time t with FFTW (float plans made once per size and shared). Nothing loops in time: every
//! bin keeps its own omega from the dispersion, and omega t is reduced in double precision.
//!
//! The bands are chosen against repetition inside the water's extent. The first cascade's tile is
//! larger than the extent, so it never repeats inside it. The others split the rest, up to
//! the shortest wave held (shortestWave), into equal shares of half the height variance plus half the slope variance, each a
//! tile of its own size, so no one tile's repeat holds most of the heights (seen far off) or of the
//! slopes (seen close up); the tiles are nudged apart until no two repeat together inside the
//! extent. Every band's shortest wave spans at least SAMPLES_PER_WAVE texels, so bilinear filtering
//! (the shader's, and the height query's, which mirrors it) keeps it.
class OSGWATER_EXPORT WaveCascades
{
public:
    static constexpr unsigned int CASCADES = 5;
    static constexpr double SAMPLES_PER_WAVE = 4.0;
    //! Metres: the shortest wave the cascades may hold (capillaries; see shortestWave).
    static constexpr double SHORTEST_WAVE = 0.02;

    struct Params {
        spectrum::WindSea sea;
        double extent = 100.0;      //!< m: the side of the square the water covers
        unsigned int size = 256;    //!< samples per tile side (a power of two, 16..1024)
        double choppiness = 0.0;    //!< horizontal displacement scale: 0 none, 1 Tessendorf's full
        unsigned int seed = 1;
    };

    //! One texel: the displacement (x, y, and the height), the slopes dh/dx, dh/dy of the
    //! undisplaced surface there, and the horizontal displacement's derivatives (zero without
    //! choppiness): the displaced surface's tangents are (1 + dDx/dx, dDy/dx, dh/dx) and
    //! (dDx/dy, 1 + dDy/dy, dh/dy), and dDx/dy = dDy/dx (the displacement is a gradient).
    struct Texel {
        osg::Vec4f displacement; // dx, dy, h, 0
        osg::Vec2f slope;
        osg::Vec3f jacobian; // dDx/dx, dDy/dy, dDx/dy
        //! dh/dx, dh/dy of the displaced surface, over the point this texel's displacement lands
        //! on: the slopes through the inverse of the displacement's Jacobian, its determinant kept
        //! above MIN_STRETCH where the choppy crests would fold over (mirrored by waves.glsl).
        osg::Vec2d displacedSlope() const;
    };
    //! The least area a choppy crest's displacement squeezes a unit of surface into: below it the
    //! surface would fold over itself, and its slopes are taken as they are at this squeeze.
    static constexpr double MIN_STRETCH = 0.1;

    explicit WaveCascades(const Params& params);
    ~WaveCascades();
    WaveCascades(const WaveCascades&) = delete;
    WaveCascades& operator=(const WaveCascades&) = delete;

    const Params& params() const { return _params; }
    //! Where each cascade's band lies; empty when the sea has no waves (no wind, no fetch).
    const std::vector<CascadeBand>& bands() const { return _bands; }
    //! The shortest wave the cascades hold for a sea (m): SHORTEST_WAVE, or a longer one where the
    //! spectrum's slopes, summed from its longest waves, reach Cox and Munk's total for its wind.
    //! JONSWAP's k^-3 tail, scaled by a short fetch's large alpha, would hold up to twice the slopes
    //! the sea shows down to 2 cm; what Cox and Munk measured beyond the waves held is the shading's
    //! roughness (unresolvedSlopeVariance). 0 without waves.
    static double shortestWave(const spectrum::WindSea& sea);
    //! The bands for a sea over an extent (what the constructor uses).
    static std::vector<CascadeBand> chooseBands(const spectrum::WindSea& sea, double extent, unsigned int size);

    //! The fields at time t (seconds); the previous time's are replaced.
    void update(double t);
    double time() const { return _time; }

    //! The texels of cascade c (size x size, row y major), as of the last update.
    const std::vector<Texel>& texels(unsigned int c) const { return _cascades[c].texels; }
    //! Whether cascade c holds waves: a band the spectrum leaves nearly empty (under a millionth
    //! of the variance, as a lake's longest waves) is left flat, never transformed nor sampled.
    bool holdsWaves(unsigned int c) const { return !_cascades[c].bins.empty(); }

    //! The sum of the cascades at the undisplaced point (x, y), each filtered bilinearly as a
    //! repeating texture is (texel centres at (i + 1/2) tile / size, plus half a texel: the FFT's
    //! sample i lies at i tile / size).
    Texel sample(double x, double y) const;
    //! The sample at the undisplaced point whose displacement lands on (x, y), found by Newton's
    //! steps (x, y finite): its height and displacedSlope() are the displaced surface's over (x, y).
    Texel over(double x, double y) const { return over(x, y, nullptr); }
    //! The same, and that undisplaced point (`source`).
    Texel over(double x, double y, osg::Vec2d* source) const;
    //! The slopes' variance over (x, y) that the bilinear interpolation between texels does not
    //! show: per cascade, the interpolated |slope|^2 less the square of the interpolated slope, at
    //! the point over() reads. What the shaders' roughness is for a footprint under a texel
    //! (waves.glsl, the level-0 read), beside unresolvedSlopeVariance(); 0 at a texel's sample.
    double subTexelSlopeVariance(double x, double y) const;
    //! The height of the displaced surface over (x, y): over(x, y)'s.
    double height(double x, double y) const;
    //! The unit normal of the displaced surface over (x, y): its tangents' cross product there.
    osg::Vec3d normal(double x, double y) const;

    //! The same fields summed over every bin directly, in double precision, at the undisplaced
    //! (x, y), as of the last update: the FFT's reference (slow: every bin of every cascade, or of
    //! cascade `only`).
    Texel directSum(double x, double y, int only = -1) const;

    //! The variance the bins hold: sum of S(k) dk^2 over every cascade's bins (m^2).
    double binVariance() const { return _binVariance; }
    //! The slopes' variance the bins hold, |grad h|^2 on average: sum of k^2 S(k) dk^2.
    double binSlopeVariance() const { return _binSlopeVariance; }
    //! A bound on the variance of the curvature d2h/du2 along any horizontal unit u the bins hold:
    //! sum of k^4 S(k) dk^2 (each bin's (k.u)^4 at most k^4).
    double binCurvatureVariance() const { return _binCurvatureVariance; }
    //! The largest variance of the displacement's derivatives dDx/dx, dDy/dy the bins hold (0
    //! without choppiness): sum of choppiness^2 k_i^4 / k^2 S(k) dk^2 for the larger of x and y.
    double binStretchVariance() const { return std::max(_binStretchVariance[0], _binStretchVariance[1]); }
    //! The slopes' variance no bin holds: Cox and Munk's total for the wind less binSlopeVariance,
    //! never below 0; 0 without bins. The shading's roughness where every texel is resolved.
    double unresolvedSlopeVariance() const;
    //! The fastest phase speed omega / k of any bin (m/s): the longest wave's. 0 without bins.
    double maxPhaseSpeed() const { return _maxPhaseSpeed; }
    //! The spectrum's integral over the bands, sum of int S(k) d^2k (m^2).
    static double bandVariance(const spectrum::WindSea& sea, const std::vector<CascadeBand>& bands);

private:
    struct Bin {
        unsigned int index;            // into the size x size spectrum
        std::complex<float> h0, h0MinusConj; // h0(k) and conj(h0(-k))
        double omega;
        float kx, ky, k;
    };
    struct Cascade {
        CascadeBand band;
        std::vector<Bin> bins;
        std::vector<Texel> texels;
    };
    //! The four texels of cascade c around (x, y) and their bilinear weights (sample()'s).
    struct Corners {
        const Texel* texel[4];
        float weight[4];
    };
    Corners corners(const Cascade& c, double x, double y) const;
    void evaluate(Cascade& c, double t);

    Params _params;
    std::vector<CascadeBand> _bands;
    std::vector<Cascade> _cascades;
    double _time;
    double _binVariance, _binSlopeVariance, _binCurvatureVariance, _binStretchVariance[2], _maxPhaseSpeed;
    struct Plans;
    std::unique_ptr<Plans> _plans;
};

}

#endif
