#include "WaterCaster.h"
#include <osgWater/WaterSurface>
#include <glm/geometric.hpp>
#include <algorithm>
#include <string>

namespace bench {

WaterCaster::WaterCaster(const osgWater::WaterSurface& surface, double t) : _surface(surface), _t(t)
{
    if (!surface.usesGrid()) _mesh = std::make_unique<RayCaster>(collectWater(surface, t));
}

Hit WaterCaster::intersect(const glm::dvec3& org, const glm::dvec3& dir, double tnear, double tfar) const
{
    if (_mesh) return _mesh->intersect(org, dir, tnear, tfar);
    Hit h;
    const double len = glm::length(dir);
    if (!(len > 0.0)) return h;
    // a segment, not a ray: out to well past the water's square (intersect clips it to the square)
    const osg::BoundingBox& box = _surface.getBoundingBox();
    const glm::dvec3 centre(box.center().x(), box.center().y(), box.center().z());
    const double reach = (glm::length(org - centre) + box.radius()) / len + 1.0;
    const double t0 = std::max(tnear, 0.0), t1 = std::min(tfar, t0 + reach);
    if (!(t1 > t0)) return h;
    const glm::dvec3 a = org + t0 * dir, b = org + t1 * dir;
    double ratio;
    osg::Vec3d point, normal;
    if (!_surface.intersect(osg::Vec3d(a.x, a.y, a.z), osg::Vec3d(b.x, b.y, b.z), _t, ratio, point, normal)) return h;
    h.hit = true;
    h.t = t0 + ratio * (t1 - t0);
    h.point = glm::dvec3(point.x(), point.y(), point.z());
    h.normal = glm::dvec3(normal.x(), normal.y(), normal.z());
    return h;
}

std::string WaterCaster::describe() const
{
    return _mesh ? std::to_string(_mesh->size()) + " water triangles (the user mesh)"
                 : std::string("the analytic waves (the built-in mesh's layout is the renderer's business)");
}

}
