#include "SceneTriangles.h"
#include "SceneShading.h"
#include "optics/Srgb.h"
#include <osgWater/Sky>
#include <osgWater/WaterNode>
#include <osg/Geometry>
#include <osg/NodeVisitor>
#include <osg/Transform>
#include <osg/Material>
#include <osg/TriangleFunctor>
#include <osg/TriangleIndexFunctor>
#include <algorithm>

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

// A drawable's look from the state in force where it is drawn (the node's, then the drawable's
// own: a later stateset's material or texture replaces an earlier one; OVERRIDE is not modelled)
struct LookState {
    const osg::Material* material = nullptr;
    const osg::Texture* texture = nullptr;
    void apply(const osg::StateSet* ss)
    {
        if (!ss) return;
        if (auto* m = dynamic_cast<const osg::Material*>(ss->getAttribute(osg::StateAttribute::MATERIAL))) material = m;
        if (auto* t = dynamic_cast<const osg::Texture*>(ss->getTextureAttribute(0, osg::StateAttribute::TEXTURE)))
            texture = t;
    }
    SurfaceLook look() const
    {
        SurfaceLook l;
        auto linear = [](const osg::Vec4& c) {
            return glm::dvec3(osgWater::optics::decodeSrgb(glm::vec3(c.r(), c.g(), c.b())));
        };
        if (material) {
            const osg::Material::Face f = osg::Material::FRONT;
            l.emission = linear(material->getEmission(f));
            l.ambient = linear(material->getAmbient(f));
            l.diffuse = linear(material->getDiffuse(f));
            l.alpha = material->getDiffuse(f).a();
        }
        if (texture && texture->getImage(0)) {
            l.texture = texture->getImage(0);
            l.wrapS = texture->getWrap(osg::Texture::WRAP_S);
            l.wrapT = texture->getWrap(osg::Texture::WRAP_T);
            l.nearest = texture->getFilter(osg::Texture::MAG_FILTER) == osg::Texture::NEAREST;
        }
        return l;
    }
};

// The corners of a Geometry's triangles by index, with their normals and texture coordinates
struct CollectIndexed {
    TriangleMesh* mesh = nullptr;
    SceneShading* shading = nullptr;
    unsigned int look = 0;
    osg::Matrixd matrix, normalMatrix; // normals: by the inverse, from the left (OSG's idiom)
    const osg::Vec3Array* vertices = nullptr;
    const osg::Vec3Array* normals = nullptr; // per vertex, or one for all
    const osg::Vec2Array* texCoords = nullptr;
    glm::dvec3 point(unsigned int i) const
    {
        const osg::Vec3d p = osg::Vec3d((*vertices)[i]) * matrix;
        return glm::dvec3(p.x(), p.y(), p.z());
    }
    void operator()(unsigned int i0, unsigned int i1, unsigned int i2)
    {
        const unsigned int n = unsigned(vertices->size());
        if (i0 >= n || i1 >= n || i2 >= n) return;
        mesh->add(point(i0), point(i1), point(i2));
        if (!shading) return;
        TriangleLook t;
        t.look = look;
        const unsigned int corner[3] = { i0, i1, i2 };
        for (int k = 0; k < 3; ++k) {
            if (normals && !normals->empty()) {
                const osg::Vec3& v = normals->size() == 1 ? (*normals)[0] : (*normals)[std::min<size_t>(corner[k], normals->size() - 1)];
                const osg::Vec3d m = osg::Matrixd::transform3x3(normalMatrix, osg::Vec3d(v));
                t.normal[k] = glm::dvec3(m.x(), m.y(), m.z());
            }
            if (texCoords && corner[k] < texCoords->size())
                t.texCoord[k] = glm::dvec2((*texCoords)[corner[k]].x(), (*texCoords)[corner[k]].y());
        }
        shading->triangles.push_back(t);
    }
};

class SceneVisitor : public osg::NodeVisitor
{
public:
    SceneVisitor(TriangleMesh& m, SceneShading* shading)
        : osg::NodeVisitor(TRAVERSE_ACTIVE_CHILDREN), _mesh(m), _shading(shading)
    {
    }
    void apply(osg::Node& n) override
    {
        const LookState saved = _state;
        _state.apply(n.getStateSet());
        traverse(n);
        _state = saved;
    }
    void apply(osg::Geode& g) override
    {
        // the sky's screen triangle is not in the scene: a ray that meets nothing has its light
        if (dynamic_cast<osgWater::Sky*>(&g)) return;
        apply(static_cast<osg::Node&>(g));
    }
    void apply(osg::Transform& t) override
    {
        const osg::Matrixd saved = _matrix;
        const LookState savedState = _state;
        _state.apply(t.getStateSet());
        t.computeLocalToWorldMatrix(_matrix, this);
        traverse(t);
        _matrix = saved;
        _state = savedState;
    }
    void apply(osg::Drawable& d) override
    {
        LookState state = _state;
        state.apply(d.getStateSet());
        unsigned int look = 0;
        if (_shading) {
            look = unsigned(_shading->looks.size());
            _shading->looks.push_back(state.look());
        }
        osg::Geometry* g = d.asGeometry();
        const osg::Vec3Array* vertices = g ? dynamic_cast<const osg::Vec3Array*>(g->getVertexArray()) : nullptr;
        if (vertices) {
            osg::TriangleIndexFunctor<CollectIndexed> f;
            f.mesh = &_mesh;
            f.shading = _shading;
            f.look = look;
            f.matrix = _matrix;
            f.normalMatrix = osg::Matrixd::inverse(_matrix);
            f.vertices = vertices;
            if (g->getNormalArray() && g->getNormalArray()->getBinding() != osg::Array::BIND_OFF &&
                g->getNormalArray()->getBinding() != osg::Array::BIND_PER_PRIMITIVE_SET)
                f.normals = dynamic_cast<const osg::Vec3Array*>(g->getNormalArray());
            f.texCoords = dynamic_cast<const osg::Vec2Array*>(g->getTexCoordArray(0));
            g->accept(f);
            return;
        }
        // a drawable without a plain vertex array: its triangles, lit fully with no texture
        const size_t before = _mesh.triangles.size();
        osg::TriangleFunctor<Collect> f;
        f.mesh = &_mesh;
        f.matrix = _matrix;
        d.accept(f);
        if (_shading) _shading->triangles.resize(_shading->triangles.size() + (_mesh.triangles.size() - before), TriangleLook{ look });
    }

private:
    TriangleMesh& _mesh;
    SceneShading* _shading;
    osg::Matrixd _matrix;
    LookState _state;
};

}

TriangleMesh collectScene(const osgWater::WaterNode& water, SceneShading* shading)
{
    TriangleMesh mesh;
    SceneVisitor v(mesh, shading);
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
