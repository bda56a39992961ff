// The triangles the GPU draws, for the reference ray caster: the WaterNode's children (lake bed,
// objects, sky) and the water surface displaced to its shape at time t, in the water's local frame.
#pragma once
#include <glm/vec3.hpp>
#include <vector>

namespace osg { class Node; }
namespace osgWater { class WaterNode; class WaterSurface; }

namespace bench {

struct SceneShading;

struct TriangleMesh {
    std::vector<glm::dvec3> vertices;
    std::vector<glm::uvec3> triangles;
    void add(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);
};

//! Every triangle below the water node's children (transforms applied, local frame of the node),
//! but an osgWater::Sky's (the light of rays that meet nothing); with `shading`, each triangle's
//! look too, in the same order.
TriangleMesh collectScene(const osgWater::WaterNode& water, SceneShading* shading = nullptr);
//! The water surface at time t: the grid displaced by the CPU wave sum (what the vertex shader
//! does), or the user mesh as given.
TriangleMesh collectWater(const osgWater::WaterSurface& surface, double t);

}
