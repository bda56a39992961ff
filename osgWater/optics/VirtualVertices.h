/* osgWater - natural water for OpenSceneGraph */
#ifndef OSGWATER_VIRTUALVERTICES
#define OSGWATER_VIRTUALVERTICES 1

#include <osgWater/Export>
#include <glm/glm.hpp>
#include <vector>

//! Refraction by virtual vertices (the geometric-refraction thesis, ch. 3): the geometry beyond a
//! faceted membrane is drawn where it appears to be. Each facet's cell is bounded by the refracted
//! sight rays through the facet's vertices; a true vertex inside a cell moves to its virtual vertex,
//! on the eye's line through its sight point on the facet, at n_eye / n_other of its distance from
//! the sight point (foreshortening, eq. 2.4). Double precision on the CPU: the reference a drawn
//! version will be held to, and the maths of the error-volume experiment (osgwatervirtualvertices).
namespace osgWater {
class WaterSurface;
namespace virtualvertices {

//! A faceted membrane: vertices, unit vertex normals on the eye's side, triangles (vertex indices).
struct Membrane {
    std::vector<glm::dvec3> positions;
    std::vector<glm::dvec3> normals;
    std::vector<glm::ivec3> facets;
};

//! How a refraction ray came about.
enum class RayKind {
    Refracted,        //!< Snell (eq. 2.2)
    FacingAway,       //!< the sight ray leaves the membrane's eye side there (a faceting artefact):
                      //!< eq. 3.1, eq. 2.2 as if the sight ray grazed the membrane
    TotallyReflected  //!< no transmitted ray: eq. 3.2, the square root's argument and result negated
};

struct RefractionRay {
    glm::dvec3 direction{0.0};
    RayKind kind = RayKind::Refracted;
};

//! The refraction ray for the unit sight direction I at a membrane point with unit normal N (on the
//! eye's side), eta = n_eye / n_other. Always a finite unit vector: where Snell gives no ray, the
//! thesis's extrapolations do, so that every facet keeps its cell and the rays move smoothly as the
//! eye moves.
OSGWATER_EXPORT RefractionRay refractionRay(const glm::dvec3& I, const glm::dvec3& N, double eta);

//! The membrane's cells seen from an eye: one refraction ray per membrane vertex. They change only
//! when the eye moves relative to the membrane (or the membrane moves).
struct Cells {
    const Membrane* membrane = nullptr;
    glm::dvec3 eye{0.0};
    double eta = 1.0;  //!< n_eye / n_other
    std::vector<RefractionRay> rays;
};
OSGWATER_EXPORT Cells buildCells(const Membrane& membrane, const glm::dvec3& eye, double nEye, double nOther);

//! How the sight point is placed on the containing facet.
enum class SightPoint {
    Linear,  //!< the thesis: the true vertex's barycentric coordinates in the cell's section by the
             //!< plane through it (normal: the mean of the facet's three rays), applied to the facet
    Solved   //!< then refined on the facet's plane (Gauss-Newton on the barycentric coordinates) until
             //!< the ray refracted there, by the interpolated vertex normal, passes through the true
             //!< vertex: exact on a flat membrane, where the linear placement is not
};

struct VirtualVertex {
    bool found = false;         //!< some cell contains the true vertex
    int facet = -1;             //!< the first containing facet: the thesis's "first virtual vertex"
    int containingCells = 0;    //!< how many cells contain it (> 1: a zone of convergence); all are
                                //!< counted only when asked, otherwise 1 once one is found
    bool extrapolated = false;  //!< a ray bounding the cell came from eq. 3.1 or 3.2
    glm::dvec3 barycentric{0.0};//!< of the sight point on the facet
    glm::dvec3 sightPoint{0.0}; //!< where the sight ray meets the facet
    glm::dvec3 position{0.0};   //!< the virtual vertex
};

//! The virtual vertex of `trueVertex` (found = false: no cell holds it, it cannot be seen through
//! the membrane). The facets are tried in order; `countCells` goes on through every facet to count
//! the cells that hold it.
OSGWATER_EXPORT VirtualVertex virtualVertex(const Cells& cells, const glm::dvec3& trueVertex,
                                            SightPoint method = SightPoint::Linear, bool countCells = false);

//! The facets' size of the membrane the refraction pass draws virtual vertices through
//! (shaders/virtualvertex.glsl): the built-in grid's cell, or an eighth of the shortest wavelength
//! where that is smaller, so the facets follow every wave (a chord sags 8% of the amplitude). The
//! cost per vertex does not depend on it: a vertex finds its facet near the exact sight point.
OSGWATER_EXPORT double membraneCellSize(const WaterSurface& surface);

//! The thesis's virtual vertex for a sight point S: on the eye's ray through S, eta = n_eye / n_other
//! times as far beyond S as the true vertex T is (eq. 2.4).
OSGWATER_EXPORT glm::dvec3 foreshortened(const glm::dvec3& eye, const glm::dvec3& S, const glm::dvec3& T, double eta);

} }

#endif
