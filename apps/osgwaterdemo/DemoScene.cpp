#include "DemoScene.h"
#include <osg/Geode>
#include <osg/Geometry>
#include <osg/Material>
#include <osg/MatrixTransform>
#include <osg/ShapeDrawable>
#include <osg/Texture2D>
#include <cmath>

namespace {

osg::Material* material(const osg::Vec4& diffuse, const osg::Vec4& emission = osg::Vec4(0, 0, 0, 1))
{
    osg::Material* m = new osg::Material;
    m->setDiffuse(osg::Material::FRONT_AND_BACK, diffuse);
    m->setAmbient(osg::Material::FRONT_AND_BACK, diffuse);
    m->setEmission(osg::Material::FRONT_AND_BACK, emission);
    return m;
}

// bed depth: flat deep centre, sloping shore rising above the water at the rim
float basinHeight(float x, float y)
{
    const float r = std::sqrt(x * x + y * y);
    const float t = std::min(std::max((r - 12.0f) / 26.0f, 0.0f), 1.0f);
    const float ripple = 0.15f * std::sin(0.7f * x) * std::cos(0.5f * y);
    return -6.0f + 8.0f * t * t * (3.0f - 2.0f * t) + ripple;
}

// colour ramp by height: deep mud, sand, grass; a little deterministic noise across
osg::Texture2D* rampTexture()
{
    osg::ref_ptr<osg::Image> img = new osg::Image;
    const int w = 256, h = 64;
    img->allocateImage(w, h, 1, GL_RGB, GL_UNSIGNED_BYTE);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            const float s = i / float(w - 1);
            const float n = 0.08f * std::sin(i * 12.9898f + j * 78.233f) * std::sin(i * 3.1f - j * 1.7f);
            osg::Vec3 c = s < 0.72f ? osg::Vec3(0.45f, 0.38f, 0.25f) * (0.6f + 0.5f * s) // bed
                                    : osg::Vec3(0.25f, 0.5f, 0.18f);                      // grass
            if (s > 0.66f && s < 0.75f) c = osg::Vec3(0.8f, 0.72f, 0.5f);                 // beach
            c += osg::Vec3(n, n, n);
            unsigned char* p = img->data(i, j);
            for (int k = 0; k < 3; ++k) p[k] = (unsigned char)(std::min(std::max(c[k], 0.0f), 1.0f) * 255);
        }
    osg::Texture2D* t = new osg::Texture2D(img.get());
    t->setWrap(osg::Texture::WRAP_S, osg::Texture::CLAMP_TO_EDGE);
    t->setWrap(osg::Texture::WRAP_T, osg::Texture::REPEAT);
    return t;
}

osg::Node* basin()
{
    const int n = 121;
    const float size = 90.0f;
    osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array;
    osg::ref_ptr<osg::Vec3Array> nrm = new osg::Vec3Array;
    osg::ref_ptr<osg::Vec2Array> tc = new osg::Vec2Array;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const float x = -0.5f * size + size * i / (n - 1), y = -0.5f * size + size * j / (n - 1);
            const float z = basinHeight(x, y), e = 0.05f;
            v->push_back(osg::Vec3(x, y, z));
            osg::Vec3 N(basinHeight(x - e, y) - basinHeight(x + e, y), basinHeight(x, y - e) - basinHeight(x, y + e), 2 * e);
            N.normalize();
            nrm->push_back(N);
            tc->push_back(osg::Vec2((z + 6.0f) / 8.5f, 0.1f * (x + y)));
        }
    osg::ref_ptr<osg::DrawElementsUInt> tris = new osg::DrawElementsUInt(GL_TRIANGLES);
    for (int j = 0; j + 1 < n; ++j)
        for (int i = 0; i + 1 < n; ++i) {
            const unsigned a = j * n + i, b = a + 1, c = a + n, d = c + 1;
            tris->push_back(a); tris->push_back(b); tris->push_back(d);
            tris->push_back(a); tris->push_back(d); tris->push_back(c);
        }
    osg::Geometry* g = new osg::Geometry;
    g->setVertexArray(v.get());
    g->setNormalArray(nrm.get(), osg::Array::BIND_PER_VERTEX);
    g->setTexCoordArray(0, tc.get());
    g->addPrimitiveSet(tris.get());
    osg::Geode* geode = new osg::Geode;
    geode->setName("basin");
    geode->addDrawable(g);
    geode->getOrCreateStateSet()->setTextureAttribute(0, rampTexture());
    geode->getOrCreateStateSet()->setAttribute(material(osg::Vec4(1, 1, 1, 1)));
    return geode;
}

osg::Node* shape(osg::Shape* s, const osg::Vec4& color, const char* name)
{
    osg::Geode* g = new osg::Geode;
    g->setName(name);
    g->addDrawable(new osg::ShapeDrawable(s));
    g->getOrCreateStateSet()->setAttribute(material(color));
    return g;
}

osg::Node* tree(const osg::Vec3& base, float h)
{
    osg::Group* t = new osg::Group;
    t->setName("tree");
    t->addChild(shape(new osg::Cylinder(base + osg::Vec3(0, 0, 0.3f * h), 0.25f, 0.6f * h), osg::Vec4(0.4f, 0.25f, 0.1f, 1), "trunk"));
    t->addChild(shape(new osg::Cone(base + osg::Vec3(0, 0, 0.55f * h), 1.6f, 0.8f * h), osg::Vec4(0.1f, 0.4f, 0.12f, 1), "crown"));
    return t;
}

}

osg::ref_ptr<osg::Group> createDemoScene()
{
    osg::ref_ptr<osg::Group> scene = new osg::Group;
    scene->addChild(basin());
    // a post crossing the water: clipping, and the back-face artefact of thesis fig. 3
    scene->addChild(shape(new osg::Cylinder(osg::Vec3(-3, 6, -1.5f), 0.3f, 6.0f), osg::Vec4(0.8f, 0.1f, 0.1f, 1), "post"));
    scene->addChild(shape(new osg::Sphere(osg::Vec3(4, 2, -5.2f), 1.5f), osg::Vec4(0.5f, 0.5f, 0.55f, 1), "rock"));
    const float ring[][2] = { { 34, 10 }, { 30, 22 }, { 20, 33 }, { -8, 37 }, { -25, 28 }, { 36, -6 } };
    for (const auto& p : ring) scene->addChild(tree(osg::Vec3(p[0], p[1], basinHeight(p[0], p[1])), 8.0f));
    return scene;
}
