#include <osgWater/GlowPasses>
#include <osgWater/PassMath>
#include <osgWater/ScreenTriangle>
#include <osgWater/Shaders>
#include <osgWater/WaterSettings>
#include <osgWater/WaterSurface>
#include <osg/BlendFunc>
#include <osg/ColorMask>
#include <osg/Depth>
#include <algorithm>
#include <cmath>

using namespace osgWater;

namespace {

const int kMaxTaps = 32;

osg::Texture2D* glowTarget(int w, int h, bool floatTarget, const char* name)
{
    osg::Texture2D* t = floatTarget ? makeTargetTexture(w, h, GL_RGBA16F_ARB, GL_RGBA, GL_FLOAT, true)
                                    : makeTargetTexture(w, h, GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, true);
    // light blurred off the edge is lost rather than piled up at the border
    t->setWrap(osg::Texture::WRAP_S, osg::Texture::CLAMP_TO_BORDER);
    t->setWrap(osg::Texture::WRAP_T, osg::Texture::CLAMP_TO_BORDER);
    t->setBorderColor(osg::Vec4d(0.0, 0.0, 0.0, 0.0));
    t->setName(name);
    return t;
}

}

GlowPasses::GlowPasses(osg::Group* scene, osg::StateSet* sceneState, osg::StateSet* waterState, int width,
                       int height, bool floatTargets)
    : _width(std::max(width, 1)), _height(std::max(height, 1)), _float(floatTargets)
{
    _highlightTex = glowTarget(_width, _height, _float, "osgWater.glowHighlight");
    _blurTex[0] = glowTarget(_width, _height, _float, "osgWater.glowBlurH");
    _blurTex[1] = glowTarget(_width, _height, _float, "osgWater.glowBlurV");

    _highlight = new osg::Camera;
    _highlight->setName("osgWater.GlowCamera");
    setUpPassTarget(_highlight.get(), _width, _height, PASS_GLOW_HIGHLIGHT);
    _highlight->setClearColor(osg::Vec4(0.0f, 0.0f, 0.0f, 0.0f));
    _highlight->attach(osg::Camera::COLOR_BUFFER, _highlightTex.get());
    _highlight->attach(osg::Camera::DEPTH_BUFFER, GL_DEPTH_COMPONENT24);

    _occluderState = new osg::StateSet;
    _occluderState->setAttribute(new osg::ColorMask(false, false, false, false));
    _glowState = new osg::StateSet;
    _glowState->setAttribute(createProgram("osgWater.glow", "water.vert", "glow.frag"));
    _glowState->addUniform(new osg::Uniform("osgWater_EyeLocal", osg::Vec3f()));
    _glowState->addUniform(new osg::Uniform("osgWater_SunLocal", osg::Vec3f(0.0f, 0.0f, 1.0f)));
    _glowState->addUniform(new osg::Uniform("osgWater_GlowColor", osg::Vec3f(1.0f, 1.0f, 1.0f)));
    _glowState->addUniform(new osg::Uniform("osgWater_GlowExponent", 200.0f));
    _glowState->setDataVariance(osg::Object::DYNAMIC);
    // the water's scene as depth only (it hides the highlight where it is in front of the water),
    // then the surface with the highlight program (set by update())
    _highlightDraw = new DrawNodes;
    _highlightDraw->addChildrenOf(scene, { sceneState, _occluderState.get() });
    _highlightDraw->addNode(nullptr, { waterState, _glowState.get() });
    _highlight->setCullCallback(_highlightDraw.get());

    _blurState = new osg::StateSet;
    _blurState->setAttribute(createProgram("osgWater.glowBlur", "screen.vert", "blur.frag"));
    _blurState->addUniform(new osg::Uniform("osgWater_GlowInput", int(UNIT_PASS_INPUT)));
    _blurState->addUniform(new osg::Uniform(osg::Uniform::FLOAT, "osgWater_GlowWeights", kMaxTaps + 1));
    _blurState->addUniform(new osg::Uniform("osgWater_GlowTaps", 0));
    _blurState->setMode(GL_CULL_FACE, osg::StateAttribute::OFF);
    _blurState->setAttributeAndModes(new osg::Depth(osg::Depth::ALWAYS, 0.0, 1.0, false));
    _blurState->setDataVariance(osg::Object::DYNAMIC);
    _blur[0] = makeBlurCamera(_highlightTex.get(), _blurTex[0].get(), osg::Vec2f(1.0f / _width, 0.0f), PASS_GLOW_BLUR_H);
    _blur[1] = makeBlurCamera(_blurTex[0].get(), _blurTex[1].get(), osg::Vec2f(0.0f, 1.0f / _height), PASS_GLOW_BLUR_V);

    _composite = makeScreenTriangle(-1.0f, "osgWater.glowComposite");
    osg::StateSet* c = _composite->getOrCreateStateSet();
    c->setAttribute(createProgram("osgWater.glowAdd", "screen.vert", "glowadd.frag"));
    c->setTextureAttribute(UNIT_PASS_INPUT, _blurTex[1].get());
    c->addUniform(new osg::Uniform("osgWater_GlowTex", int(UNIT_PASS_INPUT)));
    c->addUniform(new osg::Uniform("osgWater_GlowIntensity", 1.0f));
    c->setAttributeAndModes(new osg::BlendFunc(GL_ONE, GL_ONE));
    c->setAttributeAndModes(new osg::Depth(osg::Depth::ALWAYS, 0.0, 1.0, false));
    c->setMode(GL_CULL_FACE, osg::StateAttribute::OFF);
    c->setRenderBinDetails(renderBin(PASS_GLOW_COMPOSITE), "RenderBin");
    c->setDataVariance(osg::Object::DYNAMIC);
}

osg::Camera* GlowPasses::makeBlurCamera(osg::Texture2D* input, osg::Texture2D* output, const osg::Vec2f& step, PassId pass)
{
    osg::Camera* cam = new osg::Camera;
    cam->setName("osgWater.GlowBlur");
    setUpPassTarget(cam, _width, _height, pass);
    cam->setClearMask(0); // every texel is written
    cam->attach(osg::Camera::COLOR_BUFFER, output);
    cam->setViewMatrix(osg::Matrixd());
    cam->setProjectionMatrix(osg::Matrixd());
    osg::Geode* tri = makeScreenTriangle(-1.0f, "osgWater.glowBlurTriangle");
    osg::StateSet* ss = tri->getOrCreateStateSet();
    ss->setTextureAttribute(UNIT_PASS_INPUT, input);
    ss->addUniform(new osg::Uniform("osgWater_GlowStep", step));
    // both blur passes share the program and the weights' uniforms (merged, not replaced: the
    // camera's own StateSet carries its viewport)
    cam->getOrCreateStateSet()->merge(*_blurState);
    cam->getStateSet()->setDataVariance(osg::Object::DYNAMIC); // the weights follow the settings
    // drawn from a cull callback, as the other passes draw their scenes
    osg::ref_ptr<DrawNodes> draw = new DrawNodes;
    draw->addNode(tri, {});
    cam->setCullCallback(draw.get());
    return cam;
}

std::vector<float> GlowPasses::blurWeights(float radius)
{
    const double r = std::isfinite(radius) ? std::min(std::max(double(radius), 0.0), double(kMaxTaps)) : 0.0;
    const int n = int(std::ceil(r));
    std::vector<float> w(n + 1, 0.0f);
    const double sigma = std::max(r / 2.0, 1e-3);
    double sum = 0.0;
    for (int i = 0; i <= n; ++i) {
        w[i] = float(std::exp(-double(i * i) / (2.0 * sigma * sigma)));
        sum += (i == 0 ? 1.0 : 2.0) * w[i];
    }
    for (float& v : w) v = float(v / sum);
    return w;
}

bool GlowPasses::highlightInView(const PassContext& ctx, const WaterSurface& surface)
{
    const WaterSettings* s = ctx.settings;
    if (!s || !s->getGlowEnabled() || s->getGlowIntensity() <= 0.0f || ctx.eyeBelow) return false;
    const osg::Vec3d L = s->getSunDirection();
    if (!(L.z() > 0.0)) return false;
    if (ctx.projection(3, 3) != 0.0) return true; // orthographic: not worth a cone test
    // the highlight: view directions within theta of the flat water's mirror direction of the sun
    double slope = 1.0; // a user mesh: normals up to 45 degrees
    if (surface.usesGrid()) {
        slope = 0.0;
        for (const Wave& w : surface.getWaves()) slope += std::fabs(double(w.amplitude) * w.wavenumber());
    }
    const double lobe = std::acos(std::pow(1.0 / 1024.0, 1.0 / double(s->getGlowExponent())));
    const double theta = lobe + 2.0 * std::atan(slope);
    if (theta >= osg::PI) return true;
    osg::Vec3d v = osg::Matrixd::transform3x3(osg::Vec3d(L.x(), L.y(), -L.z()), ctx.view);
    v.normalize();
    // the frustum as a cone around its centre ray, wide enough for its corners
    const osg::Matrixd inv = osg::Matrixd::inverse(ctx.projection);
    osg::Vec3d axis = osg::Vec3d(0.0, 0.0, -1.0) * inv;
    axis.normalize();
    double alpha = 0.0;
    for (int i = 0; i < 4; ++i) {
        osg::Vec3d c = osg::Vec3d(i & 1 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, -1.0) * inv;
        c.normalize();
        alpha = std::max(alpha, std::acos(std::min(std::max(c * axis, -1.0), 1.0)));
    }
    const double angle = std::acos(std::min(std::max(v * axis, -1.0), 1.0));
    return angle <= alpha + theta;
}

void GlowPasses::update(const PassContext& ctx, WaterSurface* surface)
{
    _surface = surface;
    _highlightDraw->setNode(1, surface);
    const WaterSettings& s = *ctx.settings;
    osg::BoundingSphere bs = ctx.scene;
    bs.expandBy(surface->getBound());
    double zn = 0.1, zf = 1000.0;
    nearFarForBound(ctx.view, bs, zn, zf);
    _highlight->setViewMatrix(ctx.view);
    _highlight->setProjectionMatrix(withNearFar(ctx.projection, zn, zf));
    _glowState->getUniform("osgWater_EyeLocal")->set(osg::Vec3f(eyePosition(ctx.view)));
    _glowState->getUniform("osgWater_SunLocal")->set(s.getSunDirection());
    _glowState->getUniform("osgWater_GlowColor")->set(s.getSunColor());
    _glowState->getUniform("osgWater_GlowExponent")->set(s.getGlowExponent());

    if (s.getGlowRadius() != _radius) { // the weights change only with the setting
        _radius = s.getGlowRadius();
        setBlurWeights(blurWeights(_radius));
    }
    _composite->getStateSet()->getUniform("osgWater_GlowIntensity")->set(s.getGlowIntensity());
}

void GlowPasses::setBlurWeights(const std::vector<float>& w)
{
    osg::Uniform* wu = _blurState->getUniform("osgWater_GlowWeights");
    for (int i = 0; i <= kMaxTaps; ++i) wu->setElement(i, i < int(w.size()) ? w[i] : 0.0f);
    _blurState->getUniform("osgWater_GlowTaps")->set(int(w.size()) - 1);
}

osg::Camera* GlowPasses::getPassCamera(PassId pass) const
{
    switch (pass) {
    case PASS_GLOW_HIGHLIGHT: return _highlight.get();
    case PASS_GLOW_BLUR_H: return _blur[0].get();
    case PASS_GLOW_BLUR_V: return _blur[1].get();
    default: return nullptr;
    }
}

void GlowPasses::resizeGLObjectBuffers(unsigned int maxSize)
{
    for (osg::Camera* c : { _highlight.get(), _blur[0].get(), _blur[1].get() }) resizePassGLObjectBuffers(c, maxSize);
    _composite->resizeGLObjectBuffers(maxSize);
}

void GlowPasses::releaseGLObjects(osg::State* state) const
{
    for (const osg::Camera* c : { _highlight.get(), _blur[0].get(), _blur[1].get() }) releasePassGLObjects(c, state);
    _composite->releaseGLObjects(state);
}
