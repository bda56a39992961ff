// The environment cube map (DeepWater): reflected rays the reflection texture does not hold read
// the surroundings along their direction. With the reflection and refraction passes off and the
// map on, flat water shows exactly the map along each pixel's reflected ray (F = 1 without a
// refraction pass): a user's map of six solid faces checks that each direction reads its face,
// and a map drawn from a scene checks the faces' orientation (what lies to one side and above
// the water is seen there, not mirrored).
#include "node/WaterNodeImpl.h"
#include "GLHarness.h"
#include <osgWater/WaterNode>
#include <osg/TextureCubeMap>
#include <osg/io_utils>
#include <cmath>

using namespace testing_gl;
using namespace osgWater;

namespace {

osg::ref_ptr<WaterNode> mirrorOnlyWater(float size)
{
    osg::ref_ptr<WaterNode> water = new WaterNode;
    water->getSurface()->setWaves({});
    water->getSurface()->setSize(size);
    WaterSettings* s = water->getSettings();
    s->setReflectionEnabled(false);
    s->setRefractionEnabled(false);
    s->setCausticsEnabled(false);
    s->setGlowEnabled(false);
    s->setEnvironmentMapEnabled(true);
    return water;
}

// the colours of the faces +x, -x, +y, -y, +z, -z
const osg::Vec4 kFaces[6] = { { 1, 0, 0, 1 }, { 0, 1, 1, 1 }, { 0, 1, 0, 1 }, { 1, 0, 1, 1 }, { 0, 0, 1, 1 }, { 1, 1, 0, 1 } };

osg::TextureCubeMap* solidFaces()
{
    osg::TextureCubeMap* cube = new osg::TextureCubeMap;
    for (int face = 0; face < 6; ++face) {
        osg::ref_ptr<osg::Image> img = new osg::Image;
        img->allocateImage(4, 4, 1, GL_RGBA, GL_UNSIGNED_BYTE);
        for (int i = 0; i < 16; ++i)
            for (int c = 0; c < 4; ++c) img->data()[4 * i + c] = (unsigned char)(255 * kFaces[face][c]);
        cube->setImage(face, img.get());
    }
    return cube;
}

// a red wall 80 m along +x, only on the +y side and only above the water
osg::Geode* redWall()
{
    return emissiveQuad(osg::Vec3(80, 0, 0), osg::Vec3(80, 40, 0), osg::Vec3(80, 40, 40), osg::Vec3(80, 0, 40),
                        osg::Vec4(1, 0, 0, 1));
}

// flat mirror-only water under a red wall, the eye 1 m up looking at (10, 2.5, 0)
struct WallScene {
    Harness h{ 64, 64 };
    osg::ref_ptr<WaterNode> water = mirrorOnlyWater(100.0f);
    WallScene()
    {
        if (!h.ok()) return;
        water->addChild(redWall());
        h.setScene(water.get());
        h.lookAt(osg::Vec3d(0, 0, 1), osg::Vec3d(10, 2.5, 0));
    }
};

osg::Vec3 centrePixel(Harness& h)
{
    h.frame(1.0);
    osg::ref_ptr<osg::Image> img = h.readColor();
    const float* p = pixel(img.get(), img->s() / 2, img->t() / 2);
    return osg::Vec3(p[0], p[1], p[2]);
}

}

TEST(RenderEnvironment, EachReflectedDirectionReadsItsFaceOfTheUsersMap)
{
    Harness h(64, 64);
    REQUIRE_GL(h);
    osg::ref_ptr<WaterNode> water = mirrorOnlyWater(400.0f);
    water->setEnvironmentMap(solidFaces());
    h.setScene(water.get());
    // eye 2 m up, each view's centre ray meeting the water where its reflection leaves along one axis
    const struct { osg::Vec3d eye, center; int face; } views[] = {
        { { 0, 0, 2 }, { 30, 0, 0 }, 0 },  { { 0, 0, 2 }, { -30, 0, 0 }, 1 }, { { 0, 0, 2 }, { 0, 30, 0 }, 2 },
        { { 0, 0, 2 }, { 0, -30, 0 }, 3 }, { { 0, 0, 30 }, { 0.5, 0.5, 0 }, 4 } };
    for (const auto& v : views) {
        h.lookAt(v.eye, v.center);
        const osg::Vec3 c = centrePixel(h);
        const osg::Vec4& want = kFaces[v.face];
        EXPECT_NEAR(c.x(), want.r(), 0.02) << "face " << v.face << ": " << c;
        EXPECT_NEAR(c.y(), want.g(), 0.02) << "face " << v.face << ": " << c;
        EXPECT_NEAR(c.z(), want.b(), 0.02) << "face " << v.face << ": " << c;
    }
    EXPECT_EQ(osgWater::internals(*water).getEnvironmentPasses(), nullptr) << "the user's map: nothing to draw";
    water->getSettings()->setEnvironmentMapEnabled(false);
    h.lookAt(osg::Vec3d(0, 0, 2), osg::Vec3d(30, 0, 0));
    EXPECT_GT((centrePixel(h) - osg::Vec3(1, 0, 0)).length(), 0.5f) << "off: the map is not read";
    EXPECT_EQ(water->getEnvironmentMap(), nullptr);
}

TEST(RenderEnvironment, TheDrawnMapShowsWhatStandsAboveTheWaterWhereItStands)
{
    // a face drawn mirrored left-right or upside down shows the wall on the wrong side, or not at all
    WallScene sc;
    REQUIRE_GL(sc.h);
    Harness& h = sc.h;
    WaterNode* water = sc.water.get();
    // the centre ray meets the water at (10, +-2.5, 0) and leaves along (10, +-2.5, 1): towards
    // (80, +-20, 7), on the wall or beside it
    const osg::Vec3 onWall = centrePixel(h);
    EXPECT_NEAR(onWall.x(), 1.0, 0.05) << onWall;
    EXPECT_NEAR(onWall.y(), 0.0, 0.05) << onWall;
    ASSERT_NE(osgWater::internals(*water).getEnvironmentPasses(), nullptr);
    EXPECT_EQ(water->getEnvironmentMap(), osgWater::internals(*water).getEnvironmentPasses()->getTexture());
    h.lookAt(osg::Vec3d(0, 0, 1), osg::Vec3d(10, -2.5, 0));
    const osg::Vec3 beside = centrePixel(h);
    EXPECT_LT(beside.x() - beside.y(), 0.5) << "the wall seen on the -y side: " << beside;
    // steeper, the ray passes over the wall (towards (80, 20, 56)); flipped upside down, it would
    // read the wall's mirror image below the water, which the map does not hold
    h.lookAt(osg::Vec3d(0, 0, 7), osg::Vec3d(10, 2.5, 0));
    const osg::Vec3 over = centrePixel(h);
    EXPECT_LT(over.x() - over.y(), 0.5) << "the wall seen above its top: " << over;
}

TEST(RenderEnvironment, TheDrawnMapIsDrawnOnceThenOnlyWhenAskedOrMoved)
{
    WallScene sc;
    REQUIRE_GL(sc.h);
    Harness& h = sc.h;
    WaterNode* water = sc.water.get();
    auto drawn = [&](double t) {
        h.frame(t);
        return osgWater::internals(*water).getPassPlan(h.camera()).runs(PASS_ENVIRONMENT);
    };
    EXPECT_TRUE(drawn(1.0)) << "the first frame draws it";
    EXPECT_FALSE(drawn(2.0)) << "nothing changed";
    EXPECT_FALSE(drawn(3.0));
    water->dirtyEnvironmentMap();
    EXPECT_TRUE(drawn(4.0)) << "asked";
    EXPECT_FALSE(drawn(5.0));
    water->getSettings()->setSunDirection(osg::Vec3(0.3f, 0.2f, 0.9f));
    EXPECT_TRUE(drawn(6.0)) << "the sun moved";
    water->addChild(emissiveQuad(osg::Vec3(-90, 0, 0), osg::Vec3(-90, 40, 0), osg::Vec3(-90, 40, 40),
                                 osg::Vec3(-90, 0, 40), osg::Vec4(0, 1, 0, 1)));
    EXPECT_TRUE(drawn(7.0)) << "the scene grew";
    water->getSettings()->setEnvironmentMapEnabled(false);
    EXPECT_FALSE(drawn(8.0));
    EXPECT_EQ(osgWater::internals(*water).getEnvironmentPasses(), nullptr);
}
