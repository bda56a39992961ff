#include "frame/PassCamera.h"
#include <algorithm>
#include <osg/ValueObject>
#include "frame/PassMath.h"

using namespace osgWater;

namespace {
const char* const kWaterPassKey = "osgWater.pass"; // user value: the PassId of a water's pass camera
}

PassCamera::PassCamera(osg::Group* scene, std::initializer_list<osg::StateSet*> sceneStates, int width, int height,
                       PassId pass)
    : _pass(pass), _width(width), _height(height), _keepPlane(0.0, 0.0, 1.0, 0.0)
{
    setUpPassTarget(this, width, height, pass);
    _draw = new DrawNodes;
    _draw->addChildrenOf(scene, sceneStates);
    _draw->setCullingPlane(_keepPlane);
    setCullCallback(_draw.get());
    // lighting, clip plane and fog change every frame: OSG must not draw it while the next frame's cull writes
    getOrCreateStateSet()->setDataVariance(osg::Object::DYNAMIC);
}

void PassCamera::attachColorTexture(bool mipmapped)
{
    // linear light: 8 bits would band in the darks, where the eye sees the steps (half floats keep
    // every display level of a smooth gradient)
    _color = makeTargetTexture(_width, _height, GL_RGBA16F_ARB, GL_RGBA, GL_FLOAT, true);
    _color->setName("osgWater.passColor");
    if (mipmapped) {
        // OSG makes an image-less texture's storage with one level unless told how many, and the
        // attachment's flag fills only the levels there are
        unsigned int levels = 1;
        while ((std::max(_width, _height) >> levels) > 0) ++levels;
        _color->setNumMipmapLevels(levels);
        _color->setFilter(osg::Texture::MIN_FILTER, osg::Texture::LINEAR_MIPMAP_LINEAR);
    }
    attach(osg::Camera::COLOR_BUFFER, _color.get(), 0, 0, mipmapped);
}

void PassCamera::attachDepthTexture()
{
    // nearest: a search reads depths, and a blend of two surfaces' depths is neither
    _depth = makeTargetTexture(_width, _height, GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT, GL_FLOAT, false);
    _depth->setName("osgWater.passDepth");
    attach(osg::Camera::DEPTH_BUFFER, _depth.get());
}

void PassCamera::setDepthOnly()
{
    setClearMask(GL_DEPTH_BUFFER_BIT);
    setDrawBuffer(GL_NONE);
    setReadBuffer(GL_NONE);
    attachDepthTexture();
}

osg::Texture2D* osgWater::makeTargetTexture(int size, GLenum internalFormat, GLenum format, GLenum type, bool linear)
{
    return makeTargetTexture(size, size, internalFormat, format, type, linear);
}

osg::Texture2D* osgWater::makeTargetTexture(int width, int height, GLenum internalFormat, GLenum format, GLenum type,
                                            bool linear)
{
    osg::Texture2D* t = new osg::Texture2D;
    t->setTextureSize(width, height);
    t->setInternalFormat(internalFormat);
    t->setSourceFormat(format);
    t->setSourceType(type);
    const osg::Texture::FilterMode f = linear ? osg::Texture::LINEAR : osg::Texture::NEAREST;
    t->setFilter(osg::Texture::MIN_FILTER, f);
    t->setFilter(osg::Texture::MAG_FILTER, f);
    t->setWrap(osg::Texture::WRAP_S, osg::Texture::CLAMP_TO_EDGE);
    t->setWrap(osg::Texture::WRAP_T, osg::Texture::CLAMP_TO_EDGE);
    return t;
}

void osgWater::setUpPassTarget(osg::Camera* camera, int width, int height, PassId pass)
{
    camera->setRenderOrder(osg::Camera::PRE_RENDER, renderOrder(pass));
    camera->setRenderTargetImplementation(osg::Camera::FRAME_BUFFER_OBJECT);
    camera->setReferenceFrame(osg::Camera::ABSOLUTE_RF);
    // near/far come from the scene bound (PassMath), so a depth texture's projection is known exactly
    camera->setComputeNearFarMode(osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR);
    camera->setClearMask(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    camera->setViewport(0, 0, width, height);
    camera->setUserValue(kWaterPassKey, int(pass));
}

void osgWater::setUpPassBin(osg::StateSet* ss, PassId pass)
{
    ss->setRenderBinDetails(renderBin(pass), "RenderBin");
    ss->setNestRenderBins(false); // nested, a bin -1 or 20 would sort within the parent's bin
}

bool osgWater::isWaterPass(const osg::Camera* camera)
{
    int pass;
    return camera && camera->getUserValue(kWaterPassKey, pass);
}

bool osgWater::drawsSceneColours(const osg::Camera* camera)
{
    int pass;
    if (!camera || !camera->getUserValue(kWaterPassKey, pass)) return true;
    return pass == PASS_ENVIRONMENT || pass == PASS_REFLECTION || pass == PASS_REFRACTION;
}

bool osgWater::seesTheSky(const osg::Camera* camera)
{
    if (!drawsSceneColours(camera)) return false;
    const PassCamera* pass = dynamic_cast<const PassCamera*>(camera);
    return !pass || !(pass->getKeepPlane().getNormal().z() < 0.0);
}

void PassCamera::setKeepPlane(const osg::Plane& localPlane)
{
    _keepPlane = localPlane;
    _draw->setCullingPlane(localPlane);
}

void PassCamera::applyLighting(const SceneLighting& lighting)
{
    SceneLighting l = lighting;
    l.clip = true;
    l.display = false; // a target the water reads: linear light
    l.keepPlane = _keepPlane;
    applySceneLighting(getOrCreateStateSet(), l, getViewMatrix());
}

void PassCamera::resizeGLObjectBuffers(unsigned int maxSize)
{
    resizePassGLObjectBuffers(this, maxSize);
}

void PassCamera::releaseGLObjects(osg::State* state) const
{
    releasePassGLObjects(this, state);
}

void osgWater::releasePassGLObjects(const osg::Camera* camera, osg::State* state)
{
    camera->osg::Camera::releaseGLObjects(state);
    if (const osg::StateSet* ss = camera->getStateSet()) ss->releaseGLObjects(state);
    if (const DrawNodes* draw = dynamic_cast<const DrawNodes*>(camera->getCullCallback())) draw->releaseGLObjects(state);
    for (const auto& a : camera->getBufferAttachmentMap())
        if (a.second._texture.valid()) a.second._texture->releaseGLObjects(state);
}

void osgWater::resizePassGLObjectBuffers(osg::Camera* camera, unsigned int maxSize)
{
    camera->osg::Camera::resizeGLObjectBuffers(maxSize);
    if (osg::StateSet* ss = camera->getStateSet()) ss->resizeGLObjectBuffers(maxSize);
    if (DrawNodes* draw = dynamic_cast<DrawNodes*>(camera->getCullCallback())) draw->resizeGLObjectBuffers(maxSize);
    for (auto& a : camera->getBufferAttachmentMap())
        if (a.second._texture.valid()) a.second._texture->resizeGLObjectBuffers(maxSize);
}
