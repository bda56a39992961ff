#include "passes/GlowBands.h"
#include "frame/ScreenTriangle.h"
#include <osg/GLExtensions>
#include <osg/Notify>
#include "frame/QueryNames.h"
#include <osg/State>
#include <algorithm>
#include <vector>

using namespace osgWater;

namespace {

// GL_QUERY_WAIT: the GPU waits for the band's count (drawn just before, in an earlier pass), never the CPU
const unsigned int kQueryWait = 0x8E13;

// one band's quad, drawn between the band set's calls around it: counted (the last blur) or drawn
// on its count (the composite)
struct BandDraw : public osg::DrawArrays
{
    osg::observer_ptr<GlowBands> bands;
    int band;
    bool counted;
    BandDraw(GlowBands* b, int k, bool count) : osg::DrawArrays(GL_TRIANGLE_STRIP, 4 * k, 4), bands(b), band(k), counted(count) {}
    void draw(osg::State& state, bool useVertexBufferObjects) const override
    {
        osg::ref_ptr<GlowBands> b = bands.get();
        const bool around = b && (counted ? b->beginCount(state, band) : b->beginConditional(state, band));
        osg::DrawArrays::draw(state, useVertexBufferObjects);
        if (around) counted ? b->endCount(state) : b->endConditional(state);
    }
};

// quads over x in [-1, 1], y in [y0[k], y1[k]] (NDC), one band's primitive set each
osg::Geometry* bandQuads(const std::vector<std::pair<float, float>>& ys, float z, GlowBands* bands, bool counted)
{
    osg::Geometry* g = new osg::Geometry;
    osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array;
    for (const auto& y : ys)
        for (const osg::Vec2f& c : { osg::Vec2f(-1.0f, y.first), osg::Vec2f(1.0f, y.first), osg::Vec2f(-1.0f, y.second),
                                     osg::Vec2f(1.0f, y.second) })
            v->push_back(osg::Vec3(c.x(), c.y(), z));
    g->setVertexArray(v.get());
    for (int k = 0; k < int(ys.size()); ++k) g->addPrimitiveSet(new BandDraw(bands, k, counted));
    setUpScreenGeometry(g); // (no display list: the queries and conditions reach GL each frame)
    return g;
}

}

GlowBands::GlowBands() {}

osg::Geometry* GlowBands::makeCountedBands(int height)
{
    // band k of the composite reads the target's rows from k H / B - 1 to (k + 1) H / B + 1
    // (bilinear): its count covers MARGIN rows each side
    const float h = float(std::max(height, 1));
    std::vector<std::pair<float, float>> ys;
    for (int k = 0; k < BANDS; ++k) {
        const float r0 = std::max(0.0f, k * h / BANDS - MARGIN), r1 = std::min(h, (k + 1) * h / BANDS + MARGIN);
        ys.emplace_back(2.0f * r0 / h - 1.0f, 2.0f * r1 / h - 1.0f);
    }
    return bandQuads(ys, -1.0f, this, true);
}

osg::Geometry* GlowBands::makeConditionalBands(float z)
{
    std::vector<std::pair<float, float>> ys;
    for (int k = 0; k < BANDS; ++k) ys.emplace_back(2.0f * k / BANDS - 1.0f, 2.0f * (k + 1) / BANDS - 1.0f);
    return bandQuads(ys, z, this, false);
}

bool GlowBands::ready(osg::State& state, PerContext& c)
{
    if (c.support == 0) {
        osg::GLExtensions* ext = state.get<osg::GLExtensions>();
        // OSG wraps the queries but not conditional rendering (GL 3.0, or NV_conditional_render)
        c.beginConditionalRender = reinterpret_cast<void (*)(unsigned int, unsigned int)>(
            osg::getGLExtensionFuncPtr("glBeginConditionalRender", "glBeginConditionalRenderNV"));
        c.endConditionalRender = reinterpret_cast<void (*)()>(
            osg::getGLExtensionFuncPtr("glEndConditionalRender", "glEndConditionalRenderNV"));
        const bool yes = ext && ext->glGenQueries && ext->glBeginQuery && ext->glEndQuery && c.beginConditionalRender &&
                         c.endConditionalRender && (ext->glVersion >= 3.0f || osg::isGLExtensionSupported(state.getContextID(), "GL_NV_conditional_render"));
        if (yes) ext->glGenQueries(BANDS, c.ids);
        else OSG_NOTICE << "osgWater: no GL conditional rendering here: the glow is added over the whole view" << std::endl;
        c.support = yes ? 1 : 2;
    }
    return c.support == 1;
}

bool GlowBands::beginCount(osg::State& state, int band)
{
    PerContext& c = _contexts[state.getContextID()];
    if (!_enabled || !ready(state, c)) return false;
    state.get<osg::GLExtensions>()->glBeginQuery(GL_SAMPLES_PASSED_ARB, c.ids[band]);
    c.counted[band] = true;
    return true;
}

void GlowBands::endCount(osg::State& state)
{
    state.get<osg::GLExtensions>()->glEndQuery(GL_SAMPLES_PASSED_ARB);
}

bool GlowBands::beginConditional(osg::State& state, int band)
{
    PerContext& c = _contexts[state.getContextID()];
    if (!_enabled || c.support != 1 || !c.counted[band]) return false;
    c.beginConditionalRender(c.ids[band], kQueryWait);
    return true;
}

void GlowBands::endConditional(osg::State& state)
{
    _contexts[state.getContextID()].endConditionalRender();
}

GlowBands::~GlowBands()
{
    releaseGLObjects(nullptr);
}

void GlowBands::releaseGLObjects(osg::State* state) const
{
    releaseQueryNames(_contexts, state);
}
