// The reference image's parts: the scene program's colour of a point (SceneShading) against what
// the GPU draws there, and the Whitted renderer (ReferenceRenderer) against the optics in closed form.
#include "GLHarness.h"
#include "RayCaster.h"
#include "Reference.h"
#include "ImageCompare.h"
#include "ReferenceCaustics.h"
#include "ReferenceRenderer.h"
#include "WaterCaster.h"
#include "SceneShading.h"
#include "SceneTriangles.h"
#include "optics/Optics.h"
#include "optics/Srgb.h"
#include "surface/SpectralWaves.h"
#include <osg/Material>
#include <osg/NodeVisitor>
#include <osg/TriangleFunctor>
#include <osgDB/ReadFile>
#include <osgWater/Sky>
#include <osg/Texture2D>
#include <glm/geometric.hpp>
#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>

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
// many triangles as OSG's triangle functor finds (its sky aside), the same triangles as without the shading; the
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
    int skies = 0;
    for (unsigned int i = 0; i < water->getNumChildren(); ++i) {
        // the lake's clear sky is the light of rays that meet nothing, not a triangle
        if (dynamic_cast<osgWater::Sky*>(water->getChild(i))) ++skies;
        else water->getChild(i)->accept(osgCount);
    }
    EXPECT_EQ(skies, 1);
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

namespace {

// A water node's reference renderer and everything it refers to, at time 0
struct ReferenceScene {
    SceneShading shading;
    std::unique_ptr<RayCaster> scene;
    std::unique_ptr<WaterCaster> waterMesh;
    std::unique_ptr<Reference> ref;
    std::unique_ptr<ReferenceRenderer> renderer;
    ReferenceScene(const osgWater::WaterNode& water, const ImageSetup& setup)
    {
        scene = std::make_unique<RayCaster>(collectScene(water, &shading));
        waterMesh = std::make_unique<WaterCaster>(*water.getSurface(), 0.0);
        const osgWater::WaterSettings& s = *water.getSettings();
        ref = std::make_unique<Reference>(*scene, *waterMesh, *water.getSurface(), 0.0, Media{ s.getAirIOR(), s.getWaterIOR() });
        renderer = std::make_unique<ReferenceRenderer>(*ref, shading, setup);
    }
};

glm::dvec3 linear(const osg::Vec4& displayColour)
{
    return glm::dvec3(osgWater::optics::decodeSrgb(glm::vec3(displayColour.r(), displayColour.g(), displayColour.b())));
}

const osg::Vec4 kClear(0.45f, 0.6f, 0.85f, 1.0f);

// Water whose body shows nothing of what lies below (black, opaque) under a sky of one colour,
// `skyLight`, 400 m wide: a ray's light is what the water's Fresnel passes on of the sky
ImageSetup blackWaterUnderSky(osgWater::WaterNode& water, const glm::dvec3& skyLight)
{
    water.getSurface()->setSize(400.0f);
    ImageSetup setup = imageSetup(water, kClear);
    setup.body = glm::dvec3(0.0);
    setup.extinction = glm::dvec3(1e3);
    setup.sky = [skyLight](const glm::dvec3&) { return skyLight; };
    return setup;
}

}

// Flat water over a checkerboard 2 m down (its texels by the nearest, as the GPU magnifies them):
// every pixel is the Optics mirror's colour, eq. 9 with exact Fresnel of eq. 5 along Snell's path
// (the water's per-channel extinction towards its body colour) and the sky (the clear colour)
// along the mirror ray, within 1e-5 (single-precision tint); pixels whose refracted hit lies within
// 0.1 mm of a cell's edge (which cell is a matter of rounding) or past the board are left out.
TEST(ReferenceRenderer, FlatWaterOverACheckerboardIsTheOpticsMirror)
{
    osg::ref_ptr<osgWater::WaterNode> water = new osgWater::WaterNode;
    water->getSurface()->setWaves({});
    water->getSurface()->setSize(400.0f);
    const float depth = 2.0f, cell = 0.5f;
    water->addChild(checkerPlane(-depth, 120.0f, cell));
    const ImageSetup setup = imageSetup(*water, kClear);
    ReferenceScene rs(*water, setup);
    const osgWater::WaterSettings& s = *water->getSettings();
    const double n1 = s.getAirIOR(), n2 = s.getWaterIOR();
    const osg::Matrixd view = osg::Matrixd::lookAt(osg::Vec3d(0, -4, 3), osg::Vec3d(0, 6, -2), osg::Vec3d(0, 0, 1));
    const osg::Matrixd proj = osg::Matrixd::perspective(50.0, 4.0 / 3.0, 0.1, 1000.0);
    std::vector<double> error(80 * 60, -1.0);
    forEachPixelRay(view, proj, 80, 60, [&](int x, int y, const glm::dvec3& eye, const glm::dvec3& d) {
        const glm::dvec3 got = rs.renderer->radiance(eye, d, false);
        glm::dvec3 expected = setup.sky(d);
        if (d.z < 0.0) {
            const glm::dvec3 U = eye + d * (-eye.z / d.z);
            glm::dvec3 R;
            ASSERT_TRUE(snell(d, glm::dvec3(0, 0, 1), n1, n2, R));
            const glm::dvec3 X = U + R * ((-depth - U.z) / R.z);
            const double fx = X.x / cell - std::floor(X.x / cell), fy = X.y / cell - std::floor(X.y / cell);
            if (std::min({ fx, 1.0 - fx, fy, 1.0 - fy }) * cell < 1e-4) return;
            if (std::max(std::fabs(X.x), std::fabs(X.y)) > 59.0) return; // past the board
            const float bed = checkerAt(X.x, X.y, cell);
            const glm::vec3 refr = osgWater::optics::waterTint(
                glm::vec3(bed), glm::vec3(setup.body),
                osgWater::optics::attenuation(glm::vec3(setup.extinction), float(glm::length(X - U))));
            const double F = fresnelExact(-d.z, n1, n2);
            expected = F * setup.sky(glm::reflect(d, glm::dvec3(0, 0, 1))) + (1.0 - F) * glm::dvec3(refr);
        }
        error[size_t(y * 80 + x)] = glm::length(got - expected);
    });
    double worst = 0.0;
    int compared = 0;
    for (double e : error)
        if (e >= 0.0) {
            worst = std::max(worst, e);
            ++compared;
        }
    std::cout << compared << " pixels, worst " << worst << "\n";
    EXPECT_GT(compared, 3000);
    EXPECT_LT(worst, 1e-5);
}

// Calm water mirrors a red (emissive) quad standing on it: a pixel shows F red + (1 - F) the water
// below wherever its mirror ray meets the quad, and F sky + (1 - F) the water below elsewhere,
// with F exact Fresnel; the quad itself where the eye ray meets it first. Pixels whose ray passes
// within 0.1 mm of the quad's edges are left out.
TEST(ReferenceRenderer, CalmWaterMirrorsARedQuadWhereTheMirrorSays)
{
    osg::ref_ptr<osgWater::WaterNode> water = new osgWater::WaterNode;
    water->getSurface()->setWaves({});
    water->getSurface()->setSize(400.0f);
    const osg::Vec4 red(0.9f, 0.05f, 0.05f, 1.0f);
    const double qx = 1.5, qz0 = 0.2, qz1 = 2.0, qy = 10.0; // x in [-qx, qx], z in [qz0, qz1], at y = qy
    water->addChild(emissiveQuad(osg::Vec3(-qx, qy, qz0), osg::Vec3(qx, qy, qz0), osg::Vec3(qx, qy, qz1),
                                 osg::Vec3(-qx, qy, qz1), red));
    ImageSetup setup = imageSetup(*water, kClear);
    ReferenceScene rs(*water, setup);
    const osgWater::WaterSettings& s = *water->getSettings();
    const double n1 = s.getAirIOR(), n2 = s.getWaterIOR();
    // what the quad's plane shows along a ray: the quad (0: outside it, -1: too near an edge)
    auto onQuad = [&](const glm::dvec3& o, const glm::dvec3& d) {
        if (d.y <= 0.0) return 0;
        const glm::dvec3 p = o + d * ((qy - o.y) / d.y);
        const double margin = std::min({ qx - std::fabs(p.x), p.z - qz0, qz1 - p.z });
        return std::fabs(margin) < 1e-4 ? -1 : margin > 0.0 ? 1 : 0;
    };
    const osg::Matrixd view = osg::Matrixd::lookAt(osg::Vec3d(0.3, 0, 1.2), osg::Vec3d(0, 10, -0.8), osg::Vec3d(0, 0, 1));
    const osg::Matrixd proj = osg::Matrixd::perspective(50.0, 4.0 / 3.0, 0.1, 1000.0);
    std::vector<double> error(120 * 90, -1.0);
    std::vector<int> mirrored(120 * 90, 0);
    forEachPixelRay(view, proj, 120, 90, [&](int x, int y, const glm::dvec3& eye, const glm::dvec3& d) {
        const glm::dvec3 got = rs.renderer->radiance(eye, d, false);
        const int direct = onQuad(eye, d);
        const double tQuad = d.y > 0.0 ? (qy - eye.y) / d.y : 1e30, tWater = d.z < 0.0 ? -eye.z / d.z : 1e30;
        glm::dvec3 expected;
        if (direct == -1 && tQuad < tWater) return;
        if (direct == 1 && tQuad < tWater) {
            expected = linear(red);
        } else if (d.z < 0.0) {
            const glm::dvec3 U = eye + d * tWater, Rr = glm::reflect(d, glm::dvec3(0, 0, 1));
            const int seen = onQuad(U, Rr);
            if (seen == -1) return;
            glm::dvec3 R;
            snell(d, glm::dvec3(0, 0, 1), n1, n2, R);
            const double F = fresnelExact(-d.z, n1, n2);
            const glm::dvec3 below = setup.body; // no bed: the body colour
            expected = F * (seen ? linear(red) : setup.sky(Rr)) + (1.0 - F) * below;
            mirrored[size_t(y * 120 + x)] = seen;
        } else {
            expected = setup.sky(d);
        }
        error[size_t(y * 120 + x)] = glm::length(got - expected);
    });
    double worst = 0.0;
    int compared = 0, reflections = 0;
    for (size_t i = 0; i < error.size(); ++i)
        if (error[i] >= 0.0) {
            worst = std::max(worst, error[i]);
            ++compared;
            reflections += mirrored[i];
        }
    std::cout << compared << " pixels, " << reflections << " show the quad's reflection, worst " << worst << "\n";
    EXPECT_GT(reflections, 300);
    EXPECT_LT(worst, 1e-6);
}

// A ray the waves send back under the level meets the water again and is followed: with water
// that shows nothing of what lies below (a black body, opaque), a path that reflects twice and
// then reaches the sky carries F1 F2 of the sky's light, F1 and F2 exact Fresnel at normals found
// here independently (marching the wave's height along the ray in 2 mm steps); dropped, it would be
// dark, and taken as the sky, F1 of it (which is what a limit of one water hit gives). Rays meeting
// the water within 84 degrees of its normal (not clipping a crest) are taken.
TEST(ReferenceRenderer, ARaySentBackUnderTheLevelIsFollowed)
{
    osg::ref_ptr<osgWater::WaterNode> water = new osgWater::WaterNode;
    osgWater::WaterSurface* surface = water->getSurface();
    surface->setWaves({ makeWave(0.0f, 1.0f, 3.0f, 0.35f) }); // slopes up to 0.73
    const glm::dvec3 sky(0.2, 0.5, 1.0);
    const ImageSetup setup = blackWaterUnderSky(*water, sky);
    ReferenceScene rs(*water, setup);
    ImageSetup oneHit = setup;
    oneHit.maxWaterHits = 1;
    const ReferenceRenderer stopsAtOne(*rs.ref, rs.shading, oneHit);
    const double n1 = water->getSettings()->getAirIOR(), n2 = water->getSettings()->getWaterIOR();
    // the first crossing of the surface along o + s d (s up to 20 m; none once rising above the
    // crests), by marching and bisection
    auto crossing = [&](const glm::dvec3& o, const glm::dvec3& d, glm::dvec3& at) {
        auto above = [&](double s) { const glm::dvec3 p = o + s * d; return p.z - surface->height(p.x, p.y, 0.0); };
        double s0 = 1e-4;
        const double f0 = above(s0);
        for (double s1 = s0 + 0.002; s1 < 20.0 && (d.z < 0.0 || (o + s0 * d).z < 0.36); s0 = s1, s1 += 0.002) {
            if ((above(s1) > 0.0) == (f0 > 0.0)) continue;
            for (int i = 0; i < 60; ++i) {
                const double m = 0.5 * (s0 + s1);
                ((above(m) > 0.0) == (f0 > 0.0) ? s0 : s1) = m;
            }
            at = o + 0.5 * (s0 + s1) * d;
            return true;
        }
        return false;
    };
    auto normalAt = [&](const glm::dvec3& p) {
        const osg::Vec3d n = surface->normal(p.x, p.y, 0.0);
        return glm::normalize(glm::dvec3(n.x(), n.y(), n.z()));
    };
    int followed = 0;
    double worst = 0.0, worstAtTheLimit = 0.0;
    for (int i = 0; i < 60 * 80 && followed < 20; ++i) {
        const glm::dvec3 eye(0.0, 0.05 * (i % 60), 0.6); // over a wavelength, 25 cm above the crests
        const double down = 0.2 + 0.005 * (i / 60);       // descending 11 to 31 degrees, along the waves
        const glm::dvec3 d = glm::normalize(glm::dvec3(0.0, 1.0, -down));
        glm::dvec3 U1, U2, U3;
        if (!crossing(eye, d, U1)) continue;
        const glm::dvec3 N1 = normalAt(U1), R1 = glm::reflect(d, N1);
        if (-glm::dot(d, N1) < 0.1) continue; // a ray that clips a crest: see ReferenceRenderer.h
        if (R1.z >= 0.0 || !crossing(U1, R1, U2)) continue; // not sent back under the level
        const glm::dvec3 N2 = normalAt(U2), R2 = glm::reflect(R1, N2);
        if (-glm::dot(R1, N2) < 0.1 || R2.z <= 0.0 || crossing(U2, R2, U3)) continue; // grazing, or not straight to the sky
        const double F1 = fresnelExact(-glm::dot(d, N1), n1, n2), F2 = fresnelExact(-glm::dot(R1, N2), n1, n2);
        const glm::dvec3 got = rs.renderer->radiance(eye, d, false);
        const glm::dvec3 expected = F1 * F2 * sky;
        worst = std::max(worst, glm::length(got - expected) / glm::length(expected));
        EXPECT_GT(glm::length(got - F1 * sky), 0.5 * glm::length(F1 * sky - expected)) << "taken as the sky";
        // past the limit of water hits the ray goes on as if the water were not there: to the sky
        worstAtTheLimit = std::max(worstAtTheLimit, glm::length(stopsAtOne.radiance(eye, d, false) - F1 * sky) / glm::length(F1 * sky));
        ++followed;
    }
    std::cout << followed << " rays sent back under the level, worst relative error " << worst << " (with one water hit, "
              << worstAtTheLimit << " from the sky's F1)\n";
    EXPECT_GE(followed, 5);
    EXPECT_LT(worst, 1e-9);
    EXPECT_LT(worstAtTheLimit, 1e-9);
}

// An eye a hair above the water sees it at once: its rays meet the water micrometres away, and
// none may start past that (a ray's start is pushed along it only where it leaves a surface it
// met). Over flat water whose body shows nothing (black, opaque), a ray 20 degrees down from eyes
// 42 m from the origin, from 1 um to 1 m above the level, carries F of the sky's light, F exact
// Fresnel at 70 degrees. Started 1e-6 of the distance from the origin along (42 um), the ray from
// 1 um was already under the level and saw the sky whole.
TEST(ReferenceRenderer, AnEyeAMicrometreAboveTheWaterSeesItsSurface)
{
    osg::ref_ptr<osgWater::WaterNode> water = new osgWater::WaterNode;
    water->getSurface()->setWaves({});
    const glm::dvec3 sky(0.2, 0.5, 1.0);
    ReferenceScene rs(*water, blackWaterUnderSky(*water, sky));
    const double n1 = water->getSettings()->getAirIOR(), n2 = water->getSettings()->getWaterIOR();
    const glm::dvec3 d = glm::normalize(glm::dvec3(0.0, std::cos(osg::DegreesToRadians(20.0)), -std::sin(osg::DegreesToRadians(20.0))));
    const glm::dvec3 expected = fresnelExact(-d.z, n1, n2) * sky;
    for (double height : { 1e-6, 1e-3, 1.0 }) {
        const glm::dvec3 got = rs.renderer->radiance(glm::dvec3(30.0, -30.0, height), d, false);
        EXPECT_LT(glm::length(got - expected) / glm::length(expected), 1e-9)
            << height << " m above: got (" << got.x << ", " << got.y << ", " << got.z << ")";
    }
}

// A sky under the water node is the light of the rays that meet nothing, not a triangle of the
// scene: the reference collects the quad's two triangles alone, and a ray up into the sky carries
// the sky's own radiance (without a sky, the clear colour decoded)
TEST(ReferenceRenderer, ASkyIsTheLightOfRaysThatMeetNothing)
{
    osg::ref_ptr<osgWater::WaterNode> water = new osgWater::WaterNode;
    water->addChild(emissiveQuad(osg::Vec3(-1, 5, 1), osg::Vec3(1, 5, 1), osg::Vec3(1, 5, 2), osg::Vec3(-1, 5, 2),
                                 osg::Vec4(1, 0, 0, 1)));
    const glm::dvec3 up = glm::normalize(glm::dvec3(0.2, -0.3, 1.0));
    {
        ReferenceScene rs(*water, imageSetup(*water, kClear));
        EXPECT_LT(glm::length(rs.renderer->radiance(glm::dvec3(0, 0, 1), up, false) - linear(kClear)), 1e-12);
    }
    osg::ref_ptr<osgWater::Sky> sky = new osgWater::Sky;
    sky->setSunDirection(osg::Vec3(0.5f, 0.5f, 0.7f));
    water->addChild(sky.get());
    SceneShading shading;
    EXPECT_EQ(collectScene(*water, &shading).triangles.size(), 2u);
    ReferenceScene rs(*water, imageSetup(*water, kClear));
    const osg::Vec3 expected = sky->getRadiance(osg::Vec3(float(up.x), float(up.y), float(up.z)));
    const glm::dvec3 got = rs.renderer->radiance(glm::dvec3(0, 0, 1), up, false);
    EXPECT_LT(glm::length(got - glm::dvec3(expected.x(), expected.y(), expected.z())), 1e-7);
    EXPECT_GT(glm::length(got - linear(kClear)), 0.01);
}

// A pixel's light is the mean over its area: straight down onto a checkerboard of white and black
// (emissive, nearest texels) parallel to the image, each pixel exactly two cells wide and its
// edges on the cells' edges, 4 x 4 rays a pixel give every pixel one half to 1e-9; the pixel
// centres alone sit on the cells' corners and give black or white (the reference aliased, as one
// ray a pixel is); the two halves of a pixel's rays measure the image's noise, and the noisy
// pixels take more rays
TEST(ReferenceRenderer, APixelsLightIsTheMeanOverItsArea)
{
    const int w = 64, h = 48;
    const double height = 10.0, fovy = 30.0, aspect = double(w) / h;
    const double halfHeight = height * std::tan(osg::DegreesToRadians(fovy / 2.0)); // at the board
    const float cell = float(halfHeight / h); // a pixel: two cells each way
    osg::ref_ptr<osgWater::WaterNode> water = new osgWater::WaterNode;
    water->getSurface()->setLevel(-100.0); // far below the board, out of sight
    water->getSurface()->setSize(1.0f);
    water->addChild(checkerPlane(0.0f, 4.0f * float(halfHeight * aspect), cell));
    ImageSetup setup = imageSetup(*water, kClear);
    ReferenceScene rs(*water, setup);
    const osg::Matrixd view = osg::Matrixd::lookAt(osg::Vec3d(0, 0, height), osg::Vec3d(0, 0, 0), osg::Vec3d(0, 1, 0));
    const osg::Matrixd proj = osg::Matrixd::perspective(fovy, aspect, 0.1, 100.0);
    setup.samplesPerAxis = 4;
    const std::vector<glm::vec3> smooth = ReferenceRenderer(*rs.ref, rs.shading, setup).render(view, proj, w, h);
    setup.samplesPerAxis = 1;
    const std::vector<glm::vec3> centres = ReferenceRenderer(*rs.ref, rs.shading, setup).render(view, proj, w, h);
    double worst = 0.0, centreDeviation = 0.0;
    for (size_t i = 0; i < smooth.size(); ++i) {
        for (int k = 0; k < 3; ++k) worst = std::max(worst, std::fabs(double(smooth[i][k]) - 0.5));
        centreDeviation += std::fabs(double(centres[i].x) - 0.5) / double(centres.size());
    }
    std::cout << "4 x 4 rays: worst " << worst << " from a half; one ray: " << centreDeviation << " on average\n";
    EXPECT_LT(worst, 1e-6); // single-precision image
    EXPECT_GT(centreDeviation, 0.4);

    // The image's own noise from two halves of its rays, the n x n grid split as a checkerboard:
    // with 2 x 2 rays each falls in a cell of its own, so one half sees only black cells and the
    // other only white ones (the pixel itself is grey), and the noise, half the mean CIEDE2000
    // between the halves, is half of black against white's 100. Identical halves have none.
    setup.samplesPerAxis = 2;
    RenderExtras extras;
    const std::vector<glm::vec3> grey = ReferenceRenderer(*rs.ref, rs.shading, setup).render(view, proj, w, h, &extras);
    const std::vector<bool> everyPixel(grey.size(), true);
    double spread = 0.0;
    for (size_t i = 0; i < grey.size(); ++i)
        spread = std::max(spread, double(std::fabs(extras.halves[0][i].x - extras.halves[1][i].x)));
    EXPECT_GT(spread, 1.0 - 1e-6) << "one half black, the other white";
    EXPECT_NEAR(referenceNoise(extras.halves[0], extras.halves[1], DisplayTransform{}, everyPixel), 50.0, 1e-3);
    EXPECT_EQ(referenceNoise(grey, grey, DisplayTransform{}, everyPixel), 0.0);
    EXPECT_EQ(extras.refinedPixels, 0u) << "no refining asked for";

    // Pixels whose halves disagree take m x m more rays: here every pixel, 4 x 4 more, whose cells
    // (a quarter of a board cell each) fall 8 on white and 8 on black, half of each in either half:
    // the pixel stays one half grey, its halves move to 0.4 and 0.6 (2 + 8 rays each), to 1e-6
    setup.refineSamplesPerAxis = 4;
    const std::vector<glm::vec3> refined = ReferenceRenderer(*rs.ref, rs.shading, setup).render(view, proj, w, h, &extras);
    EXPECT_EQ(extras.refinedPixels, refined.size());
    double worstRefined = 0.0, worstHalf = 0.0;
    for (size_t i = 0; i < refined.size(); ++i) {
        worstRefined = std::max(worstRefined, double(std::fabs(refined[i].x - 0.5f)));
        const float lo = std::min(extras.halves[0][i].x, extras.halves[1][i].x), hi = std::max(extras.halves[0][i].x, extras.halves[1][i].x);
        worstHalf = std::max({ worstHalf, double(std::fabs(lo - 0.4f)), double(std::fabs(hi - 0.6f)) });
    }
    EXPECT_LT(worstRefined, 1e-6);
    EXPECT_LT(worstHalf, 1e-6);
    // a smooth image has no noisy pixel to refine: the board seen from 4 x 4 rays a pixel
    setup.samplesPerAxis = 4;
    ReferenceRenderer(*rs.ref, rs.shading, setup).render(view, proj, w, h, &extras);
    EXPECT_EQ(extras.refinedPixels, 0u);
}

// The sky is the same light both ways round: calm water over a bed under an osgWater::Sky, drawn by
// the kit (the view's sky, and the reflection pass's mirrored sky on the water) and traced by the
// reference (a mirror ray that meets nothing takes the Sky's radiance along it), agree at every
// pixel, water and sky, once exposed and encoded, with the reference's exact Fresnel: within 2/255
// (the passes' half floats and texel filtering, as the Optics mirror's test), and within 4/255 on
// water whose mirror rays rise less than 3 degrees, where the sky brightens toward the horizon
// faster than a texel of the reflection pass resolves. The sun stands behind the eye, so no glow is
// in view.
TEST(ReferenceRenderer, TheReflectionPassesSkyIsTheReferencesSky)
{
    Harness h(200, 150);
    REQUIRE_GL(h);
    osg::ref_ptr<osgWater::WaterNode> water = flatWaterOverBed(1.5f);
    water->getSettings()->setFresnelModel(osgWater::WaterSettings::FRESNEL_EXACT);
    osg::ref_ptr<osgWater::Sky> sky = new osgWater::Sky;
    sky->setSunDirection(osg::Vec3(0.0f, -0.8f, 0.6f));
    water->addChild(sky.get());
    h.setScene(water.get());
    h.lookAt(osg::Vec3d(0, 0, 3), osg::Vec3d(0, 10, 0.5)); // the horizon across the middle
    h.frame(0.0);
    osg::ref_ptr<osg::Image> img = h.readColor();
    ASSERT_TRUE(allFinite(img.get()));
    ReferenceScene rs(*water, imageSetup(*water, kClear));
    const osg::Vec3d eye = h.eye();
    double worst[3] = { 0.0, 0.0, 0.0 }; // the sky, the water, the water by the horizon
    int pixels[3] = { 0, 0, 0 };
    for (int y = 0; y < h.height(); ++y)
        for (int x = 0; x < h.width(); ++x) {
            const osg::Vec3d r = h.pixelRay(x, y);
            const glm::dvec3 d = glm::normalize(glm::dvec3(r.x(), r.y(), r.z()));
            if (std::fabs(d.z) < 0.01) continue; // the horizon's row: which side is the rasteriser's rule
            const glm::dvec3 light = rs.renderer->radiance(glm::dvec3(eye.x(), eye.y(), eye.z()), d, false);
            const glm::vec3 expected = osgWater::optics::display(glm::vec3(light), 1.0f);
            const float* c = pixel(img.get(), x, y);
            const int part = d.z > 0.0 ? 0 : d.z < -std::sin(osg::DegreesToRadians(3.0)) ? 1 : 2;
            for (int k = 0; k < 3; ++k) worst[part] = std::max(worst[part], std::fabs(double(c[k]) - expected[k]));
            ++pixels[part];
        }
    std::cout << pixels[0] << " sky pixels, worst " << worst[0] * 255.0 << "/255; " << pixels[1] << " water pixels, worst "
              << worst[1] * 255.0 << "/255; " << pixels[2] << " by the horizon, worst " << worst[2] * 255.0 << "/255\n";
    EXPECT_GT(pixels[0], 5000);
    EXPECT_GT(pixels[1], 5000);
    EXPECT_GT(pixels[2], 400);
    EXPECT_LT(worst[0], 2.0 / 255.0);
    EXPECT_LT(worst[1], 2.0 / 255.0);
    EXPECT_LT(worst[2], 4.0 / 255.0);
}

// The direct sun under the water, as the reference takes it from the photons: over a sun's window
// 20 m square (4 x 4 texels of distinct values), a bed 2 m down and a 20 cm plate 1 m above part of
// it, the sun 32 degrees from the zenith:
// - above the level, and outside the window, all of the sun (the scene program reads no caustics);
// - at a texel's centre its value, halfway between two centres their mean (GL_LINEAR), times the
//   intensity and each channel's extra fading over the depth, exp(-c 2 m), to 1e-12;
// - under the plate along the sun's path refracted into the water (Snell: 0.43 m aside per metre of
//   rise) none, though the straight sun ray (0.63 m a metre) would pass beside the plate;
// - the scene program's colour of the bed there: the sun's diffuse term times that share.
TEST(ReferenceCaustics, TheSunUnderTheWaterIsThePhotonsTexelsAlongTheRefractedPath)
{
    TriangleMesh mesh;
    const double bed = -2.0;
    mesh.add(glm::dvec3(-30, -30, bed), glm::dvec3(30, -30, bed), glm::dvec3(30, 30, bed));
    mesh.add(glm::dvec3(-30, -30, bed), glm::dvec3(30, 30, bed), glm::dvec3(-30, 30, bed));
    const glm::dvec3 P(1.25, -1.25, bed); // under the plate: its refracted path rises through it
    const double x0 = P.x + 0.33, x1 = P.x + 0.53, pz = -1.0;
    mesh.add(glm::dvec3(x0, P.y - 0.5, pz), glm::dvec3(x1, P.y - 0.5, pz), glm::dvec3(x1, P.y + 0.5, pz));
    mesh.add(glm::dvec3(x0, P.y - 0.5, pz), glm::dvec3(x1, P.y + 0.5, pz), glm::dvec3(x0, P.y + 0.5, pz));
    const RayCaster scene(mesh);

    PhotonImage photons;
    photons.resolution = 4;
    for (int k = 0; k < 16; ++k) photons.value.push_back(0.5f + 0.25f * float(k));
    UnderwaterSun sun;
    sun.photons = &photons;
    sun.localToSun = osg::Matrixd::translate(10.0, 10.0, 0.0) * osg::Matrixd::scale(0.05, 0.05, 1.0); // [-10, 10]^2 -> [0, 1]^2
    sun.intensity = 1.5;
    sun.channelExtinction = glm::dvec3(0.3, 0.0, -0.05);
    sun.level = 0.0;
    sun.towardsSun = glm::normalize(glm::dvec3(0.5, 0.0, 0.8));
    sun.airIOR = 1.0;
    sun.waterIOR = 1.333;
    const auto share = underwaterSunShare(sun, scene);
    auto expectedAt = [&](double value) {
        return sun.intensity * value *
               glm::dvec3(std::exp(-0.3 * 2.0), 1.0, std::exp(0.05 * 2.0));
    };
    EXPECT_EQ(share(glm::dvec3(1.0, 1.0, 0.5)), glm::dvec3(1.0)) << "above the level";
    EXPECT_EQ(share(glm::dvec3(15.0, 1.0, bed)), glm::dvec3(1.0)) << "outside the window";
    // texel (1, 2)'s centre: x = -10 + 1.5 * 5, y = -10 + 2.5 * 5
    const glm::dvec3 centre(-2.5, 2.5, bed), between(0.0, 2.5, bed);
    EXPECT_LT(glm::length(share(centre) - expectedAt(photons.value[2 * 4 + 1])), 1e-12);
    EXPECT_LT(glm::length(share(between) - expectedAt(0.5 * (photons.value[2 * 4 + 1] + photons.value[2 * 4 + 2]))), 1e-12);
    // under the plate: the refracted path meets it, the straight one passes beside it
    const glm::dvec3 straight = sun.towardsSun * ((pz - bed) / sun.towardsSun.z);
    ASSERT_GT(P.x + straight.x, x1) << "the straight ray passes beside the plate";
    EXPECT_EQ(share(P), glm::dvec3(0.0)) << "in the plate's shadow";
    EXPECT_GT(share(P + glm::dvec3(0.0, 1.0, 0.0)).y, 0.5) << "beside the plate's shadow";

    // the scene program's colour there: emission + ambient + diffuse sun times the share
    SceneShading shading;
    shading.looks.resize(1);
    shading.looks[0].emission = glm::dvec3(0.0);
    shading.looks[0].ambient = glm::dvec3(0.2);
    shading.looks[0].diffuse = glm::dvec3(0.5, 0.6, 0.7);
    shading.triangles.resize(mesh.triangles.size());
    SceneLight light;
    light.towardsSun = sun.towardsSun;
    light.sunColor = glm::dvec3(1.0, 0.9, 0.8);
    light.ambient = glm::dvec3(0.25);
    light.sunShare = share;
    const glm::dvec3 down(0.0, 0.0, -1.0);
    const Hit atCentre = scene.intersect(centre + glm::dvec3(0.0, 0.0, 1.0), down);
    ASSERT_TRUE(atCentre.hit);
    const glm::dvec3 unlit = 0.2 * light.ambient, sunTerm = shading.looks[0].diffuse * light.sunColor; // n.l 1: no normals
    EXPECT_LT(glm::length(shading.shade(mesh, atCentre, down, light) - (unlit + sunTerm * expectedAt(photons.value[9]))), 1e-12);
    const Hit atP = scene.intersect(P + glm::dvec3(0.0, 0.0, 0.5), down);
    ASSERT_TRUE(atP.hit);
    EXPECT_LT(glm::length(shading.shade(mesh, atP, down, light) - unlit), 1e-12);
}

// The reference's facets under the roughness (drawFacet): drawn in proportion to the area each shows
// the ray, they all face it and their Fresnel is the kit's Fresnel over the hidden slopes
// (optics::fresnelOverSlopes, exact model), from overhead to grazing; a seed draws one facet; no
// roughness, the waves' own normal
TEST(ReferenceRenderer, FacetsDrawnFromTheRoughnessGiveTheKitsFresnelOverSlopes)
{
    const double roughness = 0.02, n1 = 1.0, n2 = 1.333;
    const glm::dvec3 up(0.0, 0.0, 1.0);
    for (double cosE : { 0.95, 0.5, 0.2, 0.08 }) {
        const glm::dvec3 dir(std::sqrt(1.0 - cosE * cosE), 0.0, -cosE); // down, towards +x
        double met = 0.0, reflected = 0.0;
        const int n = 200000;
        for (int i = 0; i < n; ++i) {
            const FacetDraw f = drawFacet(up, roughness, dir, std::uint64_t(i) * 0x9e3779b97f4a7c15ull);
            if (!f.met) continue;
            ASSERT_LT(glm::dot(f.normal, dir), 0.0) << "a facet the ray meets faces it";
            met += 1.0;
            reflected += fresnelExact(-glm::dot(dir, f.normal), n1, n2);
        }
        const double kit = osgWater::optics::fresnelOverSlopes(2, float(cosE), float(roughness), float(n1), float(n2), 5.0f);
        std::cout << "cos " << cosE << ": met " << met / n << ", F " << reflected / met << " (kit " << kit
                  << ", the mean facet " << fresnelExact(cosE, n1, n2) << ")\n";
        EXPECT_NEAR(met / n, 1.0, 0.01) << cosE;
        EXPECT_NEAR(reflected / met, kit, 0.03 * kit) << cosE;
    }
    const glm::dvec3 dir = glm::normalize(glm::dvec3(1.0, 0.2, -0.3));
    const FacetDraw a = drawFacet(up, roughness, dir, 42), b = drawFacet(up, roughness, dir, 42), c = drawFacet(up, roughness, dir, 43);
    EXPECT_EQ(a.normal, b.normal);
    EXPECT_NE(a.normal, c.normal);
    const FacetDraw smooth = drawFacet(up, 0.0, dir, 42);
    EXPECT_EQ(smooth.normal, up);
    EXPECT_TRUE(smooth.met);
}

// Where the eye grazes wind-driven water, the facets that reflect most are the least tilted, and
// their mirror rays rise so low that the next wave meets a share of them (Smith's shadowing: that
// light passes mostly into the water). Over a breeze's waves (the kit's default wind over 140 m of
// fetch; the reference's own surface, at its own facets), rays from 2.5 m up at cosines 0.05, 0.1
// and 0.2 to the level, each from its own place along 100 m of water and running its own way round
// the circle: the share of their reflected light (exact Fresnel at the facet met) whose mirror rays
// leave the waves, against the kit's (optics::fresnelAndLean's last, exact model, the water's mean
// square slope as the roughness: a far pixel hides all its slopes), within 0.03 (measured 0.877,
// 0.850, 0.827 against 0.877, 0.834, 0.805); their reflectance against its first within 10%: the
// reference's is 8% and 5% lower at cosines 0.05 and 0.1 (0.372, 0.333 against 0.403, 0.350), which
// Smith's visible facets, masked alike whatever their slope, do not hold at such grazing.
TEST(ReferenceRenderer, FarWatersReflectedLightMeetsTheWavesAheadAsSmithSays)
{
    osg::ref_ptr<osgWater::WaterNode> water = new osgWater::WaterNode;
    osgWater::WaterSurface* surface = water->getSurface();
    osgWater::WindWaves breeze;
    breeze.fetch = 140.0f;
    surface->setWind(breeze);
    surface->setWaveModel(osgWater::WaterSurface::WAVES_WIND);
    water->addChild(testing_gl::checkerPlane(-30.0f, 400.0f, 1.0f)); // deep: no bed in the way
    ReferenceScene rs(*water, blackWaterUnderSky(*water, glm::dvec3(1.0)));
    const double n1 = water->getSettings()->getAirIOR(), n2 = water->getSettings()->getWaterIOR();
    const double meanSquare = surface->getSpectralWaves()->meanSquareSlope();
    for (double cosE : { 0.05, 0.1, 0.2 }) {
        double reflected = 0.0, escaping = 0.0;
        int met = 0;
        const int n = 4000;
        for (int i = 0; i < n; ++i) {
            const double azimuth = 6.283185307179586 * (i + 0.5) / n, sinE = std::sqrt(1.0 - cosE * cosE);
            const glm::dvec3 eye(-50.0 + 0.025 * i, 0.0, 2.5);
            const glm::dvec3 dir(sinE * std::sin(azimuth), sinE * std::cos(azimuth), -cosE);
            const Hit w = rs.ref->water().intersect(eye, dir, 0.0);
            if (!w.hit) continue;
            const FacetDraw f = drawFacet(rs.ref->normalAt(w), rs.ref->roughnessAt(w), dir, std::uint64_t(i) * 0x9e3779b97f4a7c15ull);
            if (!f.met) continue;
            const double F = fresnelExact(-glm::dot(dir, f.normal), n1, n2);
            const glm::dvec3 mirror = glm::reflect(dir, f.normal);
            reflected += F;
            if (!rs.ref->water().intersect(w.point, mirror, 1e-6 * (1.0 + glm::length(w.point))).hit) escaping += F;
            ++met;
        }
        const glm::vec4 kit = osgWater::optics::fresnelAndLean(2, float(cosE), float(cosE), float(meanSquare), float(n1),
                                                               float(n2), 5.0f);
        std::cout << "cos " << cosE << ": " << met << " rays met the water, F " << reflected / met << " (kit " << kit.x
                  << "), escaping " << escaping / reflected << " (kit " << kit.w << ")\n";
        EXPECT_GT(met, n * 9 / 10) << cosE;
        EXPECT_NEAR(escaping / reflected, kit.w, 0.03) << cosE;
        EXPECT_NEAR(reflected / met, kit.x, 0.1 * kit.x) << cosE;
        if (cosE == 0.05) EXPECT_LT(escaping / reflected, 0.92) << "a share meets the next wave";
    }
}
