#include "ReferenceCaustics.h"
#include "Reference.h"
#include <glm/geometric.hpp>
#include <algorithm>
#include <cmath>

namespace bench {

double samplePhotons(const PhotonImage& photons, double s, double t)
{
    const int n = photons.resolution;
    if (n <= 0 || photons.value.size() < size_t(n) * n) return 0.0;
    const double x = s * n - 0.5, y = t * n - 0.5;
    const double fx = std::floor(x), fy = std::floor(y);
    const double ax = x - fx, ay = y - fy;
    auto at = [&](double i, double j) {
        const int ii = std::clamp(int(i), 0, n - 1), jj = std::clamp(int(j), 0, n - 1);
        return double(photons.value[size_t(jj) * n + ii]);
    };
    return (1.0 - ay) * ((1.0 - ax) * at(fx, fy) + ax * at(fx + 1, fy)) +
           ay * ((1.0 - ax) * at(fx, fy + 1) + ax * at(fx + 1, fy + 1));
}

std::function<glm::dvec3(const glm::dvec3&)> underwaterSunShare(const UnderwaterSun& sun, const RayCaster& scene)
{
    // the sun's path under a level surface, towards the surface: Snell's refraction of the sun's
    // ray, reversed (a sun on or below the horizon: straight up)
    glm::dvec3 down(0.0, 0.0, -1.0);
    snell(-sun.towardsSun, glm::dvec3(0.0, 0.0, 1.0), sun.airIOR, sun.waterIOR, down);
    const glm::dvec3 up = down.z < -1e-6 ? -down : glm::dvec3(0.0, 0.0, 1.0);
    return [sun, up, &scene](const glm::dvec3& p) {
        if (!sun.photons || p.z >= sun.level) return glm::dvec3(1.0);
        const osg::Vec3d w = osg::Vec3d(p.x, p.y, p.z) * sun.localToSun;
        if (!(w.x() >= 0.0 && w.x() <= 1.0 && w.y() >= 0.0 && w.y() <= 1.0)) return glm::dvec3(1.0);
        const double toLevel = (sun.level - p.z) / up.z;
        const double eps = 1e-6 * (1.0 + glm::length(p));
        if (scene.intersect(p, up, eps, toLevel).hit) return glm::dvec3(0.0); // an underwater shadow
        const double depth = p.z - sun.level; // negative
        const glm::dvec3 channels(std::exp(sun.channelExtinction.x * depth), std::exp(sun.channelExtinction.y * depth),
                                  std::exp(sun.channelExtinction.z * depth));
        return sun.intensity * samplePhotons(*sun.photons, w.x(), w.y()) * channels;
    };
}

}
