#include <osgWater/Sky>
#include <osgWater/WaterSettings>
#include "frame/PassCamera.h"
#include "frame/ScreenTriangle.h"
#include "settings/Clamp.h"
#include "shaders/Shaders.h"
#include "sky/ClearSky.h"
#include <osg/Depth>
#include <osg/Notify>
#include <osgUtil/CullVisitor>
#include <cmath>

using namespace osgWater;

namespace {
const char* kWho = "osgWater::Sky";
// drawn after the scene's opaque bins (and the water's underlay), before its transparent one (10),
// depth-tested at the far plane and never written: only where nothing opaque was drawn, so the depth
// test spares the sky's fragments behind the scene, and what blends over it comes after it
const int kSkyBin = 9;

// the sky only where it can be seen: a pass that draws the scene for its depth (the sun's depth
// map, the glow's occluders) or its photons must not take its colour, and the refraction from above
// sees only what lies under the water (a full target of sky there, which the scene then covered, was
// a quarter of that pass's fragments on the lake)
struct OnlyWhereTheSkyIsSeen : public osg::DrawableCullCallback
{
    bool cull(osg::NodeVisitor* nv, osg::Drawable*, osg::RenderInfo*) const override
    {
        osgUtil::CullVisitor* cv = nv ? nv->asCullVisitor() : nullptr;
        return cv && !seesTheSky(cv->getCurrentCamera());
    }
};
}

Sky::Sky() : _sun(WaterSettings::defaultSunDirection()), _turbidity(2.5f), _scale(0.06f)
{
    setUp();
}

Sky::Sky(const Sky& other, const osg::CopyOp& copyop)
    : osg::Geode(), _sun(other._sun), _turbidity(other._turbidity), _scale(other._scale)
{
    setName(other.getName());
    (void)copyop; // the triangle and its state are made, never copied
    setUp();
}

void Sky::setUp()
{
    // the triangle and its state are the node's own make, never stored with it (the wrapper writes
    // the settings alone)
    osg::ref_ptr<osg::Geode> triangle = makeScreenTriangle(1.0f, "osgWater.sky");
    osg::Drawable* drawable = triangle->getDrawable(0);
    addDrawable(drawable);
    setCullingActive(false);
    drawable->setCullCallback(new OnlyWhereTheSkyIsSeen);
    osg::StateSet* ss = drawable->getOrCreateStateSet();
    ss->setAttribute(createProgram("osgWater.sky", "screen.vert", "sky.frag"));
    ss->setAttributeAndModes(new osg::Depth(osg::Depth::LEQUAL, 0.0, 1.0, false));
    ss->setRenderBinDetails(kSkyBin, "RenderBin");
    ss->setDataVariance(osg::Object::DYNAMIC);
    for (const char* u : { "osgWater_SkyA", "osgWater_SkyB", "osgWater_SkyC", "osgWater_SkyD", "osgWater_SkyE", "osgWater_SkyZenith",
                           "osgWater_SkySun" })
        ss->addUniform(new osg::Uniform(u, osg::Vec3f()));
    ss->addUniform(new osg::Uniform("osgWater_SkyScale", _scale));
    applyModel();
}

osg::StateSet* Sky::state() { return getDrawable(0)->getStateSet(); }

void Sky::setSunDirection(const osg::Vec3& towardSun)
{
    const float len = towardSun.length();
    if (!std::isfinite(len) || len < 1e-6f) {
        OSG_WARN << kWho << ": sun direction (" << towardSun.x() << " " << towardSun.y() << " " << towardSun.z()
                 << ") is not a direction, keeping (" << _sun.x() << " " << _sun.y() << " " << _sun.z() << ")" << std::endl;
        return;
    }
    _sun = towardSun / len;
    applyModel();
}

void Sky::setTurbidity(float turbidity)
{
    _turbidity = detail::clampOr(kWho, "turbidity", turbidity, float(sky::MIN_TURBIDITY), float(sky::MAX_TURBIDITY), 2.5f);
    applyModel();
}

void Sky::setLuminanceScale(float scale)
{
    _scale = detail::clampOr(kWho, "luminance scale", scale, 0.0f, 1.0e3f, 0.06f);
    state()->getUniform("osgWater_SkyScale")->set(_scale);
}

void Sky::applyModel()
{
    const sky::ClearSky model(glm::dvec3(_sun.x(), _sun.y(), _sun.z()), _turbidity);
    const sky::PerezSet& p = model.perezSet();
    osg::StateSet* ss = state();
    // each coefficient for (x, y, Y), as the zenith's values are ordered
    auto set = [ss](const char* name, double x, double y, double luminance) {
        ss->getUniform(name)->set(osg::Vec3f(float(x), float(y), float(luminance)));
    };
    set("osgWater_SkyA", p.x.a, p.y.a, p.luminance.a);
    set("osgWater_SkyB", p.x.b, p.y.b, p.luminance.b);
    set("osgWater_SkyC", p.x.c, p.y.c, p.luminance.c);
    set("osgWater_SkyD", p.x.d, p.y.d, p.luminance.d);
    set("osgWater_SkyE", p.x.e, p.y.e, p.luminance.e);
    const glm::dvec3 scale = model.zenithScale();
    set("osgWater_SkyZenith", scale.x, scale.y, scale.z);
    const glm::dvec3 sun = model.towardSun();
    set("osgWater_SkySun", sun.x, sun.y, sun.z);
}

osg::Vec3 Sky::getRadiance(const osg::Vec3& direction) const
{
    const sky::ClearSky model(glm::dvec3(_sun.x(), _sun.y(), _sun.z()), _turbidity);
    const glm::dvec3 c = glm::max(model.linearSrgb(glm::dvec3(direction.x(), direction.y(), direction.z())), glm::dvec3(0.0)) * double(_scale);
    return osg::Vec3(float(c.x), float(c.y), float(c.z));
}
