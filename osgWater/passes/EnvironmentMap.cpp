#include "passes/EnvironmentMap.h"
#include <algorithm>

using namespace osgWater;

EnvironmentMap::EnvironmentMap(osg::Group* scene, osg::StateSet* sceneState, int size) : _size(size)
{
    setName("osgWater.EnvironmentMap");
    _cube = new osg::TextureCubeMap;
    _cube->setName("osgWater.environment");
    _cube->setTextureSize(size, size);
    _cube->setInternalFormat(GL_RGBA16F_ARB); // linear light, as the pass targets
    _cube->setSourceFormat(GL_RGBA);
    _cube->setSourceType(GL_FLOAT);
    _cube->setFilter(osg::Texture::MIN_FILTER, osg::Texture::LINEAR);
    _cube->setFilter(osg::Texture::MAG_FILTER, osg::Texture::LINEAR);
    for (osg::Texture::WrapParameter w : { osg::Texture::WRAP_S, osg::Texture::WRAP_T, osg::Texture::WRAP_R })
        _cube->setWrap(w, osg::Texture::CLAMP_TO_EDGE);
    for (int face = 0; face < 6; ++face) {
        _faces[face] = new PassCamera(scene, { sceneState }, size, size, PASS_ENVIRONMENT);
        _faces[face]->setName("osgWater.EnvironmentFace");
        _faces[face]->attach(osg::Camera::COLOR_BUFFER, _cube.get(), 0, face);
        _faces[face]->attach(osg::Camera::DEPTH_BUFFER, GL_DEPTH_COMPONENT24);
        addChild(_faces[face].get());
    }
}

osg::Matrixd EnvironmentMap::faceView(int face, const osg::Vec3d& centre)
{
    // GL's cube map faces (the table of the GL specification, "Cube Map Texture Selection"): the
    // face along +x is read with s along -z and t along -y, and so on; a camera looking along the
    // face's axis with these up vectors renders its rows and columns in that order
    static const osg::Vec3d axis[6] = { { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 }, { 0, 0, 1 }, { 0, 0, -1 } };
    static const osg::Vec3d up[6] = { { 0, -1, 0 }, { 0, -1, 0 }, { 0, 0, 1 }, { 0, 0, -1 }, { 0, -1, 0 }, { 0, -1, 0 } };
    return osg::Matrixd::lookAt(centre, centre + axis[face], up[face]);
}

void EnvironmentMap::setBackground(const osg::Vec4& color)
{
    if (color == _clearColor) return;
    _clearColor = color;
    for (auto& f : _faces) f->setClearColor(color);
    ++_version;
}

void EnvironmentMap::aim(const osg::Vec3d& centre, const osg::BoundingSphere& scene, const SceneLighting& lighting)
{
    // the faces reach the far side of the scene's bound
    const double reach = scene.valid() ? (osg::Vec3d(scene.center()) - centre).length() + scene.radius() : 1.0;
    const double far = std::max(reach, 1.0) * 1.01;
    if (centre != _centre || far != _far || lighting.towardsSun != _sun) {
        _centre = centre;
        _far = far;
        _sun = lighting.towardsSun;
        ++_version;
    }
    const osg::Matrixd projection = osg::Matrixd::perspective(90.0, 1.0, far * 1e-4, far);
    for (int face = 0; face < 6; ++face) {
        PassCamera* c = _faces[face].get();
        c->setViewMatrix(faceView(face, centre));
        c->setProjectionMatrix(projection);
        c->setKeepPlane(osg::Plane(0.0, 0.0, 1.0, -lighting.level)); // the surroundings above the water
        c->applyLighting(lighting);
    }
}

bool EnvironmentMap::stale(unsigned int contextID) const
{
    auto done = _drawn.find(contextID);
    return done == _drawn.end() || done->second != _version || !_cube->getTextureObject(contextID);
}

void EnvironmentMap::resizeGLObjectBuffers(unsigned int maxSize)
{
    osg::Group::resizeGLObjectBuffers(maxSize);
    for (auto& f : _faces) resizePassGLObjectBuffers(f.get(), maxSize);
}

void EnvironmentMap::releaseGLObjects(osg::State* state) const
{
    osg::Group::releaseGLObjects(state);
    for (const auto& f : _faces) releasePassGLObjects(f.get(), state);
}
