#include <osgWater/ReflectionCamera>
#include <osgWater/PassMath>
#include <osgWater/WaterSettings>
#include <osg/FrontFace>

using namespace osgWater;

ReflectionCamera::ReflectionCamera(osg::Group* scene, osg::StateSet* sceneState, int textureSize)
    : PassCamera(scene, sceneState, textureSize)
{
    setName("osgWater.ReflectionCamera");
    attach(osg::Camera::DEPTH_BUFFER, GL_DEPTH_COMPONENT24);
    // the mirror flips winding: keep front faces front
    getOrCreateStateSet()->setAttribute(new osg::FrontFace(osg::FrontFace::CLOCKWISE));
}

void ReflectionCamera::update(const PassContext& ctx)
{
    // keep the eye's side, from just beyond the troughs (crests must not cut the reflection)
    const double s = ctx.eyeBelow ? -1.0 : 1.0;
    setKeepPlane(osg::Plane(0.0, 0.0, s, -s * ctx.level + ctx.clearance));

    const osg::Matrixd view = mirrorMatrix(ctx.level) * ctx.view;
    double zn = 0.1, zf = 1000.0;
    nearFarForBound(view, ctx.scene, zn, zf);
    const osg::Matrixd proj = withNearFar(extendFov(ctx.projection, ctx.fovExtension), zn, zf);
    osg::Vec3 sun = ctx.settings ? ctx.settings->getSunDirection() : osg::Vec3(0.0f, 0.0f, 1.0f);
    setMatrices(view, proj, sun);
    // under water the mirror shows the underwater scene through water (thesis §7.5: eq. 10 with
    // d = |A2 - C2| in this pass), and a ray that meets nothing ends in water
    if (ctx.eyeBelow && ctx.settings) {
        setUnderwaterFog(getOrCreateStateSet(), ctx.settings->getWaterColor(), ctx.settings->getAttenuation());
        setClearColor(osg::Vec4(ctx.settings->getWaterColor(), 1.0f));
    } else {
        setUnderwaterFog(getOrCreateStateSet(), osg::Vec3(), 0.0f);
        setClearColor(ctx.clearColor);
    }
}
