#include <osgWater/PhotonCamera>
#include <osgWater/Shaders>
#include <osgWater/PassCamera>
#include <osgUtil/CullVisitor>

using namespace osgWater;

namespace {

// The camera has no children: it draws the water's surface under the water and photon states.
class PhotonCullCallback : public osg::NodeCallback
{
public:
    void operator()(osg::Node* node, osg::NodeVisitor* nv) override
    {
        PhotonCamera* camera = static_cast<PhotonCamera*>(node);
        osgUtil::CullVisitor* cv = nv->asCullVisitor();
        if (!cv || !camera->getSurface()) return;
        cv->pushStateSet(camera->getWaterState());
        cv->pushStateSet(camera->getPhotonState());
        camera->getSurface()->accept(*nv);
        cv->popStateSet();
        cv->popStateSet();
    }
};

}

PhotonCamera::PhotonCamera(osg::StateSet* waterState, int gridSize, bool floatTarget)
    : _size(gridSize), _waterState(waterState)
{
    setName("osgWater.PhotonCamera");
    setUpPassTarget(this, gridSize, -2); // after the sun depth map, before the gather
    setClearColor(osg::Vec4(0.0f, 0.0f, 0.0f, 0.0f)); // alpha 0: no photon
    setCullCallback(new PhotonCullCallback);

    _photons = makeTargetTexture(gridSize, floatTarget ? GL_RGBA32F_ARB : GL_RGBA16, GL_RGBA,
                                 floatTarget ? GL_FLOAT : GL_UNSIGNED_SHORT, false);
    _photons->setName("osgWater.photons");
    attach(osg::Camera::COLOR_BUFFER, _photons.get());
    attach(osg::Camera::DEPTH_BUFFER, GL_DEPTH_COMPONENT24); // waves may hide each other from a low sun

    _photonState = new osg::StateSet;
    _photonState->setName("osgWater.photon");
    _photonState->setDataVariance(osg::Object::DYNAMIC);
    _photonState->setAttribute(createProgram("osgWater.photon", "photon.vert", "photon.frag"));
    // the search of optics.glsl reads "the refraction depth": here the sun's depth map
    _photonState->addUniform(new osg::Uniform("osgWater_RefractionDepth", 3));
    _photonState->addUniform(new osg::Uniform("osgWater_RefractionProj", osg::Matrixf()));
    _photonState->addUniform(new osg::Uniform("osgWater_RefractionInvProj", osg::Matrixf()));
    _photonState->setMode(GL_BLEND, osg::StateAttribute::OFF | osg::StateAttribute::OVERRIDE);
}

void PhotonCamera::setSun(osg::Node* surface, const osg::Matrixd& view, const osg::Matrixd& projection,
                          osg::Texture2D* sunDepth)
{
    _surface = surface;
    setViewMatrix(view);
    setProjectionMatrix(projection);
    _photonState->getUniform("osgWater_RefractionProj")->set(osg::Matrixf(projection));
    _photonState->getUniform("osgWater_RefractionInvProj")->set(osg::Matrixf(osg::Matrixd::inverse(projection)));
    _photonState->setTextureAttribute(3, sunDepth);
}
