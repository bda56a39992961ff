// The reference image's parts against what the GPU draws: the scene program's colour of a point
// (SceneShading) is what the view shows there.
#include "GLHarness.h"
#include "RayCaster.h"
#include "SceneShading.h"
#include "SceneTriangles.h"
#include "optics/Srgb.h"
#include <osg/Material>
#include <osg/NodeVisitor>
#include <osg/TriangleFunctor>
#include <osgDB/ReadFile>
#include <osg/Texture2D>
#include <glm/geometric.hpp>
#include <algorithm>
#include <cmath>
#include <iostream>

using namespace bench;
using namespace testing_gl;

namespace {

osg::Vec4 srgbDisplay(float r, float g, float b) { return osg::Vec4(r, g, b, 1.0f); }

// A 4 x 4 texture of unlike colours, filtered bilinearly and repeated
osg::Texture2D* smoothTexture()
{
    osg::ref_ptr<osg::Image> img = new osg::Image;
    img->allocateImage(4, 4, 1, GL_RGB, GL_UNSIGNED_BYTE);
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) {
            unsigned char* p = img->data(i, j);
            p[0] = (unsigned char)(40 + 60 * i);
            p[1] = (unsigned char)(230 - 50 * j);
            p[2] = (unsigned char)(90 + 35 * ((i + 2 * j) % 4));
        }
    osg::Texture2D* t = new osg::Texture2D(img.get());
    t->setFilter(osg::Texture::MIN_FILTER, osg::Texture::LINEAR);
    t->setFilter(osg::Texture::MAG_FILTER, osg::Texture::LINEAR);
    t->setWrap(osg::Texture::WRAP_S, osg::Texture::REPEAT);
    t->setWrap(osg::Texture::WRAP_T, osg::Texture::REPEAT);
    t->setResizeNonPowerOfTwoHint(false);
    return t;
}

// Half a wall at y = 10 from x = x0 to x1, z from -20 to 20, as a 2 x 2 grid of corners with a
// normal each (tilted apart, so n.l varies across it), indexed triangles wound `towardsEye` (seen
// from the origin counter-clockwise: its front) or not
osg::Geometry* wallHalf(float x0, float x1, bool towardsEye)
{
    osg::Geometry* g = new osg::Geometry;
    osg::Vec3Array* v = new osg::Vec3Array;
    osg::Vec3Array* n = new osg::Vec3Array;
    osg::Vec2Array* uv = new osg::Vec2Array;
    const float xs[2] = { x0, x1 }, zs[2] = { -20.0f, 20.0f };
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) {
            v->push_back(osg::Vec3(xs[i], 10.0f, zs[j]));
            osg::Vec3 normal(0.6f * (i ? 1.0f : -1.0f), -1.0f, 0.5f * (j ? 1.0f : -0.3f));
            normal.normalize();
            n->push_back(towardsEye ? normal : -normal);
            uv->push_back(osg::Vec2(0.07f * xs[i], 0.05f * zs[j]));
        }
    g->setVertexArray(v);
    g->setNormalArray(n, osg::Array::BIND_PER_VERTEX);
    g->setTexCoordArray(0, uv);
    // corners 0 (x0, bottom), 1 (x1, bottom), 2 (x0, top), 3 (x1, top); from the origin looking
    // along +y, x runs right and z up: 0 1 3 is counter-clockwise
    osg::DrawElementsUShort* tris = new osg::DrawElementsUShort(GL_TRIANGLES);
    const unsigned short front[6] = { 0, 1, 3, 0, 3, 2 }, back[6] = { 0, 3, 1, 0, 2, 3 };
    for (unsigned short i : towardsEye ? front : back) tris->push_back(i);
    g->addPrimitiveSet(tris);
    return g;
}

}

// A lit, textured wall seen obliquely, one half facing the eye and the other turned away (the
// scene program lights a back face with the other side's n.l): at every pixel the CPU's colour of
// the point the pixel's ray hits, exposed and encoded, is what the view shows, within 2/255 (the
// shader's fitted sRGB curves and the rasteriser's 8-bit texture filtering); the drawable seam's
// pixels are left out (which face a ray exactly on it meets is the rasteriser's rule).
TEST(ReferenceShading, TheSceneProgramsColourAtEachPixelsHit)
{
    Harness h(160, 120);
    REQUIRE_GL(h);
    osg::ref_ptr<osgWater::WaterNode> water = new osgWater::WaterNode;
    water->getSurface()->setLevel(-100.0);
    water->getSurface()->setSize(10.0f);
    osgWater::WaterSettings* s = water->getSettings();
    s->setCausticsEnabled(false);
    s->setGlowEnabled(false);
    s->setSunDirection(osg::Vec3(0.3f, -0.8f, 0.5f));
    s->setSunColor(osg::Vec3(1.1f, 0.95f, 0.8f));
    s->setAmbientColor(osg::Vec3(0.2f, 0.25f, 0.35f));
    osg::ref_ptr<osg::Geode> wall = new osg::Geode;
    wall->addDrawable(wallHalf(-30.0f, 1.5f, true));
    wall->addDrawable(wallHalf(1.5f, 30.0f, false));
    osg::StateSet* ss = wall->getOrCreateStateSet();
    osg::Material* m = new osg::Material;
    m->setEmission(osg::Material::FRONT_AND_BACK, srgbDisplay(0.10f, 0.05f, 0.0f));
    m->setAmbient(osg::Material::FRONT_AND_BACK, srgbDisplay(0.6f, 0.5f, 0.4f));
    m->setDiffuse(osg::Material::FRONT_AND_BACK, srgbDisplay(0.9f, 0.75f, 0.55f));
    ss->setAttribute(m);
    ss->setTextureAttributeAndModes(0, smoothTexture());
    water->addChild(wall.get());
    h.setScene(water.get());
    h.lookAt(osg::Vec3d(0, 0, 0), osg::Vec3d(3, 10, 2));
    h.frame(0.0);
    osg::ref_ptr<osg::Image> img = h.readColor();
    ASSERT_TRUE(allFinite(img.get()));

    SceneShading shading;
    const TriangleMesh mesh = collectScene(*water, &shading);
    ASSERT_EQ(mesh.triangles.size(), 4u);
    ASSERT_EQ(shading.triangles.size(), mesh.triangles.size());
    const RayCaster scene(mesh);
    SceneLight light;
    const osg::Vec3 sun = s->getSunDirection();
    light.towardsSun = glm::normalize(glm::dvec3(sun.x(), sun.y(), sun.z()));
    light.sunColor = glm::dvec3(1.1, 0.95, 0.8);
    light.ambient = glm::dvec3(0.2, 0.25, 0.35);

    const osg::Vec3d eye = h.eye();
    const glm::dvec3 org(eye.x(), eye.y(), eye.z());
    std::vector<int> look(size_t(h.width() * h.height()), -1);
    std::vector<glm::dvec3> colour(look.size());
    for (int y = 0; y < h.height(); ++y)
        for (int x = 0; x < h.width(); ++x) {
            const osg::Vec3d r = h.pixelRay(x, y);
            const glm::dvec3 dir(r.x(), r.y(), r.z());
            const Hit hit = scene.intersect(org, dir);
            if (!hit.hit) continue;
            look[size_t(y * h.width() + x)] = int(shading.triangles[hit.triangle].look);
            colour[size_t(y * h.width() + x)] = shading.shade(mesh, hit, dir, light);
        }
    double worst = 0.0, sum = 0.0;
    int compared = 0, backFacing = 0;
    for (int y = 1; y + 1 < h.height(); ++y)
        for (int x = 1; x + 1 < h.width(); ++x) {
            const size_t i = size_t(y * h.width() + x);
            ASSERT_GE(look[i], 0) << "the wall fills the view: " << x << ", " << y;
            if (look[i - 1] != look[i] || look[i + 1] != look[i]) continue; // the seam
            const glm::vec3 expected = osgWater::optics::display(glm::vec3(colour[i]), 1.0f);
            const float* c = pixel(img.get(), x, y);
            for (int k = 0; k < 3; ++k) {
                const double d = std::fabs(double(c[k]) - expected[k]);
                worst = std::max(worst, d);
                sum += d;
            }
            ++compared;
            backFacing += look[i] == 1;
        }
    std::cout << compared << " pixels (" << backFacing << " of the back face): worst " << worst * 255.0 << "/255, mean "
              << sum / (3.0 * compared) * 255.0 << "/255\n";
    EXPECT_GT(backFacing, compared / 5);
    EXPECT_GT(compared - backFacing, compared / 5);
    EXPECT_LT(worst, 2.0 / 255.0);
}

namespace {

// OSG's own count of the triangles under a node (the functor the GPU-side tools use)
struct CountTriangles {
    size_t* count = nullptr;
    void operator()(const osg::Vec3&, const osg::Vec3&, const osg::Vec3&) { ++*count; }
};
class CountVisitor : public osg::NodeVisitor
{
public:
    CountVisitor() : osg::NodeVisitor(TRAVERSE_ACTIVE_CHILDREN) {}
    void apply(osg::Drawable& d) override
    {
        osg::TriangleFunctor<CountTriangles> f;
        f.count = &count;
        d.accept(f);
    }
    size_t count = 0;
};

}

// On the lake, the shading is collected in step with the triangles: one look per triangle, as
// many triangles as OSG's triangle functor finds, the same triangles as without the shading; the
// lake's textured materials are found (its OBJ files give each a material and a texture) and every
// corner's texture coordinates and normal are finite
TEST(ReferenceShading, TheLakesTrianglesEachHaveTheirLook)
{
    osg::ref_ptr<osg::Node> root = osgDB::readRefNodeFile(OSGWATER_LAKE_SCENE);
    ASSERT_TRUE(root.valid());
    osgWater::WaterNode* water = dynamic_cast<osgWater::WaterNode*>(root.get());
    ASSERT_NE(water, nullptr);
    SceneShading shading;
    const TriangleMesh mesh = collectScene(*water, &shading);
    const TriangleMesh plain = collectScene(*water);
    CountVisitor osgCount;
    for (unsigned int i = 0; i < water->getNumChildren(); ++i) water->getChild(i)->accept(osgCount);
    EXPECT_EQ(mesh.triangles.size(), osgCount.count);
    ASSERT_EQ(shading.triangles.size(), mesh.triangles.size());
    ASSERT_EQ(plain.vertices.size(), mesh.vertices.size());
    EXPECT_TRUE(plain.vertices == mesh.vertices);
    size_t textured = 0;
    for (const SurfaceLook& l : shading.looks) textured += l.texture.valid();
    EXPECT_GE(textured, 6u) << "of " << shading.looks.size() << " looks";
    for (const TriangleLook& t : shading.triangles) {
        ASSERT_LT(t.look, shading.looks.size());
        for (int k = 0; k < 3; ++k) {
            ASSERT_TRUE(std::isfinite(t.texCoord[k].x) && std::isfinite(t.texCoord[k].y));
            ASSERT_TRUE(std::isfinite(glm::dot(t.normal[k], t.normal[k])));
        }
    }
    std::cout << mesh.triangles.size() << " triangles, " << shading.looks.size() << " looks, " << textured << " textured\n";
}
