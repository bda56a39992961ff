// The reciprocal-power Fresnel fit (the DeepWater paper's error plot, done again for n = 1.333):
// which power p of F = 1 / (1 + E.N)^p is closest to the exact curve, and how far each candidate,
// Schlick's approximation and (1 - E.N)^q lie from it.
#pragma once
#include <string>

namespace bench {

//! Writes dir/fresnel-approximations.png (absolute error against the exact unpolarised curve over
//! 0-90 degrees) and dir/FRESNEL.md (the table and the fitted powers). False with a message when
//! the folder cannot be written; a missing gnuplot leaves the table and says so in it.
bool writeFresnelFigure(const std::string& dir, std::string& error);

}
