#include "passes/RefractionCamera.h"
#include "frame/PassMath.h"
#include <osgWater/WaterSettings>
#include "frame/SceneLighting.h"
#include <osg/CullFace>

using namespace osgWater;

RefractionCamera::RefractionCamera(osg::Group* scene, osg::StateSet* sceneState, int width, int height)
    : PassCamera(scene, { sceneState }, width, height, PASS_REFRACTION)
{
    setName("osgWater.RefractionCamera");
    attachColorTexture();
    _shownColor = _color;
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

    // virtual vertices: the scene drawn where it appears from this very eye
    _virtualVertices = ctx.settings && ctx.settings->getRefractionLookup() == WaterSettings::VIRTUAL_VERTICES &&
                       !ctx.eyeBelow;
    osg::Matrixd view = ctx.view;
    if (ctx.settings && ctx.settings->getRefractionCameraRotation() && !ctx.eyeBelow && !_virtualVertices) {
        const double eta = ctx.settings->getAirIOR() / ctx.settings->getWaterIOR();
        view = rotatedRefractionView(ctx.view, ctx.projection, ctx.level, eta,
                                     ctx.settings->getRefractionCameraApparentEye() ? 1.0 / eta : 1.0);
    }
    double zn = 0.1, zf = 1000.0;
    nearFarForBound(view, ctx.scene, zn, zf);
    // virtual vertices: the water reads the pass at its own pixels, all in the view, so the pass
    // needs no wider field of view; but what lies out of the view can appear in it, so only the
    // keep plane culls
    const osg::Matrixd proj = withNearFar(extendFov(ctx.projection, _virtualVertices ? 1.0 : ctx.fovExtension), zn, zf);
    _draw->setCullingByFrustum(!_virtualVertices);
    setViewMatrix(view);
    setProjectionMatrix(proj);
    // from below this pass sees the air side: where it sees nothing, that is the sky
    setClearColor(ctx.eyeBelow ? ctx.clearColor : osg::Vec4(0.0f, 0.0f, 0.0f, 0.0f));

    osg::StateSet* ss = getOrCreateStateSet();
    const bool truePositions = _virtualVertices && ctx.truePositions;
    setDefineIf(ss, "OSGWATER_VIRTUAL_VERTICES", _virtualVertices);
    setDefineIf(ss, "OSGWATER_TRUE_POSITIONS", truePositions);
    if (truePositions && !_truePositions.valid()) {
        // nearest: a blend of two surfaces' places is neither
        _truePositions = makeTargetTexture(_width, _height, GL_RGBA32F_ARB, GL_RGBA, GL_FLOAT, false);
        _truePositions->setName("osgWater.refractionTruePositions");
    }
    renderColorInto(truePositions ? _truePositions.get() : _shownColor.get());
}

void RefractionCamera::renderColorInto(osg::Texture2D* texture)
{
    if (_color == texture) return;
    _color = texture;
    attach(osg::Camera::COLOR_BUFFER, texture);
    dirtyAttachmentMap(); // the FBO is remade on the next draw
}

void RefractionCamera::resizeGLObjectBuffers(unsigned int maxSize)
{
    PassCamera::resizeGLObjectBuffers(maxSize);
    _shownColor->resizeGLObjectBuffers(maxSize);
    if (_truePositions.valid()) _truePositions->resizeGLObjectBuffers(maxSize);
}

void RefractionCamera::releaseGLObjects(osg::State* state) const
{
    PassCamera::releaseGLObjects(state);
    _shownColor->releaseGLObjects(state); // the one not attached now too
    if (_truePositions.valid()) _truePositions->releaseGLObjects(state);
}
