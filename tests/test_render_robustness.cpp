// No NaN or Inf may reach a pixel: grazing rays, the eye on the water plane, the eye under water
// (total internal reflection), huge times, sky everywhere in the depth texture.
#include "node/WaterNodeImpl.h"
#include "GLHarness.h"
#include <osgWater/WaterNode>
#include "WarnCapture.h"
#include <osgDB/FileUtils>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>

using namespace testing_gl;
using namespace osgWater;

namespace {

struct Case { const char* name; osg::Vec3d eye, center; double time; };

void expectAllTargetsFinite(Harness& h, WaterNode* water, const char* name)
{
    osg::ref_ptr<osg::Image> img = h.readColor();
    ASSERT_TRUE(img.valid()) << name;
    EXPECT_TRUE(allFinite(img.get())) << name << ": final image";
    ViewPasses* p = osgWater::internals(*water).getViewPasses(h.camera());
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
    ViewPasses* p = osgWater::internals(*water).getViewPasses(h.camera());
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

// A user's shader override (osgWater/shaders/<name> on the data path) that does not compile, or
// cannot be read, must not leave the water missing: the program says so and uses the embedded
// shaders, so the image is the one without the override.
TEST(RenderRobustness, BrokenShaderOverridesFallBackToTheEmbeddedShaders)
{
    Harness h(64, 48);
    REQUIRE_GL(h);
    auto render = [&h]() {
        osg::ref_ptr<WaterNode> water = new WaterNode;
        water->getSettings()->setCausticsEnabled(false);
        water->addChild(checkerPlane(-1.0f, 40.0f, 1.0f));
        h.setScene(water.get());
        h.lookAt(osg::Vec3d(0, -6, 2), osg::Vec3d(0, 5, -1));
        h.frame(1.0);
        h.frame(1.0);
        osg::ref_ptr<osg::Image> img = h.readColor();
        h.setScene(nullptr);
        return img;
    };
    osg::ref_ptr<osg::Image> reference = render();
    ASSERT_TRUE(reference.valid());

    const std::string dir = std::string(OSGWATER_TEST_TMP) + "/override";
    osgDB::makeDirectory(dir + "/osgWater/shaders");
    osgDB::getDataFilePathList().push_front(dir);
    struct Case { const char* file; const char* text; const char* says; };
    const Case cases[] = { { "water.frag", "#version 130\nthis is not GLSL;\n", "falling back to the embedded" },
                           { "water.vert", "", "could not be read" },
                           { "waves.glsl", "float waterHeight(vec2 p) { return undefinedThing; }\n", "falling back" } };
    for (const Case& c : cases) {
        const std::string path = dir + "/osgWater/shaders/" + c.file;
        { std::ofstream(path.c_str()) << c.text; }
        ScopedWarnCapture warnings; // OSG's own compile errors are expected here
        osg::ref_ptr<osg::Image> img = render();
        std::remove(path.c_str());
        EXPECT_NE(warnings.str().find(c.says), std::string::npos) << c.file << ": " << warnings.str();
        ASSERT_TRUE(img.valid());
        float worst = 0.0f;
        for (int y = 0; y < img->t(); ++y)
            for (int x = 0; x < img->s(); ++x)
                for (int k = 0; k < 3; ++k)
                    worst = std::max(worst, std::fabs(pixel(img.get(), x, y)[k] - pixel(reference.get(), x, y)[k]));
        EXPECT_LT(worst, 1e-5f) << c.file << ": the image must be the embedded shaders' image";
    }
    osgDB::getDataFilePathList().pop_front();
}

// Time up to 1e7 s: the phases are wrapped in double precision on the CPU, so the surface the
// GPU shades at t = 1e7 s is the one a long double evaluation gives, within 1 mm.
TEST(RenderRobustness, AtTenMillionSecondsTheGPUSurfaceMatchesALongDoubleEvaluation)
{
    Harness h(64, 64);
    REQUIRE_GL(h);
    osg::ref_ptr<WaterNode> water = new WaterNode;
    water->getSurface()->setSize(40.0f);
    water->getSurface()->setLevel(1.25);
    water->setDebugOutput(DEBUG_SURFACE);
    h.setScene(water.get());
    h.camera()->setViewMatrixAsLookAt(osg::Vec3d(0.3, 0.2, 30), osg::Vec3d(0.3, 0.2, 0), osg::Vec3d(0, 1, 0));
    h.camera()->setProjectionMatrixAsPerspective(40.0, 1.0, 1.0, 100.0);
    const long double twoPi = 6.283185307179586476925286766559L;
    for (double t : { 0.0, 1.0, 1.0e7, 1.0e7 + 0.25 }) {
        h.frame(t);
        osg::ref_ptr<osg::Image> img = h.readColor();
        ASSERT_TRUE(img.valid());
        int n = 0;
        double worst = 0.0;
        for (int y = 0; y < img->t(); ++y)
            for (int x = 0; x < img->s(); ++x) {
                const float* p = pixel(img.get(), x, y);
                if (p[3] != 2.0f) continue;
                long double hgt = 1.25L;
                for (const Wave& w : water->getSurface()->getWaves()) {
                    const long double k = twoPi / (long double)w.wavelength;
                    hgt += (long double)w.amplitude
                           * std::sin(k * ((long double)w.direction.x() * p[0] + (long double)w.direction.y() * p[1])
                                      - std::sqrt(9.81L * k) * (long double)t + (long double)w.phase);
                }
                worst = std::max(worst, std::fabs(double(hgt) - double(p[2])));
                ++n;
            }
        EXPECT_GT(n, 64 * 64 * 9 / 10) << "the surface fills the view";
        EXPECT_LT(worst, 1.0e-3) << "t = " << t;
    }
}
