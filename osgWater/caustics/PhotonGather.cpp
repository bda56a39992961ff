#include "caustics/PhotonGather.h"
#include "shaders/ProgramLibrary.h"
#include "caustics/PhotonSplat.h"
#include "shaders/Shaders.h"
#include "frame/PassCamera.h"
#include "frame/SceneLighting.h"
#include "frame/ScreenTriangle.h"
#include <osg/BlendFunc>
#include <osg/buffered_value>
#include <osg/Geometry>
#include <osg/GLExtensions>
#include <osg/Point>
#include <osg/State>
#include <map>
#include <vector>

using namespace osgWater;

namespace {

#ifndef GL_PIXEL_PACK_BUFFER_ARB
#define GL_PIXEL_PACK_BUFFER_ARB 0x88EB
#endif

// One photon per vertex, the vertex array being what the shader reads per photon: n points, or
// the area-ratio mesh over the grid x grid photon texels (two triangles per cell, in the order of
// osgWater::meshPhotons).
osg::Geometry* photonGeometry(osg::Array* vertices, int grid, WaterSettings::CausticsMethod method)
{
    osg::Geometry* g = new osg::Geometry;
    g->setUseDisplayList(false);
    g->setUseVertexBufferObjects(true);
    g->setVertexArray(vertices);
    if (method == WaterSettings::CAUSTICS_AREA_MESH) {
        osg::DrawElementsUInt* cells = new osg::DrawElementsUInt(GL_TRIANGLES);
        cells->reserve(6u * unsigned(grid - 1) * unsigned(grid - 1));
        for (int j = 0; j + 1 < grid; ++j)
            for (int i = 0; i + 1 < grid; ++i) {
                const unsigned int a = unsigned(j * grid + i), b = a + 1, c = b + unsigned(grid), d = a + unsigned(grid);
                for (unsigned int v : { a, b, c, a, c, d }) cells->push_back(v);
            }
        g->addPrimitiveSet(cells);
    } else {
        g->addPrimitiveSet(new osg::DrawArrays(GL_POINTS, 0, grid * grid));
    }
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
        // the supersampled gather draws the same points four times: one copy a frame is enough
        const unsigned int frame = state.getFrameStamp() ? state.getFrameStamp()->getFrameNumber() : 0u;
        unsigned int& copied = _copiedFrame[state.getContextID()]; // sized for every context up front
        if (glbo && ext && (copied != frame || frame == 0u)) {
            copied = frame;
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
    mutable osg::buffered_value<unsigned int> _copiedFrame; // per context: the frame copied last
};

// GATHER_CPU: thesis §8.1's CPU approach.
class CpuGather : public osg::Drawable
{
public:
    CpuGather() : _grid(1), _res(1), _scale(1.0f), _spacing(0.0f), _mesh(false) {}
    CpuGather(osg::Texture2D* photons, int gridSize, osg::Texture2D* caustics, int resolution, float scale,
              WaterSettings::CausticsMethod method, const std::vector<GatherShift>& passes, float spacing)
        : _photons(photons), _caustics(caustics), _grid(gridSize), _res(resolution), _scale(scale), _spacing(spacing),
          _mesh(method == WaterSettings::CAUSTICS_AREA_MESH), _passes(passes)
    {
        setUseDisplayList(false);
        setCullingActive(false);
    }
    CpuGather(const CpuGather& o, const osg::CopyOp& op = osg::CopyOp::SHALLOW_COPY)
        : osg::Drawable(o, op), _photons(o._photons), _caustics(o._caustics), _grid(o._grid), _res(o._res),
          _scale(o._scale), _spacing(o._spacing), _mesh(o._mesh), _passes(o._passes) {}
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
        for (const GatherShift& shift : _passes) {
            if (_mesh) {
                meshPhotons(_in.data(), _grid, _scale, _out.data(), _res, shift, _spacing);
            } else {
                const float weight = float(_res) * _res / (float(_grid) * _grid) / _scale;
                splatPhotons(_in.data(), std::size_t(_grid) * _grid, weight, _out.data(), _res, shift);
            }
        }
        state.applyTextureAttribute(UNIT_PASS_INPUT, _caustics.get());
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, _res, _res, GL_RED, GL_FLOAT, _out.data());
    }

protected:
    osg::ref_ptr<osg::Texture2D> _photons, _caustics;
    int _grid, _res;
    float _scale, _spacing;
    bool _mesh;
    std::vector<GatherShift> _passes;
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

PhotonGather::PhotonGather(osg::Texture2D* photons, ProgramLibrary& programs, int gridSize, int resolution,
                           bool floatTarget, osg::StateSet* waterState)
    : _method(WaterSettings::GATHER_AUTO), _causticsMethod(WaterSettings::CAUSTICS_PHOTONS), _grid(gridSize),
      _resolution(resolution), _valueScale(floatTarget ? 1.0f : 16.0f), _photons(photons), _waterState(waterState)
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
    // mipmaps, made after every draw: a pattern of texels seen from afar aliases without them (the
    // procedural caustics' paper says so; photons' splats are smoother, but a bed seen at a grazing
    // angle minifies them too)
    _caustics->setFilter(osg::Texture::MIN_FILTER, osg::Texture::LINEAR_MIPMAP_LINEAR);
    // the attachment's flag makes them after every draw, but only into the levels the storage has,
    // and OSG makes an image-less texture's storage (glTexStorage2D) with this many: one unless told
    unsigned int levels = 1;
    while ((resolution >> levels) > 0) ++levels;
    _caustics->setNumMipmapLevels(levels);
    attach(osg::Camera::COLOR_BUFFER, _caustics.get(), 0, 0, true); // made after every draw

    osg::StateSet* ss = getOrCreateStateSet();
    ss->setDataVariance(osg::Object::DYNAMIC); // the paths switch between frames
    ss->setAttribute(programs.get("osgWater.splat", "splat.vert", "splat.frag"));
    ss->setAttributeAndModes(new osg::BlendFunc(GL_ONE, GL_ONE), osg::StateAttribute::ON);
    ss->setAttribute(new osg::Point(2.0f)); // 2x2 pixels: the tent's support
    ss->setMode(GL_DEPTH_TEST, osg::StateAttribute::OFF);
    ss->setMode(GL_CULL_FACE, osg::StateAttribute::OFF);
    ss->addUniform(new osg::Uniform("osgWater_PhotonWeight",
                                    float(resolution) * resolution / (float(gridSize) * gridSize) / _valueScale));
    ss->addUniform(new osg::Uniform("osgWater_CausticsSize", float(resolution)));
    ss->addUniform(new osg::Uniform("osgWater_Photons", int(UNIT_PASS_INPUT)));
    ss->addUniform(new osg::Uniform("osgWater_PhotonGrid", float(gridSize)));
    ss->addUniform(new osg::Uniform("osgWater_GatherShift", osg::Vec3f(0.0f, 0.0f, 1.0f))); // one pass, unshifted
    // the paths are made when first chosen (setMethod()): nothing is drawn until then

    // the procedural path's program and inputs (setProceduralSun() sets them every frame)
    _proceduralState = new osg::StateSet;
    _proceduralState->setName("osgWater.procedural");
    _proceduralState->setDataVariance(osg::Object::DYNAMIC);
    _proceduralState->setAttribute(programs.get("osgWater.procedural", "screen.vert", "procedural.frag"));
    _proceduralState->addUniform(new osg::Uniform("osgWater_ProceduralScale", 1.0f / _valueScale));
    _proceduralState->addUniform(new osg::Uniform("osgWater_SunBedDepth", int(UNIT_PASS_INPUT)));
}

void PhotonGather::setProceduralSun(const osg::Matrixd& texToLocal, const osg::Matrixd& sunView,
                                    const osg::Vec3& towardsSun, osg::Texture2D* sunDepth, osg::Texture2D* shade,
                                    const osg::Matrixd& shadeProjection)
{
    osg::StateSet* ss = _proceduralState.get();
    ss->setTextureAttribute(UNIT_PASS_INPUT, sunDepth);
    setOrAddUniform(ss, "osgWater_SunTexToLocal", osg::Matrixf(texToLocal));
    setOrAddUniform(ss, "osgWater_SunView", osg::Matrixf(sunView));
    setOrAddUniform(ss, "osgWater_TowardsSunLocal", towardsSun);
    setDefineIf(ss, "OSGWATER_PROCEDURAL_SHADE", shade != nullptr);
    if (shade) applySunShade(ss, shade, UNIT_SUN_DEPTH, shadeProjection);
}

osg::Group* PhotonGather::makePath(const PathKey& key)
{
    const WaterSettings::CausticsGather gather = std::get<0>(key);
    const WaterSettings::CausticsMethod method = std::get<1>(key);
    const bool supersampled = std::get<2>(key), tiled = std::get<3>(key);
    const std::vector<GatherShift> passes = gatherPasses(supersampled, tiled, _resolution);
    // a tile's samples reach both its edges (the surface repeats: the mesh closes on its neighbour's)
    const float spacing = float(_resolution) / float(tiled ? std::max(_grid - 1, 1) : _grid);
    const unsigned int n = unsigned(_grid) * unsigned(_grid);
    if (method == WaterSettings::CAUSTICS_PROCEDURAL) {
        // no photons: one triangle over the caustics texture, each texel traced back from its bed
        // point, under the water's state (waves, indices, Fresnel, extinction)
        osg::Group* path = new osg::Group;
        path->setCullingActive(false);
        osg::Group* water = new osg::Group;
        water->setStateSet(_waterState);
        water->setCullingActive(false);
        osg::Geode* texels = makeScreenTriangle(0.0f, "osgWater.proceduralCaustics");
        texels->setStateSet(_proceduralState.get());
        water->addChild(texels);
        path->addChild(water);
        path->setNodeMask(0u);
        addChild(path);
        return path;
    }
    osg::ref_ptr<osg::Drawable> draw;
    osg::ref_ptr<osg::StateSet> state = new osg::StateSet;
    switch (gather) {
    case WaterSettings::GATHER_POINTS_COPY: {
        osg::ref_ptr<osg::Vec4Array> copyTarget = new osg::Vec4Array(n);
        osg::Geometry* g = photonGeometry(copyTarget.get(), _grid, method);
        copyTarget->getVertexBufferObject()->setUsage(GL_STREAM_COPY_ARB);
        g->setDrawCallback(new CopyPhotonsIntoVertexBuffer(_photons.get()));
        draw = g;
        break;
    }
    case WaterSettings::GATHER_POINTS_TEXTURE: {
        osg::ref_ptr<osg::Vec2Array> texels = new osg::Vec2Array(n);
        for (unsigned int i = 0; i < n; ++i) (*texels)[i].set(float(i % unsigned(_grid)), float(i / unsigned(_grid)));
        draw = photonGeometry(texels.get(), _grid, method);
        state->setTextureAttribute(UNIT_PASS_INPUT, _photons.get());
        state->setDefine("OSGWATER_SPLAT_TEXTURE");
        break;
    }
    default: // the CPU runs the passes itself
        draw = new CpuGather(_photons.get(), _grid, _caustics.get(), _resolution, _valueScale, method, passes, spacing);
        break;
    }
    if (method == WaterSettings::CAUSTICS_AREA_MESH) state->setDefine("OSGWATER_AREA_MESH");
    state->addUniform(new osg::Uniform("osgWater_SampleSpacing", spacing));
    osg::Group* path = new osg::Group;
    path->setStateSet(state.get());
    path->setCullingActive(false);
    if (passes.size() > 1 && gather != WaterSettings::GATHER_CPU) {
        // DeepWater's 2x2 supersampling and nine tiles: the same draw again, shifted and weighted
        for (const GatherShift& shift : passes) {
            osg::Geode* pass = geodeOf(draw.get());
            pass->getOrCreateStateSet()->addUniform(
                new osg::Uniform("osgWater_GatherShift", osg::Vec3f(shift.x, shift.y, shift.weight)));
            path->addChild(pass);
        }
    } else {
        path->addChild(geodeOf(draw.get()));
    }
    path->setNodeMask(0u);
    addChild(path);
    return path;
}

void PhotonGather::setMethod(WaterSettings::CausticsGather gather, WaterSettings::CausticsMethod method,
                            bool supersampled, bool tiled)
{
    if (gather == _method && method == _causticsMethod && supersampled == _supersampled && tiled == _tiled) return;
    _method = gather;
    _causticsMethod = method;
    _supersampled = supersampled;
    _tiled = tiled;
    // the splat program's variants of the paths tried before are not needed any more
    getStateSet()->getAttribute(osg::StateAttribute::PROGRAM)->releaseGLObjects(nullptr);
    // the procedural path reads no photons: one path whatever the gather way (the automatic choice's
    // trials would otherwise make three alike)
    const PathKey wanted(method == WaterSettings::CAUSTICS_PROCEDURAL ? WaterSettings::GATHER_AUTO : gather, method,
                         supersampled, tiled);
    if (gather != WaterSettings::GATHER_AUTO && !_paths.count(wanted)) _paths[wanted] = makePath(wanted);
    for (const auto& p : _paths) {
        osg::Group* path = p.second.get();
        const bool on = p.first == wanted;
        // a path switched off keeps no GL buffers (the automatic choice tries every path once);
        // its drawables only: the path's state holds the photon target, which stays
        if (!on && path->getNodeMask() != 0u)
            for (unsigned int i = 0; i < path->getNumChildren(); ++i)
                if (osg::Geode* pass = path->getChild(i)->asGeode())
                    for (unsigned int d = 0; d < pass->getNumDrawables(); ++d) pass->getDrawable(d)->releaseGLObjects(nullptr);
        path->setNodeMask(on ? ~0u : 0u);
    }
}
