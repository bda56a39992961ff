#include "caustics/PhotonCamera.h"
#include "shaders/ProgramLibrary.h"
#include "shaders/Shaders.h"
#include "frame/PassCamera.h"
#include "frame/DrawNodes.h"
#include "frame/SceneLighting.h"
#include "frame/PassMath.h"

using namespace osgWater;

PhotonCamera::PhotonCamera(osg::StateSet* waterState, ProgramLibrary& programs, int gridSize, bool floatTarget)
    : _size(gridSize), _waterState(waterState)
{
    setName("osgWater.PhotonCamera");
    setUpPassTarget(this, gridSize, gridSize, PASS_PHOTONS);
    setClearColor(osg::Vec4(0.0f, 0.0f, 0.0f, 0.0f)); // alpha 0: no photon

    _photons = makeTargetTexture(gridSize, floatTarget ? GL_RGBA32F_ARB : GL_RGBA16, GL_RGBA,
                                 floatTarget ? GL_FLOAT : GL_UNSIGNED_SHORT, false);
    _photons->setName("osgWater.photons");
    attach(osg::Camera::COLOR_BUFFER, _photons.get());
    attach(osg::Camera::DEPTH_BUFFER, GL_DEPTH_COMPONENT24); // waves may hide each other from a low sun

    _photonState = new osg::StateSet;
    _photonState->setName("osgWater.photon");
    _photonState->setDataVariance(osg::Object::DYNAMIC);
    _photonState->setAttribute(programs.get("osgWater.photon", "photon.vert", "photon.frag"));
    // the search of optics.glsl reads "the refraction depth": here the sun's depth map
    _photonState->addUniform(new osg::Uniform("osgWater_RefractionDepth", int(UNIT_REFRACTION_DEPTH)));
    _photonState->addUniform(new osg::Uniform("osgWater_RefractionProj", osg::Matrixf()));
    _photonState->setMode(GL_BLEND, osg::StateAttribute::OFF | osg::StateAttribute::OVERRIDE);

    // the water's surface under the water and photon states (the surface is set by setSun())
    _draw = new DrawNodes;
    _draw->addNode(nullptr, { waterState, _photonState.get() });
    setCullCallback(_draw.get());
}

void PhotonCamera::setSun(osg::Node* surface, const osg::Matrixd& view, const osg::Matrixd& projection,
                          osg::Texture2D* sunDepth, const osg::Matrixd* mirror)
{
    setDefineIf(_photonState.get(), "OSGWATER_TILED_PHOTONS", false);
    setDefineIf(_photonState.get(), "OSGWATER_REFLECTED_PHOTONS", mirror != nullptr);
    if (mirror) {
        // the mirror in the sun's eye space: back to the water's frame, mirrored, forth again
        const osg::Matrixf mirrorEye(osg::Matrixd::inverse(view) * *mirror * view);
        setOrAddUniform(_photonState.get(), "osgWater_MirrorEye", mirrorEye);
    }
    _surface = surface;
    _draw->setNode(0, surface);
    setViewMatrix(view);
    setProjectionMatrix(projection);
    _photonState->getUniform("osgWater_RefractionProj")->set(osg::Matrixf(projection));
    _photonState->setTextureAttribute(UNIT_REFRACTION_DEPTH, sunDepth);
}

void PhotonCamera::setSunShade(osg::Texture2D* shade, const osg::Matrixd& projection)
{
    applySunShade(_photonState.get(), shade, UNIT_SUN_DEPTH, projection);
}

void PhotonCamera::setTile(osg::Node* surface, const osg::Matrixd& view, const osg::Matrixd& projection,
                           const osg::Vec3& towardsSun, double bedZ, const osg::Matrixd& localToTile)
{
    _surface = surface;
    _draw->setNode(0, surface);
    setViewMatrix(view);
    setProjectionMatrix(projection);
    osg::StateSet* ss = _photonState.get();
    setDefineIf(ss, "OSGWATER_REFLECTED_PHOTONS", false);
    setDefineIf(ss, "OSGWATER_TILED_PHOTONS", true);
    osg::Vec3f sun = osg::Matrixd::transform3x3(towardsSun, view);
    sun.normalize();
    setOrAddUniform(ss, "osgWater_TileSun", sun);
    setOrAddUniform(ss, "osgWater_TileBed", osg::Vec4f(planeToEye(osg::Vec4d(0.0, 0.0, 1.0, -bedZ), view)));
    setOrAddUniform(ss, "osgWater_EyeToTile", osg::Matrixf(osg::Matrixd::inverse(view) * localToTile));
}

void PhotonCamera::setEmpty(bool empty)
{
    _empty = empty;
    _draw->setNode(0, empty ? nullptr : _surface.get());
    setClearMask(empty ? 0u : GLbitfield(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT));
}
