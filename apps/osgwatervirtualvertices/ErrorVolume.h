// The thesis's error volume (§4.1): a box of regularly spaced points beyond a refractor, each one's
// virtual vertex, the point that virtual vertex implies (the eye's ray through it, refracted exactly
// at the exact surface and lengthened by n_other / n_eye), and that point's distance to the true one.
#pragma once
#include "Refractor.h"

namespace vv {

struct Box {
    glm::dvec3 min{-200.0, -200.0, -400.0}, max{200.0, 200.0, 0.0};
    //! samples per side: at the centres of perAxis^3 equal cells
    int perAxis = 40;
};

struct ErrorStats {
    double mean = 0.0, deviation = 0.0, max = 0.0;
    long samples = 0;       //!< measured points (the thesis's "data points")
    long outside = 0;       //!< beyond the refractor but in no cell: not seen through it
    long convergence = 0;   //!< in more than one cell (a zone of convergence): left out, as the thesis does
    long extrapolated = 0;  //!< in a cell bounded by an extrapolated ray (eq. 3.1, 3.2): left out
    long unimplied = 0;     //!< the exact ray through the virtual vertex misses or cannot refract
};

struct Medium { double nEye = 1.0, nOther = 1.51; };

//! The error volume of `refractor` seen from `eye`, with the sight point placed by `method`. Runs on
//! all hardware threads.
ErrorStats measureErrorVolume(const Refractor& refractor, const glm::dvec3& eye, const Medium& medium, const Box& box,
                              osgWater::virtualvertices::SightPoint method);

//! The point a virtual vertex implies: the eye's ray through it meets the exact surface at P, is
//! refracted there and runs n_other / n_eye times |V - P|. False where the ray misses the surface
//! or cannot refract.
bool impliedPoint(const Refractor& refractor, const glm::dvec3& eye, const glm::dvec3& virtualVertex, double eta,
                  glm::dvec3& point);

}
