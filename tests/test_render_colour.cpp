// Light in linear units: what comes from files is decoded from sRGB, every sum is made in linear
// light, and what the kit draws in the view is encoded once, at the end.
#include "GLHarness.h"
#include "optics/Srgb.h"
#include <osg/Material>
#include <osg/Texture2D>
#include <algorithm>
#include <cmath>

using namespace testing_gl;
using namespace osgWater;

namespace {

// An unlit (white emission, no ambient or diffuse) quad in the plane y = `y`, x in [x0, x1], z in
// [z0, z1], facing -y, textured with `texture` (s along x, t along z).
osg::Geode* unlitTexturedWall(float y, float x0, float x1, float z0, float z1, osg::Texture2D* texture)
{
    osg::Geometry* g = new osg::Geometry;
    osg::Vec3Array* v = new osg::Vec3Array;
    v->push_back(osg::Vec3(x0, y, z0)); v->push_back(osg::Vec3(x1, y, z0));
    v->push_back(osg::Vec3(x1, y, z1)); v->push_back(osg::Vec3(x0, y, z1));
    g->setVertexArray(v);
    osg::Vec2Array* t = new osg::Vec2Array;
    t->push_back(osg::Vec2(0, 0)); t->push_back(osg::Vec2(1, 0));
    t->push_back(osg::Vec2(1, 1)); t->push_back(osg::Vec2(0, 1));
    g->setTexCoordArray(0, t);
    osg::Vec3Array* n = new osg::Vec3Array(1);
    (*n)[0].set(0, -1, 0);
    g->setNormalArray(n, osg::Array::BIND_OVERALL);
    g->addPrimitiveSet(new osg::DrawArrays(GL_QUADS, 0, 4));
    osg::Geode* geode = new osg::Geode;
    geode->addDrawable(g);
    osg::StateSet* ss = geode->getOrCreateStateSet();
    osg::Material* m = new osg::Material;
    m->setEmission(osg::Material::FRONT_AND_BACK, osg::Vec4(1, 1, 1, 1));
    m->setAmbient(osg::Material::FRONT_AND_BACK, osg::Vec4(0, 0, 0, 1));
    m->setDiffuse(osg::Material::FRONT_AND_BACK, osg::Vec4(0, 0, 0, 1));
    ss->setAttribute(m);
    ss->setTextureAttributeAndModes(0, texture);
    return geode;
}

const osg::Vec3ub kBlocks[4] = { { 10, 20, 30 }, { 64, 128, 200 }, { 250, 5, 100 }, { 1, 2, 3 } };

// The quad's four blocks, each read at its centre in the view: the texel within 1/255, exposed
// (encode(exposure decode(texel)))
void expectBlocksShowTheirTexels(bool waterInView, float exposure = 1.0f)
{
    Harness h(160, 120);
    REQUIRE_GL(h);
    osg::ref_ptr<WaterNode> water = new WaterNode;
    water->getSettings()->setExposure(exposure);
    const float z0 = waterInView ? 0.5f : 4.0f, z1 = z0 + 2.0f;
    water->addChild(unlitTexturedWall(6.0f, -2.0f, 2.0f, z0, z1,
                                      nearestTexture(4, 1, [](int i, int) { return kBlocks[i]; }, osg::Texture::CLAMP_TO_EDGE)));
    h.setScene(water.get());
    const osg::Vec3d eye(0, -2, 1.0);
    h.lookAt(eye, waterInView ? osg::Vec3d(0, 6, 1.0) : osg::Vec3d(0, 6, 0.5 * (z0 + z1)));
    h.frame(0.0);
    h.frame(0.1);
    osg::ref_ptr<osg::Image> img = h.readColor();
    ASSERT_TRUE(allFinite(img.get()));
    EXPECT_EQ(water->getViewReport(h.camera()).ran[PASS_SURFACE], waterInView);
    for (int i = 0; i < 4; ++i) {
        const osg::Vec2d p = h.pixelOf(osg::Vec3d(-2.0 + 0.5 + i, 6.0, 0.5 * (z0 + z1)));
        const float* c = pixel(img.get(), int(p.x()), int(p.y()));
        for (int k = 0; k < 3; ++k)
            EXPECT_NEAR(c[k], optics::display(optics::decodeSrgb(glm::vec3(kBlocks[i][k] / 255.0f)), exposure).x, 1.0f / 255.0f)
                << "block " << i << " channel " << k << (waterInView ? ", water in view" : ", water out of view");
    }
}

}

// Nothing lit, nothing summed: decoding the texel and encoding it again gives the texel back, in the
// view with its water and in the view without it (the kit's scene program draws both)
TEST(RenderColour, AnUnlitTexturedQuadShowsItsTexelsWithTheWaterInView)
{
    expectBlocksShowTheirTexels(true);
}

TEST(RenderColour, AnUnlitTexturedQuadShowsItsTexelsWithTheWaterOutOfView)
{
    expectBlocksShowTheirTexels(false);
}

// The exposure scales linear light before the encoding: twice the light, in view and out of it
TEST(RenderColour, TheExposureScalesTheLinearLightBeforeTheEncoding)
{
    expectBlocksShowTheirTexels(true, 2.0f);
    expectBlocksShowTheirTexels(false, 2.0f);
}

// A dark sky gradient (display levels 0 to 63, one every four rows) reflected in calm, nearly
// mirroring water: each water pixel is eq. 9 in linear light of the gradient's level the exact
// mirror ray meets (within 2/255), and the water shows as many distinct levels as that expectation
// does, less two. A linear 8-bit pass target would keep 14 of these 64 levels (the darks of linear
// light are coarse in 8 bits).
TEST(RenderColour, ASmoothSkyReflectedInCalmWaterKeepsItsLevels)
{
    Harness h(200, 240);
    REQUIRE_GL(h);
    const float depth = 1.5f, wallY = 30.0f, wallTop = 20.0f;
    const int rows = 256;
    osg::ref_ptr<WaterNode> water = flatWaterOverBed(depth);
    WaterSettings& s = *water->getSettings();
    s.setFovExtension(1.5f, 1.5f, 10.0f);
    // nearly a mirror over black water: F = (1 - cos)^0.1 is 0.85 to 0.95 here, the refracted light 0
    s.setFresnelModel(WaterSettings::FRESNEL_POWER);
    s.setFresnelExponent(0.1f);
    s.setWaterColor(osg::Vec3(0.0f, 0.0f, 0.0f));
    s.setAttenuation(100.0f);
    water->addChild(unlitTexturedWall(wallY, -60.0f, 60.0f, 0.0f, wallTop, nearestTexture(1, rows, [](int, int j) {
        const unsigned char l = (unsigned char)(j / 4);
        return osg::Vec3ub(l, l, l);
    }, osg::Texture::CLAMP_TO_EDGE)));
    h.setScene(water.get());
    h.lookAt(osg::Vec3d(0, 0, 1.5), osg::Vec3d(0, 10, -1.5), 60.0);
    h.frame(0.0);
    osg::ref_ptr<osg::Image> img = h.readColor();
    ASSERT_TRUE(allFinite(img.get()));

    int offWall = 0;
    const ReflectedColour gradient = [&](const osg::Vec3d& U, const osg::Vec3d& Rr) {
        const double t = (wallY - U.y()) / Rr.y();
        const double z = U.z() + t * Rr.z();
        if (!(Rr.y() > 0.0) || z < 0.0 || z >= wallTop) { ++offWall; return osg::Vec3(-1, -1, -1); }
        const int j = std::min(rows - 1, int(z / wallTop * rows));
        const float l = float(j / 4) / 255.0f;
        return osg::Vec3(l, l, l);
    };
    // the mirror rays that meet the wall well inside a level's four rows (the reflection pass filters
    // its own texels, each about a row high there: at an edge it blends two levels)
    const auto insideARow = [&](const osg::Vec3d& U) {
        osg::Vec3d d = U - osg::Vec3d(0, 0, 1.5);
        d.normalize();
        const osg::Vec3d Rr(d.x(), d.y(), -d.z());
        const double z = U.z() + (wallY - U.y()) / Rr.y() * Rr.z();
        const double band = z / wallTop * rows / 4.0;
        return std::fabs(U.x()) < 0.3 && U.y() < 20.0 && z > 0.0 && z < wallTop && std::fabs(band - std::floor(band) - 0.5) < 0.3;
    };
    const MirrorComparison m = compareFlatWaterWithOptics(h, img.get(), *water->getSettings(), osg::Matrixd(), 0.0,
                                                          -depth, kBedGrey, 1, insideARow, gradient);
    EXPECT_FALSE(m.bedMissed);
    EXPECT_EQ(offWall, 0);
    EXPECT_GT(m.checked, 60);
    EXPECT_LT(m.worst, 2.0 / 255.0) << "half-float pass targets: 2/255; checked " << m.checked << ", levels " << m.renderedLevels.size() << " of " << m.expectedLevels.size()
                                   << ", worst at pixel " << m.worstPixel.x() << ", " << m.worstPixel.y();
    EXPECT_GE(m.expectedLevels.size(), 20u) << "the test scene shows a gradient";
    EXPECT_GE(m.renderedLevels.size() + 2, m.expectedLevels.size()) << "levels lost to the pass targets' precision";
}
