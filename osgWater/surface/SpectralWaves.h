/* osgWater - natural water for OpenSceneGraph */
#ifndef OSGWATER_SPECTRALWAVES
#define OSGWATER_SPECTRALWAVES 1

#include "surface/WaveCascades.h"
#include <osgWater/Export>
#include <osg/Referenced>
#include <osg/Texture2DArray>
#include <mutex>
#include <shared_mutex>

namespace osgWater { namespace detail {

//! A WaterSurface's wind waves: the cascades, asked at any time, and the texture the shaders read
//! them from (waves.glsl under OSGWATER_WIND). The CPU and the GPU sample the same texels the same
//! way (bilinear, texel i's centre at the FFT's sample i), so the height query is the drawn surface.
//!
//! With choppiness the texture holds the undisplaced surface's slopes, which the shaders (as the
//! CPU) turn into the displaced surface's with the displacement's Jacobian (jacobianTexture).
//!
//! The texture is a 2D array, one layer per cascade, RGBA32F: the height, its slopes dh/dx, dh/dy
//! and |grad h|^2, with mip levels averaged here (the averages of heights and of slopes are the
//! height and the slopes of the averaged surface), so far water reads a filtered surface. What a
//! level's texel no longer shows of the slopes under it is its mean |grad h|^2 less the square of its
//! mean slopes (LEAN mapping's second moments, Olano and Baker 2010): the shading's roughness there,
//! beside the slopes no cascade holds (unresolvedSlopeVariance).
class OSGWATER_EXPORT SpectralWaves : public osg::Referenced
{
public:
    explicit SpectralWaves(const WaveCascades::Params& params);

    //! The cascades at one time, held for a burst of queries (a ray's march): one lock for all of
    //! them. Threads asking about the same time share the cascades without waiting on each other
    //! (a lock per query made two threads spend most of their time handing a mutex back and forth).
    //! While a thread holds one it asks this object nothing else.
    class Sampler
    {
    public:
        double height(double x, double y) const { return _cascades.height(x, y); }
        osg::Vec3d normal(double x, double y) const { return _cascades.normal(x, y); }
        //! The height, and the slopes (dh/dx, dh/dy) of the surface over (x, y), from one sample.
        double heightAndSlope(double x, double y, osg::Vec2d& slope) const
        {
            const WaveCascades::Texel s = _cascades.over(x, y);
            slope = s.displacedSlope();
            return s.displacement.z();
        }

        //! The slopes' variance over (x, y) its normal does not show: what the interpolation between
        //! texels averages away and what no cascade holds. The shaders' roughness for a footprint
        //! under a texel (a ray's).
        double roughness(double x, double y) const
        {
            return _cascades.subTexelSlopeVariance(x, y) + _cascades.unresolvedSlopeVariance();
        }

    private:
        friend class SpectralWaves;
        Sampler(const WaveCascades& cascades, std::shared_lock<std::shared_mutex> shared,
                std::unique_lock<std::shared_mutex> exclusive)
            : _cascades(cascades), _shared(std::move(shared)), _exclusive(std::move(exclusive)) {}
        const WaveCascades& _cascades;
        std::shared_lock<std::shared_mutex> _shared;       // the cascades were at the time asked
        std::unique_lock<std::shared_mutex> _exclusive;    // ... or were brought to it
    };
    //! The cascades brought to time t when it differs from their last time (a few milliseconds).
    Sampler at(double t) const;

    //! The surface's height above its level and its unit normal over (x, y) at time t.
    double height(double x, double y, double t) const { return at(t).height(x, y); }
    osg::Vec3d normal(double x, double y, double t) const { return at(t).normal(x, y); }

    //! The texture's texels made those of time t (once a frame, the frame's time).
    void applyTime(double t);
    //! The time the cascades were last evaluated at (by a query or by applyTime), and the time the
    //! texture's texels are of.
    double evaluatedTime() const;
    double textureTime() const;
    osg::Texture2DArray* texture() const { return _texture.get(); }
    //! The same layers' heights alone, level 0 (R32F): what the sight ray's search reads. Choppy,
    //! (h, Dx, Dy, 0) (RGBA32F): the displacement the shaders invert as the CPU does.
    osg::Texture2DArray* heightTexture() const { return _heights.get(); }
    //! Whether the waves move the surface sideways (choppiness, and waves to move it): the shaders
    //! then invert the displacement (OSGWATER_CHOPPY) and read jacobianTexture.
    bool choppy() const { return _cascades.params().choppiness > 0.0 && !_layers.empty(); }
    //! Choppy, per layer the displacement's derivatives (dDx/dx, dDy/dy, dDx/dy, 0), mipmapped as
    //! texture() is; else null.
    osg::Texture2DArray* jacobianTexture() const { return _jacobians.get(); }
    //! How much longer a chord of the choppy surface is, measured on the undisplaced one, than on
    //! the water: 1 / (1 - stretchBound), at most 1 / WaveCascades::MIN_STRETCH; 1 without
    //! choppiness. A crest squeezed sideways bends more sharply between a mesh's vertices.
    double choppyChord() const;
    //! The displacement's derivatives stay below this: HEIGHT_SIGMAS standard deviations of them.
    double stretchBound() const { return _stretchBound; }
    //! Per layer of the texture (a cascade that holds waves), what the shader needs:
    //! (1 / tile, the height bound, the band's top k, 0).
    osg::Vec4f cascadeScale(unsigned int layer) const;
    unsigned int cascadeCount() const { return unsigned(_layers.size()); }
    unsigned int textureSize() const { return _cascades.params().size; }

    //! |h| stays below this (m): HEIGHT_SIGMAS standard deviations of the heights the bins hold
    //! (a Gaussian field's extreme over a lake's worth of texels is about 4.5 of them).
    double heightBound() const { return _heightBound; }
    //! |grad h| stays below this: HEIGHT_SIGMAS standard deviations of the slopes. The choppy
    //! surface's slopes too: its steepest lie mid-flank, where the displacement hardly squeezes it
    //! (tested on the realised surface).
    double slopeBound() const { return _slopeBound; }
    //! |d2h/du2| along any horizontal unit u stays below this (1/m): HEIGHT_SIGMAS standard
    //! deviations of the curvatures the bins hold, times choppyChord() squared (a crest squeezed
    //! sideways bends that much more sharply). The height query's step near the surface.
    double curvatureBound() const { return _curvatureBound; }
    double maxPhaseSpeed() const { return _cascades.maxPhaseSpeed(); }
    //! The slopes' variance no cascade holds: the roughness of water whose texels are all resolved.
    double unresolvedSlopeVariance() const { return _cascades.unresolvedSlopeVariance(); }
    //! The water's mean square slope as of the texture's time: its tiles' mean |grad h|^2 (their
    //! last mip level) plus the unresolved. The roughness of a pixel wider than every tile.
    double meanSquareSlope() const;
    //! The shortest wave the cascades hold (m).
    double shortestWave() const;
    static constexpr double HEIGHT_SIGMAS = 6.0;

private:
    void bringTo(double t) const; // under _lock, held exclusively
    void fill(); // the texture's images from the cascades

    mutable std::shared_mutex _lock;
    mutable WaveCascades _cascades;
    std::vector<unsigned int> _layers; // the cascades that hold waves, one texture layer each
    std::vector<double> _cascadeBound;
    double _heightBound, _slopeBound, _curvatureBound, _stretchBound, _tilesMeanSquareSlope;
    double _textureTime = 0.0;
    osg::ref_ptr<osg::Texture2DArray> _texture, _heights, _jacobians;
    std::vector<osg::ref_ptr<osg::Image>> _images, _heightImages, _jacobianImages;
};

} }

#endif
