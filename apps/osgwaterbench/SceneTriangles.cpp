#include "SceneTriangles.h"
#include <osgWater/WaterNode>
#include <osg/Geometry>
#include <osg/NodeVisitor>
#include <osg/Transform>
#include <osg/TriangleFunctor>

namespace bench {

void TriangleMesh::add(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c)
{
    const unsigned int i = unsigned(vertices.size());
    vertices.push_back(a);
    vertices.push_back(b);
    vertices.push_back(c);
    triangles.emplace_back(i, i + 1, i + 2);
}

namespace {

struct Collect {
    TriangleMesh* mesh = nullptr;
    osg::Matrixd matrix;
    const osgWater::WaterSurface* displace = nullptr; // grid: z from the wave sum
    double t = 0.0;
    glm::dvec3 point(const osg::Vec3& v) const
    {
        osg::Vec3d p = osg::Vec3d(v) * matrix;
        if (displace) p.z() = displace->height(p.x(), p.y(), t);
        return glm::dvec3(p.x(), p.y(), p.z());
    }
    void operator()(const osg::Vec3& a, const osg::Vec3& b, const osg::Vec3& c) { mesh->add(point(a), point(b), point(c)); }
};

class SceneVisitor : public osg::NodeVisitor
{
public:
    explicit SceneVisitor(TriangleMesh& m) : osg::NodeVisitor(TRAVERSE_ACTIVE_CHILDREN), _mesh(m) {}
    void apply(osg::Transform& t) override
    {
        const osg::Matrixd saved = _matrix;
        t.computeLocalToWorldMatrix(_matrix, this);
        traverse(t);
        _matrix = saved;
    }
    void apply(osg::Drawable& d) override
    {
        osg::TriangleFunctor<Collect> f;
        f.mesh = &_mesh;
        f.matrix = _matrix;
        d.accept(f);
    }

private:
    TriangleMesh& _mesh;
    osg::Matrixd _matrix;
};

}

TriangleMesh collectScene(const osgWater::WaterNode& water)
{
    TriangleMesh mesh;
    SceneVisitor v(mesh);
    for (unsigned int i = 0; i < water.getNumChildren(); ++i) const_cast<osg::Node*>(water.getChild(i))->accept(v);
    return mesh;
}

TriangleMesh collectWater(const osgWater::WaterSurface& surface, double t)
{
    TriangleMesh mesh;
    if (const osg::Geometry* g = surface.getGeometry()) {
        osg::TriangleFunctor<Collect> f;
        f.mesh = &mesh;
        f.displace = surface.usesGrid() ? &surface : nullptr;
        f.t = t;
        const_cast<osg::Geometry*>(g)->accept(f);
    }
    return mesh;
}

}
