#include "surface/SpectralWaves.h"
#include <osg/GLExtensions>
#include <osg/State>
#include <algorithm>
#include <cmath>

using namespace osgWater;
using namespace osgWater::detail;

namespace {
const unsigned int kChannels = 4; // h, dh/dx, dh/dy, |grad h|^2

// Uploads the layers' every mip level, again each time an image changed. OSG's own path for
// mipmapped array images re-specifies the levels of the immutable storage it made (a GL error),
// and regenerates no levels on a subload.
class CascadeUpload : public osg::Texture2DArray::SubloadCallback
{
public:
    explicit CascadeUpload(const std::vector<osg::ref_ptr<osg::Image>>& images) : _images(images) {}

    void load(const osg::Texture2DArray& texture, osg::State& state) const override
    {
        const osg::GLExtensions* gl = state.get<osg::GLExtensions>();
        int side = _images.front()->s();
        for (int level = 0; side >= 1; ++level, side /= 2)
            gl->glTexImage3D(GL_TEXTURE_2D_ARRAY_EXT, level, GL_RGBA32F_ARB, side, side, GLsizei(_images.size()), 0, GL_RGBA,
                             GL_FLOAT, nullptr);
        _uploaded[state.getContextID()] = ~0u;
        subload(texture, state);
    }

    void subload(const osg::Texture2DArray&, osg::State& state) const override
    {
        unsigned int revision = 0;
        for (const osg::ref_ptr<osg::Image>& image : _images) revision += image->getModifiedCount();
        unsigned int& uploaded = _uploaded[state.getContextID()];
        if (uploaded == revision) return;
        const osg::GLExtensions* gl = state.get<osg::GLExtensions>();
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
        for (size_t layer = 0; layer < _images.size(); ++layer) {
            const osg::Image& image = *_images[layer];
            int side = image.s();
            for (unsigned int level = 0; side >= 1 && level < image.getNumMipmapLevels(); ++level, side /= 2)
                gl->glTexSubImage3D(GL_TEXTURE_2D_ARRAY_EXT, GLint(level), 0, 0, GLint(layer), side, side, 1, GL_RGBA, GL_FLOAT,
                                    image.getMipmapData(level));
        }
        uploaded = revision;
    }

private:
    std::vector<osg::ref_ptr<osg::Image>> _images;
    mutable osg::buffered_value<unsigned int> _uploaded;
};
}

namespace {
// each mip level the 2 x 2 average of the one above, from `level` (level 0 of an n x n tile of
// kChannels floats) down to 1 x 1, stored after it: texel i of level L covers texels 2^L i ..
// 2^L (i + 1) of level 0, as GL's mip levels do. Returns the 1 x 1 level.
const float* averageLevels(float* level, unsigned int n)
{
    for (unsigned int side = n / 2; side >= 1; side /= 2) {
        float* next = level + size_t(2 * side) * (2 * side) * kChannels;
        const size_t row = size_t(2 * side) * kChannels;
        for (unsigned int y = 0; y < side; ++y)
            for (unsigned int x = 0; x < side; ++x)
                for (unsigned int k = 0; k < kChannels; ++k) {
                    const float* a = level + (2 * y) * row + (2 * x) * kChannels + k;
                    next[(size_t(y) * side + x) * kChannels + k] = 0.25f * (a[0] + a[kChannels] + a[row] + a[row + kChannels]);
                }
        level = next;
    }
    return level;
}

// `layers` images of n x n RGBA floats with every mip level down to 1 x 1, one block per layer,
// uploaded by CascadeUpload
std::vector<osg::ref_ptr<osg::Image>> mipmappedLayers(unsigned int n, unsigned int layers)
{
    osg::Image::MipmapDataType offsets;
    size_t texels = size_t(n) * n;
    for (unsigned int side = n / 2; side >= 1; side /= 2) {
        offsets.push_back(unsigned(texels * kChannels * sizeof(float)));
        texels += size_t(side) * side;
    }
    std::vector<osg::ref_ptr<osg::Image>> images;
    for (unsigned int layer = 0; layer < layers; ++layer) {
        osg::ref_ptr<osg::Image> image = new osg::Image;
        float* data = new float[texels * kChannels]();
        image->setImage(int(n), int(n), 1, GL_RGBA32F_ARB, GL_RGBA, GL_FLOAT, reinterpret_cast<unsigned char*>(data),
                        osg::Image::USE_NEW_DELETE);
        image->setMipmapLevels(offsets);
        image->setDataVariance(osg::Object::DYNAMIC);
        images.push_back(image);
    }
    return images;
}

// a float array of `layers` periodic n x n tiles, rewritten every frame
void setUpLayers(osg::Texture2DArray& t, unsigned int n, unsigned int layers, GLint internalFormat, GLenum sourceFormat,
                 osg::Texture::FilterMode minFilter)
{
    t.setTextureSize(int(n), int(n), int(layers));
    t.setInternalFormat(internalFormat);
    t.setSourceFormat(sourceFormat);
    t.setSourceType(GL_FLOAT);
    t.setFilter(osg::Texture::MIN_FILTER, minFilter);
    t.setFilter(osg::Texture::MAG_FILTER, osg::Texture::LINEAR);
    for (osg::Texture::WrapParameter w : { osg::Texture::WRAP_S, osg::Texture::WRAP_T })
        t.setWrap(w, osg::Texture::REPEAT); // each cascade is a periodic tile
    t.setResizeNonPowerOfTwoHint(false);
    t.setDataVariance(osg::Object::DYNAMIC);
}
}

SpectralWaves::SpectralWaves(const WaveCascades::Params& params)
    : _cascades(params), _heightBound(0.0), _slopeBound(0.0), _curvatureBound(0.0), _stretchBound(0.0), _tilesMeanSquareSlope(0.0),
      _texture(new osg::Texture2DArray),
      _heights(new osg::Texture2DArray)
{
    _heightBound = HEIGHT_SIGMAS * std::sqrt(_cascades.binVariance());
    _slopeBound = HEIGHT_SIGMAS * std::sqrt(_cascades.binSlopeVariance());
    _stretchBound = HEIGHT_SIGMAS * std::sqrt(_cascades.binStretchVariance());
    for (unsigned int c = 0; c < _cascades.bands().size(); ++c)
        if (_cascades.holdsWaves(c)) {
            _layers.push_back(c);
            _cascadeBound.push_back(HEIGHT_SIGMAS * std::sqrt(WaveCascades::bandVariance(params.sea, { _cascades.bands()[c] })));
        }
    // (after the layers: choppyChord() asks whether any hold waves)
    _curvatureBound = HEIGHT_SIGMAS * std::sqrt(_cascades.binCurvatureVariance()) * choppyChord() * choppyChord();

    const unsigned int n = _cascades.params().size, layers = std::max(cascadeCount(), 1u);
    setUpLayers(*_texture, n, layers, GL_RGBA32F_ARB, GL_RGBA, osg::Texture::LINEAR_MIPMAP_LINEAR);
    _images = mipmappedLayers(n, layers);
    _texture->setSubloadCallback(new CascadeUpload(_images));
    if (choppy()) {
        _jacobians = new osg::Texture2DArray;
        setUpLayers(*_jacobians, n, layers, GL_RGBA32F_ARB, GL_RGBA, osg::Texture::LINEAR_MIPMAP_LINEAR);
        _jacobianImages = mipmappedLayers(n, layers);
        _jacobians->setSubloadCallback(new CascadeUpload(_jacobianImages));
    }

    // the heights alone, level 0: what the sight ray's search reads (one channel a texel costs a
    // software rasteriser a third of four); choppy, with the displacement it inverts
    const GLenum heightFormat = choppy() ? GL_RGBA : GL_RED;
    const unsigned int heightChannels = choppy() ? 4 : 1;
    setUpLayers(*_heights, n, layers, choppy() ? GL_RGBA32F_ARB : GL_R32F, heightFormat, osg::Texture::LINEAR);
    for (unsigned int layer = 0; layer < layers; ++layer) {
        osg::ref_ptr<osg::Image> image = new osg::Image;
        image->allocateImage(int(n), int(n), 1, heightFormat, GL_FLOAT);
        image->setInternalTextureFormat(choppy() ? GL_RGBA32F_ARB : GL_R32F);
        std::fill(reinterpret_cast<float*>(image->data()), reinterpret_cast<float*>(image->data()) + size_t(n) * n * heightChannels,
                  0.0f);
        image->setDataVariance(osg::Object::DYNAMIC);
        _heights->setImage(layer, image.get());
        _heightImages.push_back(image);
    }
    fill();
}

void SpectralWaves::bringTo(double t) const
{
    if (t != _cascades.time()) _cascades.update(t);
}

SpectralWaves::Sampler SpectralWaves::at(double t) const
{
    if (!std::isfinite(t)) t = 0.0;
    std::shared_lock<std::shared_mutex> shared(_lock);
    if (t == _cascades.time()) return Sampler(_cascades, std::move(shared), {});
    shared.unlock();
    std::unique_lock<std::shared_mutex> exclusive(_lock);
    bringTo(t);
    return Sampler(_cascades, {}, std::move(exclusive));
}

void SpectralWaves::applyTime(double t)
{
    if (!std::isfinite(t)) t = 0.0;
    std::unique_lock<std::shared_mutex> guard(_lock);
    bringTo(t);
    if (_cascades.time() != _textureTime) {
        fill();
        _textureTime = _cascades.time();
    }
}

double SpectralWaves::evaluatedTime() const
{
    std::shared_lock<std::shared_mutex> guard(_lock);
    return _cascades.time();
}

double SpectralWaves::textureTime() const
{
    std::shared_lock<std::shared_mutex> guard(_lock);
    return _textureTime;
}

void SpectralWaves::fill()
{
    const unsigned int n = _cascades.params().size;
    _tilesMeanSquareSlope = 0.0;
    for (unsigned int layer = 0; layer < cascadeCount(); ++layer) {
        float* level = reinterpret_cast<float*>(_images[layer]->data());
        const std::vector<WaveCascades::Texel>& texels = _cascades.texels(_layers[layer]);
        float* heights = reinterpret_cast<float*>(_heightImages[layer]->data());
        float* jacobians = choppy() ? reinterpret_cast<float*>(_jacobianImages[layer]->data()) : nullptr;
        for (size_t i = 0; i < texels.size(); ++i) {
            const WaveCascades::Texel& t = texels[i];
            level[kChannels * i + 0] = t.displacement.z();
            level[kChannels * i + 1] = t.slope.x();
            level[kChannels * i + 2] = t.slope.y();
            level[kChannels * i + 3] = t.slope.length2();
            if (!jacobians) {
                heights[i] = t.displacement.z();
                continue;
            }
            const float height[4] = { t.displacement.z(), t.displacement.x(), t.displacement.y(), 0.0f };
            const float jacobian[4] = { t.jacobian.x(), t.jacobian.y(), t.jacobian.z(), 0.0f };
            std::copy(height, height + 4, heights + 4 * i);
            std::copy(jacobian, jacobian + 4, jacobians + kChannels * i);
        }
        _tilesMeanSquareSlope += averageLevels(level, n)[3]; // the 1 x 1 level: the tile's mean |grad h|^2
        _images[layer]->dirty();
        _heightImages[layer]->dirty();
        if (jacobians) {
            averageLevels(jacobians, n);
            _jacobianImages[layer]->dirty();
        }
    }
}

double SpectralWaves::meanSquareSlope() const
{
    std::shared_lock<std::shared_mutex> guard(_lock);
    return _tilesMeanSquareSlope + _cascades.unresolvedSlopeVariance();
}

double SpectralWaves::choppyChord() const
{
    return choppy() ? 1.0 / std::max(1.0 - _stretchBound, WaveCascades::MIN_STRETCH) : 1.0;
}

osg::Vec4f SpectralWaves::cascadeScale(unsigned int layer) const
{
    if (layer >= cascadeCount()) return osg::Vec4f();
    const CascadeBand& b = _cascades.bands()[_layers[layer]];
    return osg::Vec4f(float(1.0 / b.tile), float(_cascadeBound[layer]), float(b.kHigh), 0.0f);
}

double SpectralWaves::shortestWave() const
{
    double k = 0.0;
    for (unsigned int c : _layers) k = std::max(k, _cascades.bands()[c].kHigh);
    return k > 0.0 ? 2.0 * osg::PI / k : 1.0e30;
}
