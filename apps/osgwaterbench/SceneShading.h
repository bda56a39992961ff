// What the reference renderer needs to colour a point of the scene as the kit's scene program
// (scene.vert, scene.frag) colours it: each triangle's material, vertex normals and texture
// coordinates, collected with the triangles themselves (collectScene), in the same order.
#pragma once
#include "RayCaster.h"
#include <osg/Image>
#include <osg/Texture>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <functional>
#include <vector>

namespace bench {

//! One drawable's look: its material decoded to linear light (a drawable without one has GL's
//! default material) and its base texture (none: a white texel).
struct SurfaceLook {
    glm::dvec3 emission{ 0.0 }, ambient{ 0.2 }, diffuse{ 0.8 };
    double alpha = 1.0;
    osg::ref_ptr<const osg::Image> texture;
    osg::Texture::WrapMode wrapS = osg::Texture::REPEAT, wrapT = osg::Texture::REPEAT;
    bool nearest = false; //!< magnified by the nearest texel (GL_NEAREST), not filtered
};

//! A triangle's attributes at its three corners, in the water node's local frame.
struct TriangleLook {
    unsigned int look = 0;
    glm::dvec3 normal[3]{ glm::dvec3(0.0), glm::dvec3(0.0), glm::dvec3(0.0) }; //!< zero: none (lit fully)
    glm::dvec2 texCoord[3]{ glm::dvec2(0.0), glm::dvec2(0.0), glm::dvec2(0.0) };
};

//! The light the scene program is given (WaterSettings' sun and ambient, local frame).
struct SceneLight {
    glm::dvec3 towardsSun{ 0.0, 0.0, 1.0 }; //!< unit
    glm::dvec3 sunColor{ 1.0 }, ambient{ 0.3 };
    //! The share of the direct sun, per channel, reaching a scene point (the caustics and shadows
    //! under the water: underwaterSunShare); unset, all of it everywhere.
    std::function<glm::dvec3(const glm::dvec3&)> sunShare;
};

struct SceneShading {
    std::vector<SurfaceLook> looks;
    std::vector<TriangleLook> triangles; //!< one per triangle of the mesh collected with it

    //! The linear light the scene program gives the point where `hit` (a hit of `mesh`, the mesh
    //! collected with this shading) meets a ray along `dir`, without fog: emission + ambient +
    //! diffuse sun, lit per vertex as scene.vert lights (n.l at each corner, for the face the ray
    //! sees, interpolated) and times the light's sunShare at the point, times the texture's texel
    //! decoded after bilinear filtering at its finest level (or the nearest texel, as the texture
    //! magnifies).
    glm::dvec3 shade(const TriangleMesh& mesh, const Hit& hit, const glm::dvec3& dir, const SceneLight& light) const;
};

//! The nearest texel, and bilinear filtering, of an image at texture coordinates `st`, as GL filters GL_LINEAR at level 0
//! (texel centres at half-integers, the wrap modes of the texture); the image's own values.
glm::dvec3 sampleNearest(const osg::Image& image, const glm::dvec2& st, osg::Texture::WrapMode wrapS,
                         osg::Texture::WrapMode wrapT);
glm::dvec3 sampleBilinear(const osg::Image& image, const glm::dvec2& st, osg::Texture::WrapMode wrapS,
                          osg::Texture::WrapMode wrapT);

}
