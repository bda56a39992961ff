#include <osgWater/PhotonGather>
#include <osgWater/PhotonSplat>
#include <osgWater/Shaders>
#include <osgWater/PassCamera>
#include <osg/BlendFunc>
#include <osg/Geometry>
#include <osg/GLExtensions>
#include <osg/Point>
#include <osg/State>
#include <vector>

using namespace osgWater;

namespace {

#ifndef GL_PIXEL_PACK_BUFFER_ARB
#define GL_PIXEL_PACK_BUFFER_ARB 0x88EB
#endif

// n points, one per photon texel; the vertex array is what the shader reads per point.
osg::Geometry* photonPoints(osg::Array* vertices, unsigned int n)
{
    osg::Geometry* g = new osg::Geometry;
    g->setUseDisplayList(false);
    g->setUseVertexBufferObjects(true);
    g->setVertexArray(vertices);
    g->addPrimitiveSet(new osg::DrawArrays(GL_POINTS, 0, n));
    g->setCullingActive(false); // its coordinates are photon data, not positions
    return g;
}

// GATHER_POINTS_COPY: before the points are drawn, the photon target is copied into their own
// vertex buffer through the pixel-pack binding (glGetTexImage into a buffer object: a pixel buffer
// object copy that stays on the GPU). OSG wraps every call but the copy itself.
class CopyPhotonsIntoVertexBuffer : public osg::Drawable::DrawCallback
{
public:
    explicit CopyPhotonsIntoVertexBuffer(osg::Texture2D* photons) : _photons(photons) {}

    void drawImplementation(osg::RenderInfo& ri, const osg::Drawable* drawable) const override
    {
        osg::State& state = *ri.getState();
        const osg::Geometry* g = static_cast<const osg::Geometry*>(drawable);
        const osg::Array* a = g->getVertexArray();
        osg::GLBufferObject* glbo = a->getOrCreateGLBufferObject(state.getContextID());
        osg::GLExtensions* ext = state.get<osg::GLExtensions>();
        if (glbo && ext) {
            if (glbo->isDirty()) glbo->compileBuffer(); // allocates it once
            state.unbindPixelBufferObject();
            state.setActiveTextureUnit(UNIT_PASS_INPUT);
            state.applyTextureAttribute(UNIT_PASS_INPUT, _photons.get());
            ext->glBindBuffer(GL_PIXEL_PACK_BUFFER_ARB, glbo->getGLObjectID());
            glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT,
                          reinterpret_cast<void*>(glbo->getOffset(a->getBufferIndex())));
            ext->glBindBuffer(GL_PIXEL_PACK_BUFFER_ARB, 0);
        }
        drawable->drawImplementation(ri);
    }

private:
    osg::ref_ptr<osg::Texture2D> _photons;
};

// GATHER_CPU: thesis §8.1's CPU approach.
class CpuGather : public osg::Drawable
{
public:
    CpuGather() : _grid(1), _res(1), _scale(1.0f) {}
    CpuGather(osg::Texture2D* photons, int gridSize, osg::Texture2D* caustics, int resolution, float scale)
        : _photons(photons), _caustics(caustics), _grid(gridSize), _res(resolution), _scale(scale)
    {
        setUseDisplayList(false);
        setCullingActive(false);
    }
    CpuGather(const CpuGather& o, const osg::CopyOp& op = osg::CopyOp::SHALLOW_COPY)
        : osg::Drawable(o, op), _photons(o._photons), _caustics(o._caustics), _grid(o._grid), _res(o._res),
          _scale(o._scale) {}
    META_Object(osgWater, CpuGather)

    void drawImplementation(osg::RenderInfo& ri) const override
    {
        if (!_photons.valid() || !_caustics.valid()) return;
        osg::State& state = *ri.getState();
        _in.resize(std::size_t(_grid) * _grid * 4);
        _out.assign(std::size_t(_res) * _res, 0.0f);
        state.unbindPixelBufferObject();
        state.setActiveTextureUnit(UNIT_PASS_INPUT);
        state.applyTextureAttribute(UNIT_PASS_INPUT, _photons.get());
        glPixelStorei(GL_PACK_ALIGNMENT, 4);
        glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, _in.data());
        const float weight = float(_res) * _res / (float(_grid) * _grid) / _scale;
        splatPhotons(_in.data(), std::size_t(_grid) * _grid, weight, _out.data(), _res);
        state.applyTextureAttribute(UNIT_PASS_INPUT, _caustics.get());
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, _res, _res, GL_RED, GL_FLOAT, _out.data());
    }

protected:
    osg::ref_ptr<osg::Texture2D> _photons, _caustics;
    int _grid, _res;
    float _scale;
    mutable std::vector<float> _in, _out;
};

osg::Geode* geodeOf(osg::Drawable* d)
{
    osg::Geode* g = new osg::Geode;
    g->addDrawable(d);
    g->setCullingActive(false);
    return g;
}

}

PhotonGather::PhotonGather(osg::Texture2D* photons, int gridSize, int resolution, bool floatTarget)
    : _method(WaterSettings::GATHER_AUTO), _resolution(resolution),
      _valueScale(floatTarget ? 1.0f : 16.0f)
{
    setName("osgWater.PhotonGather");
    setUpPassTarget(this, resolution, resolution, PASS_GATHER);
    setClearMask(GL_COLOR_BUFFER_BIT);
    setClearColor(osg::Vec4(0.0f, 0.0f, 0.0f, 0.0f));
    setProjectionMatrix(osg::Matrixd::identity()); // the splat shader writes clip space itself
    setViewMatrix(osg::Matrixd::identity());

    _caustics = makeTargetTexture(resolution, floatTarget ? GL_R32F : GL_RGBA16, floatTarget ? GL_RED : GL_RGBA,
                                  floatTarget ? GL_FLOAT : GL_UNSIGNED_SHORT, true);
    _caustics->setName("osgWater.caustics");
    attach(osg::Camera::COLOR_BUFFER, _caustics.get());

    osg::StateSet* ss = getOrCreateStateSet();
    ss->setDataVariance(osg::Object::DYNAMIC); // the paths switch between frames
    ss->setAttribute(createProgram("osgWater.splat", "splat.vert", "splat.frag"));
    ss->setAttributeAndModes(new osg::BlendFunc(GL_ONE, GL_ONE), osg::StateAttribute::ON);
    ss->setAttribute(new osg::Point(2.0f)); // 2x2 pixels: the tent's support
    ss->setMode(GL_DEPTH_TEST, osg::StateAttribute::OFF);
    ss->setMode(GL_CULL_FACE, osg::StateAttribute::OFF);
    ss->addUniform(new osg::Uniform("osgWater_PhotonWeight",
                                    float(resolution) * resolution / (float(gridSize) * gridSize) / _valueScale));
    ss->addUniform(new osg::Uniform("osgWater_CausticsSize", float(resolution)));
    ss->addUniform(new osg::Uniform("osgWater_Photons", int(UNIT_PASS_INPUT)));

    const unsigned int n = unsigned(gridSize) * unsigned(gridSize);
    osg::ref_ptr<osg::Vec4Array> copyTarget = new osg::Vec4Array(n);
    osg::Geometry* copyPoints = photonPoints(copyTarget.get(), n);
    copyTarget->getVertexBufferObject()->setUsage(GL_STREAM_COPY_ARB);
    copyPoints->setDrawCallback(new CopyPhotonsIntoVertexBuffer(photons));
    _copySplat = geodeOf(copyPoints);

    osg::ref_ptr<osg::Vec2Array> texels = new osg::Vec2Array(n);
    for (unsigned int i = 0; i < n; ++i) (*texels)[i].set(float(i % gridSize), float(i / gridSize));
    _textureSplat = geodeOf(photonPoints(texels.get(), n));
    _textureSplat->getOrCreateStateSet()->setTextureAttribute(UNIT_PASS_INPUT, photons);
    _textureSplat->getOrCreateStateSet()->setDefine("OSGWATER_SPLAT_TEXTURE");

    _cpuGather = geodeOf(new CpuGather(photons, gridSize, _caustics.get(), resolution, _valueScale));

    addChild(_copySplat.get());
    addChild(_textureSplat.get());
    addChild(_cpuGather.get());
    // nothing drawn until CausticsCamera::resolveGather() chose
    _copySplat->setNodeMask(0u);
    _textureSplat->setNodeMask(0u);
    _cpuGather->setNodeMask(0u);
}

void PhotonGather::setMethod(WaterSettings::CausticsGather m)
{
    if (m == _method) return;
    _method = m;
    // the splat program's variants of the paths tried before are not needed any more
    getStateSet()->getAttribute(osg::StateAttribute::PROGRAM)->releaseGLObjects(nullptr);
    const std::pair<osg::Geode*, WaterSettings::CausticsGather> paths[] = {
        { _copySplat.get(), WaterSettings::GATHER_POINTS_COPY },
        { _textureSplat.get(), WaterSettings::GATHER_POINTS_TEXTURE },
        { _cpuGather.get(), WaterSettings::GATHER_CPU } };
    for (const auto& p : paths) {
        const bool on = p.second == m;
        // a path switched off keeps no GL buffers (the automatic choice tries every path once);
        // its drawables only: the geode's state holds the photon target, which stays
        if (!on && p.first->getNodeMask() != 0u)
            for (unsigned int i = 0; i < p.first->getNumDrawables(); ++i) p.first->getDrawable(i)->releaseGLObjects(nullptr);
        p.first->setNodeMask(on ? ~0u : 0u);
    }
}
