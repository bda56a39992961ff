// The refractors of the error-volume experiment: a faceted membrane (what the virtual-vertex
// algorithm sees) and the exact surface it stands for (what the exact ray cast sees).
#pragma once
#include "optics/VirtualVertices.h"
#include <glm/glm.hpp>
#include <memory>

namespace osgWater { class WaterSurface; }

namespace vv {

class Refractor {
public:
    virtual ~Refractor() = default;
    const osgWater::virtualvertices::Membrane& membrane() const { return _membrane; }
    //! The first point (t > 0) where origin + t dir meets the exact surface, with its unit normal on
    //! the eye's side (up); false where it misses.
    virtual bool intersect(const glm::dvec3& origin, const glm::dvec3& dir, glm::dvec3& point, glm::dvec3& normal) const = 0;
    //! Whether p lies beyond the exact surface, in the refracting medium.
    virtual bool beyond(const glm::dvec3& p) const = 0;

protected:
    osgWater::virtualvertices::Membrane _membrane;
};

//! A circular refractor of radius `radius` in the plane z = 0, faceted in concentric rings: ring i
//! of `rings` has 4 i vertices, so the facets number 4 rings^2 (11 rings: 484 facets, 265 vertices).
//! With a finite `sphereRadius` (>= radius) it is conformed to a sphere, each vertex lifted
//! vertically onto it: a bowl with its rim at z = 0, opening towards the eye (diverging rays);
//! sphereRadius = radius is a hemisphere.
std::unique_ptr<Refractor> makeDisk(double radius, int rings, double sphereRadius);

//! A square patch of water waves at time t (the surface's analytic sum): centre, half side, the
//! facets' spacing; the vertices and normals on the analytic surface, as a drawn grid has them.
//! `fromBelow`: seen by an eye under the water (normals down, the refracting medium the air above).
std::unique_ptr<Refractor> makeWavePatch(const osgWater::WaterSurface& surface, double t, const glm::dvec2& centre,
                                         double halfSide, double spacing, bool fromBelow = false);

}
