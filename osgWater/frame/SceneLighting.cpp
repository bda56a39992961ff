#include "frame/SceneLighting.h"
#include "frame/PassMath.h"
#include "frame/PassTable.h"
#include <algorithm>
#include <cmath>

using namespace osgWater;

namespace {

// a texture on a unit, or none there
void setTextureIf(osg::StateSet* ss, int unit, osg::Texture* texture)
{
    if (texture) ss->setTextureAttribute(unit, texture);
    else ss->removeTextureAttribute(unit, osg::StateAttribute::TEXTURE);
}

}

void osgWater::applySceneLighting(osg::StateSet* ss, const SceneLighting& l, const osg::Matrixd& view)
{
    osg::Vec3f sun = osg::Matrixd::transform3x3(l.towardsSun, view);
    sun.normalize();
    setOrAddUniform(ss, "osgWater_SunEye", sun);
    setOrAddUniform(ss, "osgWater_FogColor", osg::Vec3f(l.fogColor));
    setOrAddUniform(ss, "osgWater_FogExtinction", osg::Vec3f(l.fogExtinction));
    setOrAddUniform(ss, "osgWater_EyeUnit", float(localLengthPerEyeLength(view)));
    // the water's frame in the pass (virtual vertices, procedural caustics)
    setOrAddUniform(ss, "osgWater_EyeToLocal", osg::Matrixf(osg::Matrixd::inverse(view)));
    setOrAddUniform(ss, "osgWater_LocalToEye", osg::Matrixf(view));
    // variants, not branches: a pass without water between its eye and the scene (every pass with
    // the eye above the water) compiles no fog at all (a software rasteriser runs both sides of a branch)
    setDefineIf(ss, "OSGWATER_FOG", l.fogExtinction != osg::Vec3());
    // a pass's target holds linear light; switched off, not removed: the passes of a water inside
    // another water's scene are culled under that view's own lighting, and would inherit its define
    ss->setDefine("OSGWATER_DISPLAY", l.display ? osg::StateAttribute::ON : osg::StateAttribute::OFF);
    setOrAddUniform(ss, "osgWater_WaterPlane", osg::Vec4f(planeToEye(osg::Vec4d(0.0, 0.0, 1.0, -l.level), view)));

    if (l.clip) {
        setOrAddUniform(ss, "osgWater_ClipPlane", osg::Vec4f(planeToEye(l.keepPlane.asVec4(), view)));
        ss->setMode(GL_CLIP_PLANE0, osg::StateAttribute::ON); // == GL_CLIP_DISTANCE0
    } else {
        setOrAddUniform(ss, "osgWater_ClipPlane", osg::Vec4f(0.0f, 0.0f, 0.0f, 1.0f));
        ss->removeMode(GL_CLIP_PLANE0);
    }

    const CausticsLighting* c = l.caustics;
    // a pass without caustics compiles none of their fetches
    setDefineIf(ss, "OSGWATER_CAUSTICS", c != nullptr);
    setOrAddUniform(ss, "osgWater_CausticsIntensity", c ? c->intensity : 0.0f);
    setOrAddUniform(ss, "osgWater_EyeToSun", c ? osg::Matrixf(osg::Matrixd::inverse(view) * c->localToSun) : osg::Matrixf());
    setOrAddUniform(ss, "osgWater_SunDepthBias", c ? c->depthBias : osg::Vec2f(0.0f, 0.0f));
    setOrAddUniform(ss, "osgWater_CausticsChannels", c ? c->channelExtinction : osg::Vec3f());
    setDefineIf(ss, "OSGWATER_CAUSTICS_CHANNELS", c && c->channelExtinction != osg::Vec3f());
    setDefineIf(ss, "OSGWATER_CAUSTICS_TILED", c && c->tiled);
    setOrAddUniform(ss, "osgWater_EyeToTile", c && c->tiled ? osg::Matrixf(osg::Matrixd::inverse(view) * c->localToTile) : osg::Matrixf());
    setTextureIf(ss, UNIT_CAUSTICS, c && !c->procedural ? c->caustics.get() : nullptr);
    setTextureIf(ss, UNIT_SUN_DEPTH, c ? c->depth.get() : nullptr);
    // the procedural caustics made here: the construction's inputs (the waves, indices, Fresnel and
    // extinction come with the scene's StateSet)
    const bool procedural = c && c->procedural;
    setDefineIf(ss, "OSGWATER_CAUSTICS_PROCEDURAL", procedural);
    setDefineIf(ss, "OSGWATER_PROCEDURAL_SHADE", procedural && c->shade.valid());
    setOrAddUniform(ss, "osgWater_TowardsSunLocal", l.towardsSun);
    setOrAddUniform(ss, "osgWater_SunView", procedural ? osg::Matrixf(c->sunView) : osg::Matrixf());
    if (procedural && c->shade.valid()) applySunShade(ss, c->shade.get(), UNIT_SUN_SHADE, c->shadeProjection);
    else setTextureIf(ss, UNIT_SUN_SHADE, nullptr);

    // the reflected sun: from the sun's mirror image under the water
    const CausticsLighting* r = l.reflectedCaustics;
    setDefineIf(ss, "OSGWATER_REFLECTED_CAUSTICS", r != nullptr);
    osg::Vec3f mirroredSun = osg::Matrixd::transform3x3(osg::Vec3d(l.towardsSun.x(), l.towardsSun.y(), -l.towardsSun.z()), view);
    mirroredSun.normalize();
    setOrAddUniform(ss, "osgWater_ReflectedSunEye", mirroredSun);
    setOrAddUniform(ss, "osgWater_ReflectedIntensity", r ? r->intensity : 0.0f);
    setOrAddUniform(ss, "osgWater_EyeToReflectedSun", r ? osg::Matrixf(osg::Matrixd::inverse(view) * r->localToSun) : osg::Matrixf());
    setOrAddUniform(ss, "osgWater_ReflectedDepthBias", r ? r->depthBias : osg::Vec2f(0.0f, 0.0f));
    setTextureIf(ss, UNIT_REFLECTED_CAUSTICS, r ? r->caustics.get() : nullptr);
    setTextureIf(ss, UNIT_REFLECTED_SUN_DEPTH, r ? r->depth.get() : nullptr);
}

void osgWater::applySunShade(osg::StateSet* ss, osg::Texture2D* shade, int unit, const osg::Matrixd& projection)
{
    ss->setTextureAttribute(unit, shade);
    setOrAddUniform(ss, "osgWater_SunShade", unit);
    setOrAddUniform(ss, "osgWater_SunShadeProj", osg::Matrixf(projection));
}

float osgWater::photonExtinction(const WaterSettings& s) { return s.getSunExtinction().y(); }

osg::Vec3f osgWater::channelExtinction(const WaterSettings& s, bool whole)
{
    const osg::Vec3 K = s.getSunExtinction();
    const float green = whole ? 0.0f : photonExtinction(s);
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
