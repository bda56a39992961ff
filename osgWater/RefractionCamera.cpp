#include <osgWater/RefractionCamera>
#include <osgWater/PassMath>
#include <osgWater/WaterSettings>
#include <osg/CullFace>

using namespace osgWater;

RefractionCamera::RefractionCamera(osg::Group* scene, osg::StateSet* sceneState, int width, int height)
    : PassCamera(scene, { sceneState }, width, height, PASS_REFRACTION)
{
    setName("osgWater.RefractionCamera");
    attachColorTexture();
    attachDepthTexture();
    // thesis fig. 3: clipped solids must not show their insides
    getOrCreateStateSet()->setAttributeAndModes(new osg::CullFace(osg::CullFace::BACK), osg::StateAttribute::ON);
    setClearColor(osg::Vec4(0.0f, 0.0f, 0.0f, 0.0f));
}

void RefractionCamera::update(const PassContext& ctx)
{
    // keep the far side, up to just beyond the crests
    const double s = ctx.eyeBelow ? 1.0 : -1.0;
    setKeepPlane(osg::Plane(0.0, 0.0, s, -s * ctx.level + ctx.clearance));

    osg::Matrixd view = ctx.view;
    if (ctx.settings && ctx.settings->getRefractionCameraRotation() && !ctx.eyeBelow) {
        const double eta = ctx.settings->getAirIOR() / ctx.settings->getWaterIOR();
        view = rotatedRefractionView(ctx.view, ctx.projection, ctx.level, eta,
                                     ctx.settings->getRefractionCameraApparentEye() ? 1.0 / eta : 1.0);
    }
    double zn = 0.1, zf = 1000.0;
    nearFarForBound(view, ctx.scene, zn, zf);
    const osg::Matrixd proj = withNearFar(extendFov(ctx.projection, ctx.fovExtension), zn, zf);
    setViewMatrix(view);
    setProjectionMatrix(proj);
    // from below this pass sees the air side: where it sees nothing, that is the sky
    setClearColor(ctx.eyeBelow ? ctx.clearColor : osg::Vec4(0.0f, 0.0f, 0.0f, 0.0f));
}
