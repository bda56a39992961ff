#include "frame/SceneBounds.h"
#include <osg/ComputeBoundsVisitor>
#include <osg/Drawable>
#include <osg/TriangleFunctor>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

using namespace osgWater;

namespace {

// Rays along the sun's direction through the cells of a grid at the crest height: each triangle
// is mapped to (entry x, entry y, distance below the crest plane along the ray) and rasterised
// at the cells' centres, keeping the nearest hit per cell (a CPU depth map from the sun).
struct SunRays {
    osg::Vec3d towardsSun;
    double crest = 0.0, x0 = 0.0, y0 = 0.0, cell = 1.0;
    int cells = 1;
    std::vector<double> nearest; // per cell: distance along the ray below the crest plane

    osg::Vec3d toRay(const osg::Vec3d& p) const
    {
        const double t = (crest - p.z()) / towardsSun.z(); // > 0: below the crest plane
        return osg::Vec3d(p.x() + t * towardsSun.x(), p.y() + t * towardsSun.y(), t);
    }

    void add(const osg::Vec3d& pa, const osg::Vec3d& pb, const osg::Vec3d& pc)
    {
        const osg::Vec3d a = toRay(pa), b = toRay(pb), c = toRay(pc);
        const double area = (b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y());
        if (area == 0.0 || !std::isfinite(area)) return; // seen edge-on from the sun
        // above the crests only faces turned to the sun shade the water: a sky dome's inside does not
        const bool facesSun = area > 0.0;
        auto index = [this](double v, double origin) { return (v - origin) / cell - 0.5; };
        const int i0 = std::max(0, int(std::ceil(index(std::min({ a.x(), b.x(), c.x() }), x0))));
        const int i1 = std::min(cells - 1, int(std::floor(index(std::max({ a.x(), b.x(), c.x() }), x0))));
        const int j0 = std::max(0, int(std::ceil(index(std::min({ a.y(), b.y(), c.y() }), y0))));
        const int j1 = std::min(cells - 1, int(std::floor(index(std::max({ a.y(), b.y(), c.y() }), y0))));
        for (int j = j0; j <= j1; ++j)
            for (int i = i0; i <= i1; ++i) {
                const double x = x0 + (i + 0.5) * cell, y = y0 + (j + 0.5) * cell;
                const double wa = ((b.x() - x) * (c.y() - y) - (c.x() - x) * (b.y() - y)) / area;
                const double wb = ((c.x() - x) * (a.y() - y) - (a.x() - x) * (c.y() - y)) / area;
                const double wc = 1.0 - wa - wb;
                if (wa < 0.0 || wb < 0.0 || wc < 0.0) continue;
                const double t = wa * a.z() + wb * b.z() + wc * c.z();
                if (t < 0.0 && !facesSun) continue;
                double& n = nearest[size_t(j) * cells + i];
                n = std::min(n, t);
            }
    }
};

struct TriangleSink {
    SunRays* rays = nullptr;
    osg::Matrixd matrix;
    void operator()(const osg::Vec3& a, const osg::Vec3& b, const osg::Vec3& c)
    {
        rays->add(osg::Vec3d(a) * matrix, osg::Vec3d(b) * matrix, osg::Vec3d(c) * matrix);
    }
};

// ComputeBoundsVisitor keeps the transforms' matrix stack; the drawables' triangles go to the rays
class SunRayVisitor : public osg::ComputeBoundsVisitor
{
public:
    explicit SunRayVisitor(SunRays& rays) : _rays(rays) {}

    void apply(osg::Drawable& drawable) override
    {
        osg::TriangleFunctor<TriangleSink> triangles;
        triangles.rays = &_rays;
        if (!_matrixStack.empty()) triangles.matrix = _matrixStack.back();
        drawable.accept(triangles);
    }

private:
    SunRays& _rays;
};

}

LitWater osgWater::findLitWater(osg::Group& scene, const osg::BoundingBox& water, double crest,
                                const osg::Vec3& towardsSun, int cells)
{
    LitWater result;
    osg::BoundingBox& lit = result.box;
    osg::Vec3d sun(towardsSun);
    if (!water.valid() || cells < 1 || !(sun.normalize() > 0.0) || !(sun.z() > 1e-3)) return result; // sun at the horizon: none
    SunRays rays;
    rays.towardsSun = sun;
    rays.crest = crest;
    rays.cells = cells;
    rays.x0 = water.xMin();
    rays.y0 = water.yMin();
    rays.cell = std::max(water.xMax() - water.xMin(), water.yMax() - water.yMin()) / cells;
    if (!(rays.cell > 0.0)) return result;
    rays.nearest.assign(size_t(cells) * cells, std::numeric_limits<double>::infinity());
    SunRayVisitor visitor(rays);
    for (unsigned int i = 0; i < scene.getNumChildren(); ++i) scene.getChild(i)->accept(visitor);

    double deepest = 0.0, bedSum = 0.0, shadeSum = 0.0; // along the rays
    size_t bedCount = 0, shadeCount = 0;
    for (int j = 0; j < cells; ++j)
        for (int i = 0; i < cells; ++i) {
            const double t = rays.nearest[size_t(j) * cells + i];
            const double x = rays.x0 + (i + 0.5) * rays.cell, y = rays.y0 + (j + 0.5) * rays.cell;
            if (x > water.xMax() || y > water.yMax() || std::isinf(t) || std::isnan(t)) continue; // overhang, nothing
            if (t < 0.0) { // shaded above the crests
                shadeSum += crest - t * sun.z();
                ++shadeCount;
                continue;
            }
            lit.expandBy(osg::Vec3(x - rays.cell, y - rays.cell, crest));
            lit.expandBy(osg::Vec3(x + rays.cell, y + rays.cell, crest));
            deepest = std::max(deepest, t);
            bedSum += crest - t * sun.z();
            ++bedCount;
        }
    result.shaded = shadeCount > 0;
    if (result.shaded) result.meanShadeZ = shadeSum / shadeCount;
    if (!lit.valid()) return result;
    result.meanBedZ = bedSum / bedCount;
    const double depth = deepest * sun.z();
    lit.zMin() = float(crest - 1.25 * depth);
    return result;
}

void SceneBoxes::update(osg::Group& group, const osg::BoundingSphere& bound, const osg::BoundingBox& water,
                        double crest, const osg::Vec3& towardsSun, bool lit)
{
    const bool moved = bound.center() != _key.center() || bound.radius() != _key.radius();
    if (moved) {
        _key = bound;
        osg::ComputeBoundsVisitor cbv;
        for (unsigned int i = 0; i < group.getNumChildren(); ++i) group.getChild(i)->accept(cbv);
        _whole = cbv.getBoundingBox();
    }
    if (!lit) {
        _litValid = false;
        _lit = LitWater();
        return;
    }
    if (moved || !_litValid || crest != _crest || towardsSun != _sun || water._min != _waterKey._min ||
        water._max != _waterKey._max) {
        _litValid = true;
        _crest = crest;
        _sun = towardsSun;
        _waterKey = water;
        _lit = findLitWater(group, water, crest, towardsSun);
    }
}
