#include "caustics/ProceduralCaustics.h"
#include <osgWater/WaterSurface>
#include <algorithm>
#include <cmath>

namespace osgWater { namespace procedural {

namespace {

// fixed-point steps on the height: the height's slope along the ray's horizontal run stays well
// under 1 for water waves, so each step shrinks the error several times
const int kHeightSteps = 6;

//! GLSL refract(): I incident (unit), N unit facing against I, eta = n1 / n2; zero under total
//! internal reflection.
glm::dvec3 refractGlsl(const glm::dvec3& I, const glm::dvec3& N, double eta)
{
    const double d = glm::dot(N, I);
    const double k = 1.0 - eta * eta * (1.0 - d * d);
    if (k < 0.0) return glm::dvec3(0.0);
    return eta * I - (eta * d + std::sqrt(k)) * N;
}

}

double sunHalo(double angle, const SunHalo& map)
{
    if (!(angle >= 0.0)) angle = std::fabs(angle);
    if (!std::isfinite(angle)) return 0.0;
    if (angle <= map.discRadius) return 1.0;
    if (angle >= map.haloRadius || map.haloRadius <= map.discRadius) return 0.0;
    const double x = 1.0 - (angle - map.discRadius) / (map.haloRadius - map.discRadius);
    return map.haloLevel * x * x;
}

Backtrace backtrace(const glm::dvec3& bed, const glm::dvec3& towardsSun, const WaterSurface& surface, double t,
                    double nAir, double nWater, bool vertical)
{
    Backtrace out;
    if (!(towardsSun.z > 0.0) || !(nAir > 0.0) || !(nWater > 0.0)) return out;
    const glm::dvec3 sun = glm::normalize(towardsSun);
    const glm::dvec3 up(0.0, 0.0, 1.0);
    // the sun's light through flat water, reversed: from the bed up towards where it came in
    const glm::dvec3 down = refractGlsl(-sun, up, nAir / nWater);
    const glm::dvec3 back = vertical ? up : -down;
    if (!(back.z > 0.0)) return out;
    // fixed-point steps on the height where the backward ray runs: tau = (h(x(tau)) - z_bed) / back.z
    double tau = (surface.getLevel() - bed.z) / back.z;
    for (int i = 0; i < kHeightSteps; ++i) {
        const glm::dvec3 p = bed + tau * back;
        tau = (surface.height(p.x, p.y, t) - bed.z) / back.z;
    }
    if (!(tau > 0.0)) return out;
    out.valid = true;
    out.surface = bed + tau * back;
    out.surface.z = surface.height(out.surface.x, out.surface.y, t);
    const osg::Vec3d n = surface.normal(out.surface.x, out.surface.y, t);
    out.normal = glm::dvec3(n.x(), n.y(), n.z());
    out.pathInWater = glm::length(out.surface - bed);
    out.exit = refractGlsl(back, -out.normal, nWater / nAir);
    const double exitLength = glm::length(out.exit);
    out.angleToSun = exitLength > 0.0 ? std::acos(std::clamp(glm::dot(out.exit / exitLength, sun), -1.0, 1.0))
                                      : 3.14159265358979323846;
    return out;
}

double causticLight(const Backtrace& trace, double transmitted, double extinction, bool calibrated, const SunHalo& map)
{
    if (!trace.valid) return 0.0;
    const double centre = sunHalo(0.0, map);
    const double value = sunHalo(trace.angleToSun, map);
    if (!calibrated) return value;
    if (!(centre > 0.0)) return 0.0;
    return value / centre * std::clamp(transmitted, 0.0, 1.0) * std::exp(-std::max(extinction, 0.0) * trace.pathInWater);
}

} }
