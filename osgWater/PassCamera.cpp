#include <osgWater/PassCamera>
#include <osgWater/PassMath>
#include <osgUtil/CullVisitor>

using namespace osgWater;

namespace {

// Draws the scene under the pass camera: the camera itself has no children, so the water's
// scene is traversed here, with the keep plane added to the culling frustum (cf. osgShadow's
// ViewDependentShadowMap, whose cameras traverse the shadowed scene the same way).
class PassCullCallback : public osg::NodeCallback
{
public:
    void operator()(osg::Node* node, osg::NodeVisitor* nv) override
    {
        PassCamera* camera = static_cast<PassCamera*>(node);
        osgUtil::CullVisitor* cv = nv->asCullVisitor();
        if (!cv || !camera->getScene()) return;
        // the culling set is in the camera's reference frame, which is the water's local frame
        cv->getCurrentCullingSet().getFrustum().add(camera->getKeepPlane());
        cv->pushStateSet(camera->getSceneState());
        camera->getScene()->osg::Group::traverse(*nv);
        cv->popStateSet();
    }
};

}

PassCamera::PassCamera(osg::Group* scene, osg::StateSet* sceneState, int textureSize)
    : _scene(scene), _sceneState(sceneState), _size(textureSize), _keepPlane(0.0, 0.0, 1.0, 0.0)
{
    setUpPassTarget(this, textureSize, 0);
    setCullCallback(new PassCullCallback);

    _color = makeTexture(textureSize, GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, true);
    _color->setName("osgWater.passColor");
    attach(osg::Camera::COLOR_BUFFER, _color.get());

    osg::StateSet* ss = getOrCreateStateSet();
    _clipPlaneUniform = new osg::Uniform("osgWater_ClipPlane", osg::Vec4f(0.0f, 0.0f, 0.0f, 1.0f));
    _sunUniform = new osg::Uniform("osgWater_SunEye", osg::Vec3f(0.0f, 0.0f, 1.0f));
    ss->addUniform(_clipPlaneUniform.get());
    ss->addUniform(_sunUniform.get());
    ss->setMode(GL_CLIP_PLANE0, osg::StateAttribute::ON); // == GL_CLIP_DISTANCE0
    addCausticsUniforms(ss);
    setUnderwaterFog(ss, osg::Vec3(), 0.0f);
    ss->setDataVariance(osg::Object::DYNAMIC);
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

void osgWater::setUpPassTarget(osg::Camera* camera, int size, int order)
{
    setUpPassTarget(camera, size, size, order);
}

void osgWater::setUpPassTarget(osg::Camera* camera, int width, int height, int order)
{
    camera->setRenderOrder(osg::Camera::PRE_RENDER, order);
    camera->setRenderTargetImplementation(osg::Camera::FRAME_BUFFER_OBJECT);
    camera->setReferenceFrame(osg::Camera::ABSOLUTE_RF);
    // near/far come from the scene bound (PassMath), so a depth texture's projection is known exactly
    camera->setComputeNearFarMode(osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR);
    camera->setClearMask(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    camera->setViewport(0, 0, width, height);
}

void PassCamera::setKeepPlane(const osg::Plane& localPlane)
{
    _keepPlane = localPlane;
}

void PassCamera::setMatrices(const osg::Matrixd& view, const osg::Matrixd& projection, const osg::Vec3& sunLocal)
{
    setViewMatrix(view);
    setProjectionMatrix(projection);
    _clipPlaneUniform->set(osg::Vec4f(planeToEye(_keepPlane.asVec4(), view)));
    osg::Vec3f sunEye = osg::Matrixd::transform3x3(sunLocal, view);
    sunEye.normalize();
    _sunUniform->set(sunEye);
}

void osgWater::addCausticsUniforms(osg::StateSet* ss)
{
    ss->addUniform(new osg::Uniform("osgWater_Caustics", osg::Vec2f(0.0f, 0.0f)));
    ss->addUniform(new osg::Uniform("osgWater_EyeToSun", osg::Matrixf()));
    ss->addUniform(new osg::Uniform("osgWater_WaterPlane", osg::Vec4f(0.0f, 0.0f, 0.0f, 1.0f)));
    ss->addUniform(new osg::Uniform("osgWater_SunDepthBias", osg::Vec2f(0.0f, 0.0f)));
}

void osgWater::setUnderwaterFog(osg::StateSet* ss, const osg::Vec3& waterColor, float k)
{
    const osg::Vec4f v(waterColor, k);
    if (osg::Uniform* u = ss->getUniform("osgWater_Fog")) u->set(v);
    else ss->addUniform(new osg::Uniform("osgWater_Fog", v));
}

void osgWater::applyCausticsLighting(osg::StateSet* ss, const CausticsLighting* c, const osg::Matrixd& view,
                                     double level)
{
    ss->getUniform("osgWater_WaterPlane")->set(osg::Vec4f(planeToEye(osg::Vec4d(0.0, 0.0, 1.0, -level), view)));
    if (!c) {
        ss->getUniform("osgWater_Caustics")->set(osg::Vec2f(0.0f, 0.0f));
        return;
    }
    ss->getUniform("osgWater_Caustics")->set(osg::Vec2f(1.0f, c->intensity));
    ss->getUniform("osgWater_EyeToSun")->set(osg::Matrixf(osg::Matrixd::inverse(view) * c->localToSun));
    ss->getUniform("osgWater_SunDepthBias")->set(c->depthBias);
    ss->setTextureAttribute(4, c->caustics.get());
    ss->setTextureAttribute(5, c->depth.get());
}
