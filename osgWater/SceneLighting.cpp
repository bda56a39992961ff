#include <osgWater/SceneLighting>
#include <osgWater/PassMath>
#include <osgWater/PassTable>
#include <algorithm>
#include <cmath>

using namespace osgWater;

namespace {

template<class T> void setUniform(osg::StateSet* ss, const char* name, const T& value)
{
    if (osg::Uniform* u = ss->getUniform(name)) u->set(value);
    else ss->addUniform(new osg::Uniform(name, value));
}

}

void osgWater::applySceneLighting(osg::StateSet* ss, const SceneLighting& l, const osg::Matrixd& view)
{
    osg::Vec3f sun = osg::Matrixd::transform3x3(l.towardsSun, view);
    sun.normalize();
    setUniform(ss, "osgWater_SunEye", sun);
    setUniform(ss, "osgWater_FogColor", osg::Vec3f(l.fogColor));
    setUniform(ss, "osgWater_FogExtinction", osg::Vec3f(l.fogExtinction));
    setUniform(ss, "osgWater_EyeUnit", float(localLengthPerEyeLength(view)));
    // variants, not branches: a pass without water between its eye and the scene (every pass with
    // the eye above the water) compiles no fog at all (a software rasteriser runs both sides of a branch)
    setDefineIf(ss, "OSGWATER_FOG", l.fogExtinction != osg::Vec3());
    setUniform(ss, "osgWater_WaterPlane", osg::Vec4f(planeToEye(osg::Vec4d(0.0, 0.0, 1.0, -l.level), view)));

    if (l.clip) {
        setUniform(ss, "osgWater_ClipPlane", osg::Vec4f(planeToEye(l.keepPlane.asVec4(), view)));
        ss->setMode(GL_CLIP_PLANE0, osg::StateAttribute::ON); // == GL_CLIP_DISTANCE0
    } else {
        setUniform(ss, "osgWater_ClipPlane", osg::Vec4f(0.0f, 0.0f, 0.0f, 1.0f));
        ss->removeMode(GL_CLIP_PLANE0);
    }

    const CausticsLighting* c = l.caustics;
    // a pass without caustics compiles none of their fetches
    setDefineIf(ss, "OSGWATER_CAUSTICS", c != nullptr);
    setUniform(ss, "osgWater_CausticsIntensity", c ? c->intensity : 0.0f);
    setUniform(ss, "osgWater_EyeToSun", c ? osg::Matrixf(osg::Matrixd::inverse(view) * c->localToSun) : osg::Matrixf());
    setUniform(ss, "osgWater_SunDepthBias", c ? c->depthBias : osg::Vec2f(0.0f, 0.0f));
    setUniform(ss, "osgWater_CausticsChannels", c ? c->channelExtinction : osg::Vec3f());
    setDefineIf(ss, "OSGWATER_CAUSTICS_CHANNELS", c && c->channelExtinction != osg::Vec3f());
    setDefineIf(ss, "OSGWATER_CAUSTICS_TILED", c && c->tiled);
    setUniform(ss, "osgWater_EyeToTile", c && c->tiled ? osg::Matrixf(osg::Matrixd::inverse(view) * c->localToTile) : osg::Matrixf());
    if (c) {
        ss->setTextureAttribute(UNIT_CAUSTICS, c->caustics.get());
        ss->setTextureAttribute(UNIT_SUN_DEPTH, c->depth.get());
    } else {
        ss->removeTextureAttribute(UNIT_CAUSTICS, osg::StateAttribute::TEXTURE);
        ss->removeTextureAttribute(UNIT_SUN_DEPTH, osg::StateAttribute::TEXTURE);
    }

    // the reflected sun: from the sun's mirror image under the water
    const CausticsLighting* r = l.reflectedCaustics;
    setDefineIf(ss, "OSGWATER_REFLECTED_CAUSTICS", r != nullptr);
    osg::Vec3f mirroredSun = osg::Matrixd::transform3x3(osg::Vec3d(l.towardsSun.x(), l.towardsSun.y(), -l.towardsSun.z()), view);
    mirroredSun.normalize();
    setUniform(ss, "osgWater_ReflectedSunEye", mirroredSun);
    setUniform(ss, "osgWater_ReflectedIntensity", r ? r->intensity : 0.0f);
    setUniform(ss, "osgWater_EyeToReflectedSun", r ? osg::Matrixf(osg::Matrixd::inverse(view) * r->localToSun) : osg::Matrixf());
    setUniform(ss, "osgWater_ReflectedDepthBias", r ? r->depthBias : osg::Vec2f(0.0f, 0.0f));
    if (r) {
        ss->setTextureAttribute(UNIT_REFLECTED_CAUSTICS, r->caustics.get());
        ss->setTextureAttribute(UNIT_REFLECTED_SUN_DEPTH, r->depth.get());
    } else {
        ss->removeTextureAttribute(UNIT_REFLECTED_CAUSTICS, osg::StateAttribute::TEXTURE);
        ss->removeTextureAttribute(UNIT_REFLECTED_SUN_DEPTH, osg::StateAttribute::TEXTURE);
    }
}

float osgWater::photonExtinction(const WaterSettings& s) { return s.getSunExtinction().y(); }

osg::Vec3f osgWater::channelExtinction(const WaterSettings& s)
{
    const osg::Vec3 K = s.getSunExtinction();
    const float green = photonExtinction(s);
    // the sun's path below a level surface: depth / cos of the refracted angle (Snell)
    const float sinI = std::sqrt(std::max(0.0f, 1.0f - s.getSunDirection().z() * s.getSunDirection().z()));
    const float sinT = std::min(1.0f, sinI * s.getAirIOR() / s.getWaterIOR());
    const float cosT = std::max(std::sqrt(1.0f - sinT * sinT), 0.05f);
    return osg::Vec3f(K.x() - green, K.y() - green, K.z() - green) / cosT;
}

void osgWater::setDefineIf(osg::StateSet* ss, const char* name, bool on)
{
    if (on) ss->setDefine(name);
    else ss->removeDefine(name);
}
