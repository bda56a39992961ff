// No NaN or Inf may reach a pixel: grazing rays, the eye on the water plane, the eye under water
// (total internal reflection), huge times, sky everywhere in the depth texture.
#include "GLHarness.h"
#include <osgWater/WaterNode>

using namespace testing_gl;
using namespace osgWater;

namespace {

struct Case { const char* name; osg::Vec3d eye, center; double time; };

void expectAllTargetsFinite(Harness& h, WaterNode* water, const char* name)
{
    osg::ref_ptr<osg::Image> img = h.readColor();
    ASSERT_TRUE(img.valid()) << name;
    EXPECT_TRUE(allFinite(img.get())) << name << ": final image";
    ViewPasses* p = water->getViewPasses(h.camera());
    ASSERT_TRUE(p) << name;
    EXPECT_TRUE(allFinite(h.readTexture(p->getReflectionCamera()->getColorTexture()).get())) << name << ": reflection";
    EXPECT_TRUE(allFinite(h.readTexture(p->getRefractionCamera()->getColorTexture()).get())) << name << ": refraction";
    EXPECT_TRUE(allFinite(h.readTexture(p->getRefractionCamera()->getDepthTexture()).get())) << name << ": depth";
}

}

TEST(RenderRobustness, HardCasesGiveNoNaNOrInf)
{
    Harness h(96, 72);
    REQUIRE_GL(h);
    osg::ref_ptr<WaterNode> water = new WaterNode;
    water->getSurface()->setSize(60.0f);
    // a shallow bed that ends: rays beyond it see only sky in the depth texture
    water->addChild(checkerPlane(-1.0f, 20.0f, 1.0f));
    water->addChild(emissiveQuad(osg::Vec3(-1, 5, -2), osg::Vec3(1, 5, -2), osg::Vec3(1, 5, 2), osg::Vec3(-1, 5, 2),
                                 osg::Vec4(1, 0.5f, 0, 1)));
    h.setScene(water.get());
    const Case cases[] = {
        { "eye on the water plane", osg::Vec3d(0, -5, 0.0), osg::Vec3d(0, 10, 0.0), 1.0 },
        { "grazing", osg::Vec3d(0, -20, 0.02), osg::Vec3d(0, 30, 0.0), 2.0 },
        { "under water, total internal reflection", osg::Vec3d(0, 0, -0.5), osg::Vec3d(0, 10, 0.3), 3.0 },
        { "under water, looking up", osg::Vec3d(0, 0, -0.8), osg::Vec3d(0, 0.5, 5.0), 4.0 },
        { "huge time", osg::Vec3d(0, -6, 3), osg::Vec3d(0, 5, -1), 1.0e9 },
        { "looking straight down", osg::Vec3d(0.1, 0, 10), osg::Vec3d(0.1, 0, -5), 5.0 },
    };
    for (const WaterSettings::RefractionLookup lookup : { WaterSettings::ITERATIVE, WaterSettings::ONE_STEP })
        for (const WaterSettings::FresnelModel fm : { WaterSettings::FRESNEL_SCHLICK, WaterSettings::FRESNEL_EXACT })
            for (const Case& c : cases) {
                water->getSettings()->setRefractionLookup(lookup);
                water->getSettings()->setFresnelModel(fm);
                water->getSettings()->setSearchSteps(8);
                h.lookAt(c.eye, c.center);
                h.frame(c.time);
                expectAllTargetsFinite(h, water.get(), c.name);
            }
    water->setDebugOutput(DEBUG_BOTTOM_HIT);
    h.lookAt(osg::Vec3d(0, -5, 0.0), osg::Vec3d(0, 10, 0.0));
    h.frame(1.0);
    expectAllTargetsFinite(h, water.get(), "debug output, eye on the plane");
}

TEST(RenderRobustness, UnderwaterEyeSwapsThePassSides)
{
    Harness h(64, 64);
    REQUIRE_GL(h);
    osg::ref_ptr<WaterNode> water = new WaterNode;
    h.setScene(water.get());
    h.lookAt(osg::Vec3d(0, 0, -1), osg::Vec3d(0, 10, 0));
    h.frame(0.0);
    ViewPasses* p = water->getViewPasses(h.camera());
    ASSERT_TRUE(p);
    // eye below: the reflection keeps the water side (z below the crests), the refraction the air side
    const osg::Plane& refl = p->getReflectionCamera()->getKeepPlane();
    const osg::Plane& refr = p->getRefractionCamera()->getKeepPlane();
    EXPECT_GT(refl.distance(osg::Vec3(0, 0, -1)), 0.0);
    EXPECT_LT(refl.distance(osg::Vec3(0, 0, 1)), 0.0);
    EXPECT_GT(refr.distance(osg::Vec3(0, 0, 1)), 0.0);
    EXPECT_LT(refr.distance(osg::Vec3(0, 0, -1)), 0.0);
    // both clear the crests
    const double a = water->getSurface()->getMaxAmplitude();
    EXPECT_GT(refl.distance(osg::Vec3(0, 0, float(a))), 0.0);
    EXPECT_GT(refr.distance(osg::Vec3(0, 0, float(-a))), 0.0);
}
