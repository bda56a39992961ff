#include "passes/GlowPasses.h"
#include "surface/SpectralWaves.h"
#include "shaders/ProgramLibrary.h"
#include "frame/PassMath.h"
#include "frame/ScreenTriangle.h"
#include "shaders/Shaders.h"
#include <osgWater/WaterSettings>
#include <osgWater/WaterSurface>
#include <osg/BlendFunc>
#include <osg/ColorMask>
#include <osg/Depth>
#include <algorithm>
#include <cmath>
#include <limits>

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

GlowPasses::GlowPasses(osg::Group* scene, osg::StateSet* sceneState, osg::StateSet* waterState,
                       ProgramLibrary& programs, int width, int height, bool floatTargets)
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
    // its viewport follows the highlight every frame: OSG must not draw it while the next cull writes
    _highlight->getOrCreateStateSet()->setDataVariance(osg::Object::DYNAMIC);

    // occluders write depth only: the depth program places them exactly as the scene program does
    // (and clips them alike) without its per-vertex lighting
    _occluderState = new osg::StateSet;
    _occluderState->setAttribute(new osg::ColorMask(false, false, false, false));
    _occluderState->setAttribute(programs.get("osgWater.depth", "depth.vert", "depth.frag"));
    _glowState = new osg::StateSet;
    _glowState->setAttribute(programs.get("osgWater.glow", "water.vert", "glow.frag"));
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
    _blurState->setAttribute(programs.get("osgWater.glowBlur", "screen.vert", "blur.frag"));
    _blurState->addUniform(new osg::Uniform("osgWater_GlowInput", int(UNIT_PASS_INPUT)));
    _blurState->addUniform(new osg::Uniform(osg::Uniform::FLOAT, "osgWater_GlowWeights", kMaxTaps + 1));
    _blurState->setMode(GL_CULL_FACE, osg::StateAttribute::OFF);
    _blurState->setAttributeAndModes(new osg::Depth(osg::Depth::ALWAYS, 0.0, 1.0, false));
    _blurScissor = new osg::Scissor(0, 0, _width, _height);
    _blurState->setAttributeAndModes(_blurScissor.get());
    _blurState->setDataVariance(osg::Object::DYNAMIC);
    _glowTexels.set(0, 0, _width, _height);
    // the last blur counts, band by band, where the glow shows; the composite adds it only there
    _bands = new GlowBands;
    _blur[0] = makeBlurCamera(_highlightTex.get(), _blurTex[0].get(), osg::Vec2f(1.0f / _width, 0.0f), PASS_GLOW_BLUR_H,
                              makeScreenTriangle(-1.0f, "osgWater.glowBlurTriangle"));
    osg::ref_ptr<osg::Geode> counted = new osg::Geode;
    counted->setName("osgWater.glowBlurBands");
    counted->addDrawable(_bands->makeCountedBands(_height));
    _blur[1] = makeBlurCamera(_blurTex[0].get(), _blurTex[1].get(), osg::Vec2f(0.0f, 1.0f / _height), PASS_GLOW_BLUR_V,
                              counted.get());
    // its texels too faint to show are left at the cleared zero, so a band of them counts none
    _blur[1]->getStateSet()->setDefine("OSGWATER_GLOW_CUT");
    _blur[1]->getStateSet()->addUniform(new osg::Uniform("osgWater_GlowCut", 0.0f));

    _composite = new osg::Geode;
    _composite->setName("osgWater.glowComposite");
    _composite->addDrawable(_bands->makeConditionalBands(-1.0f));
    _composite->setCullingActive(false);
    osg::StateSet* c = _composite->getOrCreateStateSet();
    c->setAttribute(programs.get("osgWater.glowAdd", "screen.vert", "glowadd.frag"));
    c->setTextureAttribute(UNIT_PASS_INPUT, _blurTex[1].get());
    c->addUniform(new osg::Uniform("osgWater_GlowTex", int(UNIT_PASS_INPUT)));
    c->addUniform(new osg::Uniform("osgWater_GlowIntensity", 1.0f));
    c->setAttributeAndModes(new osg::BlendFunc(GL_ONE, GL_ONE));
    // the glow is linear light: where the view's framebuffer stores sRGB, GL decodes the finished
    // image, adds, and encodes again; elsewhere the glow adds to display values
    c->setMode(GL_FRAMEBUFFER_SRGB, osg::StateAttribute::ON);
    c->setAttributeAndModes(new osg::Depth(osg::Depth::ALWAYS, 0.0, 1.0, false));
    c->setMode(GL_CULL_FACE, osg::StateAttribute::OFF);
    setUpPassBin(c, PASS_GLOW_COMPOSITE);
    _compositeScissor = new osg::Scissor(0, 0, 1, 1);
    c->setAttributeAndModes(_compositeScissor.get());

    // timed when the view's pass timing is on; the callbacks are set once, before any draw
    _highlightMeter = new PassMeter;
    _highlightMeter->attach(_highlight.get());
    _blurMeter = new PassMeter;
    _blurMeter->attach(_blur[0].get(), _blur[1].get());
    _compositeMeter = new PassMeter;
    _compositeMeter->attach(_composite->getDrawable(0));
    setTimingEnabled(false);
    c->setDataVariance(osg::Object::DYNAMIC);
}

osg::Camera* GlowPasses::makeBlurCamera(osg::Texture2D* input, osg::Texture2D* output, const osg::Vec2f& step, PassId pass,
                                       osg::Geode* screen)
{
    osg::Camera* cam = new osg::Camera;
    cam->setName("osgWater.GlowBlur");
    setUpPassTarget(cam, _width, _height, pass);
    // cleared whole, then written only where the glow can be (the scissor): what the next pass
    // reads beyond it is the true zero
    cam->setClearMask(GL_COLOR_BUFFER_BIT);
    cam->setClearColor(osg::Vec4(0.0f, 0.0f, 0.0f, 0.0f));
    cam->attach(osg::Camera::COLOR_BUFFER, output);
    cam->setViewMatrix(osg::Matrixd());
    cam->setProjectionMatrix(osg::Matrixd());
    osg::StateSet* ss = screen->getOrCreateStateSet();
    ss->setTextureAttribute(UNIT_PASS_INPUT, input);
    ss->addUniform(new osg::Uniform("osgWater_GlowStep", step));
    // both blur passes share the program, the weights' uniforms and the scissor (merged, not
    // replaced: the camera's own StateSet carries its viewport)
    cam->getOrCreateStateSet()->merge(*_blurState);
    cam->getStateSet()->setDataVariance(osg::Object::DYNAMIC); // the weights follow the settings
    // drawn from a cull callback, as the other passes draw their scenes
    osg::ref_ptr<DrawNodes> draw = new DrawNodes;
    draw->addNode(screen, {});
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

namespace {

// The highlight: view directions within theta of the flat water's mirror direction of the sun v
// (eye space), theta the width of pow(R.E, e) above 1/1024 widened by twice the steepest slope the
// waves can reach (a normal tilted by a turns the mirror direction by 2a). Under the wind the lobe
// is the widest the shader draws: e' = e / (1 + 2 e sigma^2) with every slope roughness (a pixel
// wider than every tile); where some are drawn instead, the steepest slope's term covers them.
double highlightCone(const PassContext& ctx, const WaterSurface& surface, osg::Vec3d& v)
{
    const WaterSettings& s = *ctx.settings;
    const double slope = surface.getMaxSlope();
    double e = s.getGlowExponent();
    if (const detail::SpectralWaves* wind = surface.getSpectralWaves()) e /= 1.0 + 2.0 * e * wind->meanSquareSlope();
    const double lobe = std::acos(std::pow(1.0 / 1024.0, 1.0 / e));
    const osg::Vec3d L = s.getSunDirection();
    v = osg::Matrixd::transform3x3(osg::Vec3d(L.x(), L.y(), -L.z()), ctx.view);
    v.normalize();
    return lobe + 2.0 * std::atan(slope);
}

// grows `rect` (x0, y0, x1, y1) to hold the projection of the eye-space point p; false when p is
// not in front of the eye
bool addProjected(osg::Vec4d& rect, const osg::Vec3d& p, const osg::Matrixd& projection)
{
    if (!(p.z() < -1e-9)) return false;
    const osg::Vec4d c = osg::Vec4d(p, 1.0) * projection;
    if (!(c.w() > 0.0)) return false;
    const double x = c.x() / c.w(), y = c.y() / c.w();
    rect.set(std::min(rect.x(), x), std::min(rect.y(), y), std::max(rect.z(), x), std::max(rect.w(), y));
    return true;
}

const osg::Vec4d kWholeView(-1.0, -1.0, 1.0, 1.0);

}

osg::Vec4d GlowPasses::highlightRect(const PassContext& ctx, const WaterSurface& surface)
{
    if (!ctx.settings || ctx.projection(3, 3) != 0.0) return kWholeView; // orthographic: the whole view
    osg::Vec3d v;
    const double theta = highlightCone(ctx, surface, v) * 1.02; // a little wider: 64 samples of its rim
    if (theta >= 0.5 * osg::PI - 1e-3) return kWholeView;
    osg::Vec3d a = std::fabs(v.x()) < 0.9 ? v ^ osg::Vec3d(1.0, 0.0, 0.0) : v ^ osg::Vec3d(0.0, 1.0, 0.0);
    a.normalize();
    const osg::Vec3d b = v ^ a;
    const double big = std::numeric_limits<double>::max();
    osg::Vec4d cone(big, big, -big, -big);
    for (int k = 0; k < 64; ++k) {
        const double phi = 2.0 * osg::PI * k / 64.0;
        const osg::Vec3d d = v * std::cos(theta) + (a * std::cos(phi) + b * std::sin(phi)) * std::sin(theta);
        if (!addProjected(cone, d, ctx.projection)) return kWholeView; // the cone reaches behind the eye
    }
    // only where the water is: its box's corners projected
    const osg::BoundingBox& box = surface.getBoundingBox();
    osg::Vec4d water(big, big, -big, -big);
    bool waterInFront = box.valid();
    for (int i = 0; i < 8 && waterInFront; ++i) waterInFront = addProjected(water, box.corner(i) * ctx.view, ctx.projection);
    osg::Vec4d r(std::max(cone.x(), -1.0), std::max(cone.y(), -1.0), std::min(cone.z(), 1.0), std::min(cone.w(), 1.0));
    if (waterInFront)
        r.set(std::max(r.x(), water.x()), std::max(r.y(), water.y()), std::min(r.z(), water.z()), std::min(r.w(), water.w()));
    return r;
}

bool GlowPasses::highlightInView(const PassContext& ctx, const WaterSurface& surface)
{
    const WaterSettings* s = ctx.settings;
    if (!s || !s->getGlowEnabled() || s->getGlowIntensity() <= 0.0f || ctx.eyeBelow) return false;
    const osg::Vec3d L = s->getSunDirection();
    if (!(L.z() > 0.0)) return false;
    if (ctx.projection(3, 3) != 0.0) return true; // orthographic: not worth a cone test
    osg::Vec3d v;
    const double theta = highlightCone(ctx, surface, v);
    if (theta >= osg::PI) return true;
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

void GlowPasses::update(const PassContext& ctx, WaterSurface* surface, const osg::Viewport& viewport, bool confine)
{
    _surface = surface;
    _highlightDraw->setNode(1, surface);
    const WaterSettings& s = *ctx.settings;
    osg::BoundingSphere bs = ctx.scene;
    bs.expandBy(surface->getBound());
    double zn = 0.1, zf = 1000.0;
    nearFarForBound(ctx.view, bs, zn, zf);
    _highlight->setViewMatrix(ctx.view);
    // the eye is above the water (no glow below it): what lies wholly below the troughs cannot hide
    // the surface from it, so it is not drawn as an occluder
    _highlightDraw->setCullingPlane(osg::Plane(0.0, 0.0, 1.0, -(ctx.level - ctx.clearance)));
    const osg::Matrixd projection = withNearFar(ctx.projection, zn, zf);

    // the texels the glow can reach: the highlight's, grown by the blur on each side
    const osg::Vec4d ndc = confine ? highlightRect(ctx, *surface) : kWholeView;
    const int reach = int(std::ceil(std::max(0.0f, s.getGlowRadius()))) + 1;
    auto texels = [&](int grow) {
        const int x0 = std::max(0, int(std::floor((ndc.x() + 1.0) * 0.5 * _width)) - grow);
        const int y0 = std::max(0, int(std::floor((ndc.y() + 1.0) * 0.5 * _height)) - grow);
        const int x1 = std::min(_width, int(std::ceil((ndc.z() + 1.0) * 0.5 * _width)) + grow);
        const int y1 = std::min(_height, int(std::ceil((ndc.w() + 1.0) * 0.5 * _height)) + grow);
        return osg::Vec4i(x0, y0, std::max(1, x1 - x0), std::max(1, y1 - y0));
    };
    // the highlight pass draws (and clears) every texel the blur reads: a sub-viewport with the
    // matching sub-frustum, so occluders outside it are culled
    const osg::Vec4i drawn = texels(2 * reach);
    _highlight->setViewport(drawn.x(), drawn.y(), drawn.z(), drawn.w());
    const double X0 = 2.0 * drawn.x() / _width - 1.0, X1 = 2.0 * (drawn.x() + drawn.z()) / _width - 1.0;
    const double Y0 = 2.0 * drawn.y() / _height - 1.0, Y1 = 2.0 * (drawn.y() + drawn.w()) / _height - 1.0;
    _highlight->setProjectionMatrix(projection * osg::Matrixd::translate(-0.5 * (X0 + X1), -0.5 * (Y0 + Y1), 0.0) *
                                    osg::Matrixd::scale(2.0 / (X1 - X0), 2.0 / (Y1 - Y0), 1.0));
    // the blur and the composite write only where the glow can be non-zero
    _glowTexels = texels(reach);
    _blurScissor->setScissor(_glowTexels.x(), _glowTexels.y(), _glowTexels.z(), _glowTexels.w());
    const double sx = viewport.width() / _width, sy = viewport.height() / _height;
    const int cx0 = int(std::floor(viewport.x() + _glowTexels.x() * sx));
    const int cy0 = int(std::floor(viewport.y() + _glowTexels.y() * sy));
    const int cx1 = int(std::ceil(viewport.x() + (_glowTexels.x() + _glowTexels.z()) * sx));
    const int cy1 = int(std::ceil(viewport.y() + (_glowTexels.y() + _glowTexels.w()) * sy));
    _compositeScissor->setScissor(cx0, cy0, std::max(1, cx1 - cx0), std::max(1, cy1 - cy0));
    _glowState->getUniform("osgWater_EyeLocal")->set(osg::Vec3f(eyePosition(ctx.view)));
    _glowState->getUniform("osgWater_SunLocal")->set(s.getSunDirection());
    _glowState->getUniform("osgWater_GlowColor")->set(s.getSunColor());
    _glowState->getUniform("osgWater_GlowExponent")->set(s.getGlowExponent());

    if (s.getGlowRadius() != _radius) { // the weights change only with the setting
        _radius = s.getGlowRadius();
        setBlurWeights(blurWeights(_radius));
    }
    _composite->getStateSet()->getUniform("osgWater_GlowIntensity")->set(s.getGlowIntensity());
    // the cut: the composite adds intensity x glow, which changes no display value by half a level
    // below it, even on black where the sRGB curve is steepest (12.92 display per linear unit)
    _bands->setEnabled(confine);
    // (an 8-bit target rounds anything under half its level to that zero anyway)
    const float visible = 0.5f / 255.0f / (12.92f * std::max(s.getGlowIntensity(), 1e-6f));
    const float cut = !confine ? 0.0f : _float ? visible : std::max(visible, 0.49f / 255.0f);
    _blur[1]->getStateSet()->getUniform("osgWater_GlowCut")->set(cut);
}

void GlowPasses::setTimingEnabled(bool on)
{
    for (PassMeter* t : { _highlightMeter.get(), _blurMeter.get(), _compositeMeter.get() }) t->setEnabled(on);
}

void GlowPasses::setBlurWeights(const std::vector<float>& w)
{
    osg::Uniform* wu = _blurState->getUniform("osgWater_GlowWeights");
    for (int i = 0; i <= kMaxTaps; ++i) wu->setElement(i, i < int(w.size()) ? w[i] : 0.0f);
    // a define is a value in each state set, not a shared object like the uniforms: set on both cameras
    for (osg::Camera* c : { _blur[0].get(), _blur[1].get() })
        c->getStateSet()->setDefine("OSGWATER_GLOW_TAPS", std::to_string(int(w.size()) - 1));
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
    _bands->releaseGLObjects(state);
    for (const PassMeter* m : { _highlightMeter.get(), _blurMeter.get(), _compositeMeter.get() }) m->releaseGLObjects(state);
}
