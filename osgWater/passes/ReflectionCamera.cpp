#include "passes/ReflectionCamera.h"
#include "frame/PassMath.h"
#include <osgWater/WaterSettings>
#include <osg/FrontFace>

using namespace osgWater;

ReflectionCamera::ReflectionCamera(osg::Group* scene, osg::StateSet* sceneState, int width, int height)
    : PassCamera(scene, { sceneState }, width, height, PASS_REFLECTION)
{
    setName("osgWater.ReflectionCamera");
    attachColorTexture(true); // mipmapped: the water reads it blurred by the slopes below its pixels
    attachDepthTexture(); // the mirror search reads it
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
    setViewMatrix(view);
    setProjectionMatrix(proj);
    // under water a ray that meets nothing ends in water (the fog of eq. 10 comes with the lighting)
    setClearColor(ctx.eyeBelow && ctx.settings ? osg::Vec4(ctx.settings->getBodyColor(), 1.0f) : ctx.clearColor);
}
