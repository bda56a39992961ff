#include "Refractor.h"
#include <osgWater/WaterSurface>
#include <cmath>
#include <limits>
#include <vector>

namespace vv {

namespace {

class Disk : public Refractor {
public:
    Disk(double radius, int rings, double sphereRadius)
        : _radius(radius), _sphereRadius(sphereRadius),
          _flat(!std::isfinite(sphereRadius)),
          _centreZ(_flat ? 0.0 : std::sqrt(std::max(0.0, sphereRadius * sphereRadius - radius * radius)))
    {
        std::vector<int> ringStart(rings + 2, 0);
        add(0.0, 0.0);
        for (int i = 1; i <= rings; ++i) {
            ringStart[i] = int(_membrane.positions.size());
            const int n = 4 * i;
            for (int k = 0; k < n; ++k) {
                const double angle = 2.0 * M_PI * k / n, r = radius * i / rings;
                add(r * std::cos(angle), r * std::sin(angle));
            }
        }
        for (int k = 0; k < 4; ++k) _membrane.facets.push_back(glm::ivec3(0, 1 + k, 1 + (k + 1) % 4));
        // the strip between ring i (n vertices) and ring i + 1 (m): walk both by angle
        for (int i = 1; i < rings; ++i) {
            const int n = 4 * i, m = 4 * (i + 1), in = ringStart[i], out = ringStart[i + 1];
            int a = 0, b = 0;
            while (a < n || b < m) {
                const double nextA = double(a + 1) / n, nextB = double(b + 1) / m;
                if (a < n && (b == m || nextA < nextB))
                    _membrane.facets.push_back(glm::ivec3(in + a % n, out + b % m, in + (a + 1) % n)), ++a;
                else
                    _membrane.facets.push_back(glm::ivec3(in + a % n, out + b % m, out + (b + 1) % m)), ++b;
            }
        }
    }

    bool intersect(const glm::dvec3& o, const glm::dvec3& d, glm::dvec3& p, glm::dvec3& n) const override
    {
        if (_flat) {
            if (!(d.z < 0.0) || o.z <= 0.0) return false;
            p = o + (-o.z / d.z) * d;
            p.z = 0.0;
            n = glm::dvec3(0, 0, 1);
            return p.x * p.x + p.y * p.y <= _radius * _radius;
        }
        // the bowl is the sphere's lower cap: where a ray from above leaves the sphere
        const glm::dvec3 c(0, 0, _centreZ), oc = o - c;
        const double b = glm::dot(oc, d), q = glm::dot(oc, oc) - _sphereRadius * _sphereRadius;
        const double disc = b * b - q;
        if (disc < 0.0) return false;
        const double t = -b + std::sqrt(disc);
        if (!(t > 0.0)) return false;
        p = o + t * d;
        n = (c - p) / _sphereRadius;
        return p.z <= 1e-9;
    }

    bool beyond(const glm::dvec3& p) const override
    {
        if (p.z >= 0.0) return false;
        if (_flat) return true;
        return glm::length(p - glm::dvec3(0, 0, _centreZ)) >= _sphereRadius;
    }

private:
    void add(double x, double y)
    {
        if (_flat) {
            _membrane.positions.push_back(glm::dvec3(x, y, 0.0));
            _membrane.normals.push_back(glm::dvec3(0, 0, 1));
            return;
        }
        const glm::dvec3 p(x, y, _centreZ - std::sqrt(_sphereRadius * _sphereRadius - x * x - y * y));
        _membrane.positions.push_back(p);
        _membrane.normals.push_back((glm::dvec3(0, 0, _centreZ) - p) / _sphereRadius);
    }

    double _radius, _sphereRadius;
    bool _flat;
    double _centreZ;
};

class WavePatch : public Refractor {
public:
    WavePatch(const osgWater::WaterSurface& surface, double t, const glm::dvec2& centre, double halfSide, double spacing,
              bool fromBelow)
        : _surface(surface), _t(t), _min(centre - halfSide), _max(centre + halfSide), _side(fromBelow ? -1.0 : 1.0)
    {
        const int cells = std::max(1, int(std::ceil(2.0 * halfSide / spacing)));
        const double step = 2.0 * halfSide / cells;
        for (int j = 0; j <= cells; ++j)
            for (int i = 0; i <= cells; ++i) {
                const double x = _min.x + i * step, y = _min.y + j * step;
                _membrane.positions.push_back(glm::dvec3(x, y, surface.height(x, y, t)));
                const osg::Vec3d n = surface.normal(x, y, t);
                _membrane.normals.push_back(_side * glm::dvec3(n.x(), n.y(), n.z()));
            }
        for (int j = 0; j < cells; ++j)
            for (int i = 0; i < cells; ++i) {
                const int a = j * (cells + 1) + i, b = a + 1, c = a + cells + 1, d = c + 1;
                _membrane.facets.push_back(glm::ivec3(a, b, d));
                _membrane.facets.push_back(glm::ivec3(a, d, c));
            }
    }

    bool intersect(const glm::dvec3& o, const glm::dvec3& d, glm::dvec3& p, glm::dvec3& n) const override
    {
        // a segment long enough to cross the patch's slab of waves
        const double reach = 10.0 * (glm::length(o) + glm::length(_max - _min) + 1.0);
        double ratio = 0.0;
        osg::Vec3d point, normal;
        const osg::Vec3d start(o.x, o.y, o.z), end(o.x + reach * d.x, o.y + reach * d.y, o.z + reach * d.z);
        if (!_surface.intersect(start, end, _t, ratio, point, normal)) return false;
        p = glm::dvec3(point.x(), point.y(), point.z());
        const osg::Vec3d up = _surface.normal(point.x(), point.y(), _t);
        n = _side * glm::dvec3(up.x(), up.y(), up.z());
        return p.x >= _min.x && p.x <= _max.x && p.y >= _min.y && p.y <= _max.y;
    }

    bool beyond(const glm::dvec3& p) const override { return _side * (p.z - _surface.height(p.x, p.y, _t)) < 0.0; }

private:
    const osgWater::WaterSurface& _surface;
    double _t;
    glm::dvec2 _min, _max;
    double _side;  // +1 seen from above, -1 from below
};

} // namespace

std::unique_ptr<Refractor> makeDisk(double radius, int rings, double sphereRadius)
{
    return std::unique_ptr<Refractor>(new Disk(radius, std::max(1, rings), std::max(sphereRadius, radius)));
}

std::unique_ptr<Refractor> makeWavePatch(const osgWater::WaterSurface& surface, double t, const glm::dvec2& centre,
                                         double halfSide, double spacing, bool fromBelow)
{
    return std::unique_ptr<Refractor>(new WavePatch(surface, t, centre, halfSide, spacing, fromBelow));
}

}
