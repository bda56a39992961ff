// One declared frame: every pass that draws the scene gets the same SceneLighting (the view with the
// water out of view, the mirrored bed under water), and releasing the node gives back every GL
// object it made.
#include "node/WaterNodeImpl.h"
#include "GLHarness.h"
#include <osgWater/Sky>
#include <osgWater/WaterNode>
#include "frame/PassMath.h"
#include "optics/Srgb.h"
#include <cmath>
#include <iostream>

using namespace testing_gl;
using namespace osgWater;

namespace {

// the kit's default material: diffuse 0.8, ambient 0.2 (display values, as a file's), lit by the
// settings' sun and ambient colours (linear light)
const float kMaterialAmbient = optics::decodeSrgb(0.2f), kMaterialDiffuse = optics::decodeSrgb(0.8f);

// ambient + diffuse x N.L x the share of the sun that reaches the point, in linear light
osg::Vec3 lambert(const WaterSettings& s, float ndl, float sunShare)
{
    return s.getAmbientColor() * kMaterialAmbient + s.getSunColor() * (kMaterialDiffuse * ndl * sunShare);
}

osg::Vec3 colourAt(Harness& h, const osg::Image* img, const osg::Vec3d& p)
{
    const osg::Vec2d px = h.pixelOf(p);
    EXPECT_TRUE(px.x() >= 0 && px.y() >= 0 && px.x() < h.width() && px.y() < h.height()) << "point out of view";
    const float* v = pixel(img, std::min(std::max(int(px.x()), 0), h.width() - 1),
                           std::min(std::max(int(px.y()), 0), h.height() - 1));
    return osg::Vec3(v[0], v[1], v[2]);
}

// the colour of a texture of the pass with this view and projection where local point p lands
osg::Vec3 passColourAt(const osg::Image* img, const osg::Vec3d& p, const osg::Matrixd& view, const osg::Matrixd& proj)
{
    const osg::Vec3d tc = projectToTexture(p, view, proj);
    EXPECT_TRUE(tc.x() > 0.02 && tc.x() < 0.98 && tc.y() > 0.02 && tc.y() < 0.98) << "point outside the pass";
    const int x = std::min(std::max(int(tc.x() * img->s()), 0), img->s() - 1);
    const int y = std::min(std::max(int(tc.y() * img->t()), 0), img->t() - 1);
    const float* v = pixel(img, x, y);
    return osg::Vec3(v[0], v[1], v[2]);
}

float maxDifference(const osg::Vec3& a, const osg::Vec3& b)
{
    return std::max({ std::fabs(a.x() - b.x()), std::fabs(a.y() - b.y()), std::fabs(a.z() - b.z()) });
}

// Four frames a second's sixtieth apart from t = 1, each read back: pass measures are read a frame
// after they are made, and finished (as a swap finishes them). The last frame's image.
osg::ref_ptr<osg::Image> measuredFrames(Harness& h)
{
    osg::ref_ptr<osg::Image> img;
    for (int i = 0; i < 4; ++i) {
        h.frame(1.0 + i / 60.0);
        img = h.readColor();
    }
    return img;
}

osg::ref_ptr<WaterNode> flatWater()
{
    osg::ref_ptr<WaterNode> water = new WaterNode;
    water->getSurface()->setWaves({});
    water->getSurface()->setSize(60.0f);
    water->getSettings()->setGlowEnabled(false);
    return water;
}

}

TEST(RenderFrame, ChildrenAreLitTheSameWithTheWaterInViewAndOutOfView)
{
    // A lit wall above the water, facing the eye and half facing the sun (N.L = 0.5): its colour is
    // ambient + diffuse x 0.5 whether the view looks up (the water out of view: the scene alone) or
    // down (the water in view: the passes run). A fresh view looks up first, so no earlier pass can
    // have left its sun in the scene program.
    Harness h(96, 72);
    REQUIRE_GL(h);
    osg::ref_ptr<WaterNode> water = flatWater();
    water->getSettings()->setSunDirection(osg::Vec3(0.0f, -0.5f, std::sqrt(0.75f)));
    water->addChild(litQuad(osg::Vec3(-3, 10, 8), osg::Vec3(3, 10, 8), osg::Vec3(3, 10, 14), osg::Vec3(-3, 10, 14)));
    water->addChild(checkerPlane(-3.0f, 60.0f, 1.0f));
    h.setScene(water.get());
    const osg::Vec3d eye(0, 0, 10), wall(0, 10, 11);
    const osg::Vec3 expected = shown(lambert(*water->getSettings(), 0.5f, 1.0f));

    h.lookAt(eye, osg::Vec3d(0, 10, 15), 45.0); // up: the water below the frustum
    h.frame(1.0);
    ASSERT_EQ(osgWater::internals(*water).getViewPasses(h.camera()), nullptr) << "the water should be out of view";
    osg::ref_ptr<osg::Image> up = h.readColor();
    const osg::Vec3 outOfView = colourAt(h, up.get(), wall);

    h.lookAt(eye, osg::Vec3d(0, 10, 8), 45.0); // down: the water in view
    h.frame(1.0);
    ASSERT_NE(osgWater::internals(*water).getViewPasses(h.camera()), nullptr) << "the water should be in view";
    osg::ref_ptr<osg::Image> down = h.readColor();
    const osg::Vec3 inView = colourAt(h, down.get(), wall);

    std::cout << "wall: out of view " << outOfView.x() << ", in view " << inView.x() << ", expected " << expected.x() << std::endl;
    EXPECT_LE(maxDifference(outOfView, inView), 1.0f / 255.0f) << "the same point, lit differently";
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(outOfView[i], expected[i], 2.0 / 255.0) << "out of view, channel " << i;
        EXPECT_NEAR(inView[i], expected[i], 2.0 / 255.0) << "in view, channel " << i;
    }
}

TEST(RenderFrame, UnderWaterChildrenAreLitTheSameWithTheSurfaceInViewAndOutOfView)
{
    // The eye 5 m under flat water (fog k = 0.1), caustics on, looking down at a lit shelf: a
    // narrow field of view leaves the surface out of view, a wide one takes it in. The centre
    // pixel is the same ray in both, so the same point: the same colour, and sunlit (the caustic
    // irradiance through flat water is most of the sun).
    Harness h(97, 73); // odd: the centre pixel's ray is the view's axis
    REQUIRE_GL(h);
    osg::ref_ptr<WaterNode> water = flatWater();
    water->getSettings()->setAttenuation(0.1f);
    water->getSettings()->setSunDirection(osg::Vec3(0.0f, -0.5f, std::sqrt(0.75f)));
    water->addChild(litQuad(osg::Vec3(-20, -20, -8), osg::Vec3(20, -20, -8), osg::Vec3(20, 20, -8), osg::Vec3(-20, 20, -8)));
    h.setScene(water.get());
    const osg::Vec3d eye(0, 0, -5), shelf(0, 10, -8);
    auto centre = [&](double fovy) {
        h.lookAt(eye, shelf, fovy);
        h.frame(1.0);
        osg::ref_ptr<osg::Image> img = h.readColor(); // held: the pixel points into it
        const float* p = pixel(img.get(), h.width() / 2, h.height() / 2);
        return osg::Vec3(p[0], p[1], p[2]);
    };
    const osg::Vec3 narrow = centre(20.0); // top edge 6.7 degrees below the horizontal
    ASSERT_FALSE(osgWater::internals(*water).getViewPasses(h.camera())->getPlan().runs(PASS_SURFACE));
    const osg::Vec3 wide = centre(120.0);   // top edge 43 degrees above it: the surface in view
    ASSERT_TRUE(osgWater::internals(*water).getViewPasses(h.camera())->getPlan().runs(PASS_SURFACE));
    std::cout << "shelf under water: surface out of view " << narrow.x() << ", in view " << wide.x() << std::endl;
    EXPECT_LE(maxDifference(narrow, wide), 1.0f / 255.0f);
    // eq. 10 towards a water colour with no red: red = exp(-k d) x the lit red; the sun reaches
    // the shelf 8 m down along the refracted ray (22 degrees from the vertical), attenuated on
    // the way: most of exp(-k 8 / cos 22) is expected, far more than ambient alone
    const float fogged = float(std::exp(-0.1 * (shelf - eye).length()));
    const float sunPath = float(std::exp(-0.1 * 8.0 / std::cos(std::asin(0.5 / 1.333))));
    EXPECT_GT(narrow.x(), shown(lambert(*water->getSettings(), std::sqrt(0.75f), 0.75f * sunPath) * fogged).x())
        << "the shelf under water should get the sun through the surface";
}

TEST(RenderFrame, UnderWaterTheBedSeenByTotalReflectionCarriesTheCausticsAndShadows)
{
    // The eye 1 m under flat water (k = 0) looks up beyond the critical angle: the surface mirrors
    // the bed (z = -4). A slab at z = -2 over y in [12, 20] shadows the bed below it from an
    // overhead sun. In the reflection pass the bed must look as the view itself shows it from
    // below: in the shadow ambient only, elsewhere ambient + diffuse x the caustic irradiance.
    Harness h(128, 96);
    REQUIRE_GL(h);
    osg::ref_ptr<WaterNode> water = flatWater();
    WaterSettings* s = water->getSettings();
    s->setAttenuation(0.0f);
    s->setSunDirection(osg::Vec3(0.0f, 0.0f, 1.0f));
    s->setReflectionTextureSize(512);
    s->setCausticsGather(WaterSettings::GATHER_CPU);
    water->addChild(litQuad(osg::Vec3(-30, -30, -4), osg::Vec3(30, -30, -4), osg::Vec3(30, 30, -4), osg::Vec3(-30, 30, -4)));
    water->addChild(litQuad(osg::Vec3(-5, 12, -2), osg::Vec3(5, 12, -2), osg::Vec3(5, 20, -2), osg::Vec3(-5, 20, -2)));
    h.setScene(water.get());
    const osg::Vec3d eye(0, 0, -1), lit(0, 8, -4), shadowed(0, 15, -4);

    // the view from below, looking down at both points
    h.lookAt(eye, osg::Vec3d(0, 11, -4), 70.0);
    h.frame(1.0);
    osg::ref_ptr<osg::Image> below = h.readColor();
    const osg::Vec3 litView = colourAt(h, below.get(), lit), shadowView = colourAt(h, below.get(), shadowed);

    // looking up at 60 degrees from the vertical (beyond 48.6): the reflection pass draws the bed
    h.lookAt(eye, eye + osg::Vec3d(0, std::sin(osg::DegreesToRadians(60.0)), std::cos(osg::DegreesToRadians(60.0))), 70.0);
    h.frame(1.0);
    ViewPasses* p = osgWater::internals(*water).getViewPasses(h.camera());
    ASSERT_TRUE(p && p->getEyeBelow() && p->getPlan().runs(PASS_REFLECTION));
    ReflectionCamera* refl = p->getReflectionCamera();
    osg::ref_ptr<osg::Image> mirror = h.readTexture(refl->getColorTexture());
    ASSERT_TRUE(mirror.valid());
    const osg::Vec3 litMirror = passColourAt(mirror.get(), lit, refl->getViewMatrix(), refl->getProjectionMatrix());
    const osg::Vec3 shadowMirror = passColourAt(mirror.get(), shadowed, refl->getViewMatrix(), refl->getProjectionMatrix());

    std::cout << "bed lit: view " << litView.x() << ", mirrored " << litMirror.x() << "; in the shadow: view "
              << shadowView.x() << ", mirrored " << shadowMirror.x() << std::endl;
    // the view's own bed: caustics (about 1 - F(0) = 0.98 of the sun) and the slab's shadow
    EXPECT_NEAR(shadowView.x(), shown(lambert(*s, 1.0f, 0.0f)).x(), 2.0 / 255.0);
    EXPECT_GT(litView.x(), shown(lambert(*s, 1.0f, 0.9f)).x());
    EXPECT_LT(litView.x(), shown(lambert(*s, 1.0f, 0.999f)).x()) << "the caustic irradiance is below the full sun";
    // the mirrored bed, in linear light in its pass target: as the view shows it, once encoded,
    // within a texel
    EXPECT_LE(maxDifference(shown(shadowMirror), shadowView), 3.0f / 255.0f) << "the mirrored bed lost the underwater shadow";
    EXPECT_LE(maxDifference(shown(litMirror), litView), 3.0f / 255.0f) << "the mirrored bed lost the caustics";
}

TEST(RenderFrame, ReleasingTheNodeGivesBackEveryGLObjectItMade)
{
    // Counted on the context: before the water is first drawn; after frames above and under water
    // with every pass (caustics with each gather path, glow); after releaseGLObjects(state).
    Harness h(64, 48);
    REQUIRE_GL(h);
    osg::ref_ptr<osg::Group> empty = new osg::Group;
    h.setScene(empty.get());
    h.lookAt(osg::Vec3d(0, -12, 3), osg::Vec3d(0, 0, 0));
    h.frame(0.0);
    GLuint highest = 0;
    const GLCounts before = countGLObjects(h.context(), highest);

    osg::ref_ptr<WaterNode> water = new WaterNode;
    water->getSurface()->setSize(40.0f);
    WaterSettings* s = water->getSettings();
    s->setSunDirection(osg::Vec3(0.0f, 0.9f, 0.44f)); // ahead and low: its highlight in view
    s->setReflectionTextureSize(64);
    s->setRefractionTextureSize(64);
    s->setCausticsResolution(32);
    s->setPhotonGridSize(32);
    water->addChild(checkerPlane(-2.0f, 40.0f, 1.0f));
    h.setScene(water.get());
    double t = 0.0;
    for (int i = 0; i < 40; ++i) h.frame(t += 0.05); // the automatic gather tries every path
    h.lookAt(osg::Vec3d(0, -12, -1), osg::Vec3d(0, 0, 1));
    for (int i = 0; i < 3; ++i) h.frame(t += 0.05);
    ASSERT_TRUE(osgWater::internals(*water).getViewPasses(h.camera()) && osgWater::internals(*water).getViewPasses(h.camera())->getGlow());
    const GLCounts drawn = countGLObjects(h.context(), highest);
    std::cout << "before: " << before << "\ndrawn: " << drawn << std::endl;
    EXPECT_GT(drawn.textures, before.textures + 8);
    EXPECT_GT(drawn.framebuffers, before.framebuffers + 6);
    EXPECT_GT(drawn.programs, before.programs + 8);

    water->releaseGLObjects(h.context()->getState());
    const GLCounts released = countGLObjects(h.context(), highest);
    std::cout << "released: " << released << std::endl;
    EXPECT_EQ(released, before) << "releaseGLObjects left GL objects behind";
    EXPECT_LT(highest, kNames - 1024);

    // and it draws again afterwards, its objects made anew
    h.frame(t += 0.05);
    EXPECT_TRUE(allFinite(h.readColor().get()));
    EXPECT_GT(countGLObjects(h.context(), highest).textures, before.textures + 4);
}

TEST(RenderFrame, PassTimesAndWhetherEachPassRanGoIntoTheViewersStatistics)
{
    Harness h(96, 64);
    REQUIRE_GL(h);
    osg::ref_ptr<WaterNode> water = new WaterNode;
    water->getSurface()->setSize(200.0f);
    water->getSettings()->setCausticsEnabled(false);
    water->getSettings()->setGlowEnabled(false);
    water->addChild(checkerPlane(-2.0f, 200.0f, 1.0f));
    water->setPassTimingEnabled(true);
    h.setScene(water.get());
    h.lookAt(osg::Vec3d(0, 0, 3), osg::Vec3d(0, 10, -1));
    measuredFrames(h);
    osg::Stats* stats = h.viewer()->getViewerStats();
    const unsigned int frame = h.viewer()->getFrameStamp()->getFrameNumber();
    double v = -1.0;
    ASSERT_TRUE(stats->getAttribute(frame, "osgWater reflection ran", v));
    EXPECT_EQ(v, 1.0);
    ASSERT_TRUE(stats->getAttribute(frame, "osgWater glow highlight ran", v));
    EXPECT_EQ(v, 0.0) << "the glow is off";
    ASSERT_TRUE(stats->getAttribute(frame, "osgWater photons ran", v));
    EXPECT_EQ(v, 0.0) << "the caustics are off";
    for (const char* timed : { "osgWater reflection GPU ms", "osgWater refraction GPU ms", "osgWater surface GPU ms" }) {
        ASSERT_TRUE(stats->getAttribute(frame, timed, v)) << timed;
        EXPECT_GE(v, 0.0) << timed;
        EXPECT_LT(v, 10000.0) << timed;
    }
    EXPECT_GE(water->getPassMilliseconds(h.camera(), PASS_REFLECTION), 0.0);
    EXPECT_LT(water->getPassMilliseconds(h.camera(), PASS_SCENE), 0.0) << "the scene is drawn in the view's bins: not timed";

    // off: nothing measured, nothing written
    water->setPassTimingEnabled(false);
    h.frame(2.0);
    EXPECT_LT(water->getPassMilliseconds(h.camera(), PASS_REFLECTION), 0.0);
    EXPECT_FALSE(stats->getAttribute(h.viewer()->getFrameStamp()->getFrameNumber(), "osgWater reflection ran", v));
}

// Fragments counted (GL_ARB_pipeline_statistics_query) are the work a pass asks of the rasteriser:
// a bed that fills the refraction pass's target asks one fragment per texel, so the count follows
// the target's area. (A software rasteriser shades 4x4 blocks: a block an edge crosses is shaded
// for the triangles on both sides. The bed's edges across the target, at most four, cross at most
// side / 2 blocks each: at most 32 side texels more.)
TEST(RenderFrame, ThePassesCountTheFragmentsTheyShade)
{
    Harness h(96, 64);
    REQUIRE_GL(h);
    osg::ref_ptr<WaterNode> water = flatWater();
    water->getSettings()->setCausticsEnabled(false);
    water->addChild(checkerPlane(-2.0f, 400.0f, 1.0f));
    water->setPassTimingEnabled(true);
    h.setScene(water.get());
    h.lookAt(osg::Vec3d(0, 0, 3), osg::Vec3d(0, 0.01, -1));
    auto refractionFragments = [&](int side) {
        water->getSettings()->setRefractionTextureSize(side);
        measuredFrames(h);
        const ViewReport r = water->getViewReport(h.camera());
        EXPECT_EQ(r.refractionSize[0], side);
        EXPECT_EQ(r.refractionSize[1], side);
        return r.fragments[PASS_REFRACTION];
    };
    for (int side : { 256, 512 }) {
        const double fragments = refractionFragments(side);
        EXPECT_GE(fragments, double(side * side)) << side;
        EXPECT_LE(fragments, double(side * side + 32 * side)) << side;
    }
    const ViewReport r = water->getViewReport(h.camera());
    EXPECT_GE(r.fragments[PASS_SURFACE], double(h.width() * h.height())) << "the water fills the view";
    EXPECT_LT(r.fragments[PASS_SCENE], 0.0) << "the scene is drawn in the view's bins: not counted";
    water->setPassTimingEnabled(false);
    h.frame(2.0);
    EXPECT_LT(water->getViewReport(h.camera()).fragments[PASS_REFRACTION], 0.0) << "off: nothing counted";
}

// The sky is drawn only where it can be seen: in the refraction pass from above, which keeps what
// lies under the water, no ray meets it, and that pass counts the bed's fragments alone, as
// without a sky (a sky drawn there shades the whole target again); the reflection from above and the
// refraction from below see it, and shade at least the target's texels for it.
TEST(RenderFrame, TheSkyIsDrawnOnlyInThePassesThatSeeIt)
{
    Harness h(96, 64);
    REQUIRE_GL(h);
    const int side = 256;
    auto passFragments = [&](bool withSky, double eyeZ, PassId pass) {
        osg::ref_ptr<WaterNode> water = flatWater();
        water->getSettings()->setCausticsEnabled(false);
        water->getSettings()->setRefractionTextureSize(side);
        water->getSettings()->setReflectionTextureSize(side);
        water->addChild(checkerPlane(-2.0f, 400.0f, 1.0f));
        if (withSky) water->addChild(new Sky);
        water->setPassTimingEnabled(true);
        h.setScene(water.get());
        h.lookAt(osg::Vec3d(0, 0, eyeZ), osg::Vec3d(0, 0.01, eyeZ > 0.0 ? -1.0 : 1.0));
        measuredFrames(h);
        return water->getViewReport(h.camera()).fragments[pass];
    };
    const double bedAlone = passFragments(false, 3.0, PASS_REFRACTION);
    const double withSky = passFragments(true, 3.0, PASS_REFRACTION);
    ASSERT_GE(bedAlone, double(side * side)) << "the bed fills the refraction target";
    EXPECT_EQ(withSky, bedAlone) << "the refraction from above shades no sky";
    EXPECT_GE(passFragments(true, 3.0, PASS_REFLECTION), double(side * side)) << "the reflection from above shows the sky";
    EXPECT_GE(passFragments(true, -1.0, PASS_REFRACTION), double(side * side)) << "Snell's window shows the sky";
}

// The surface pass's work per water pixel: the rings around the eye are never thinner than their
// cells are wide, so far away, at a grazing angle, fewer rings are slivers of a pixel that a
// rasteriser shades whole 4x4 blocks for, once per sliver. In the demo's view at 640 x 480 that is
// 2.3 fragments a water pixel; rings as thin as the reach allows (256 to the far corner) shade
// 3.7, and fail the bound.
TEST(RenderFrame, TheSurfaceShadesFewBlocksPerWaterPixel)
{
    Harness h(640, 480);
    REQUIRE_GL(h);
    osg::ref_ptr<WaterNode> water = new WaterNode;
    water->getSurface()->setSize(140.0f);
    water->getSettings()->setCausticsEnabled(false);
    water->getSettings()->setGlowEnabled(false);
    water->addChild(checkerPlane(-2.0f, 200.0f, 1.0f));
    water->setPassTimingEnabled(true);
    water->setDebugOutput(DEBUG_SURFACE); // alpha 2 where the surface was shaded
    h.setScene(water.get());
    h.lookAt(osg::Vec3d(0, -42, 4.5), osg::Vec3d(0, 10, -1)); // the demo's view
    osg::ref_ptr<osg::Image> img = measuredFrames(h);
    int waterPixels = 0;
    for (int y = 0; y < h.height(); ++y)
        for (int x = 0; x < h.width(); ++x) waterPixels += pixel(img.get(), x, y)[3] == 2.0f;
    ASSERT_GT(waterPixels, h.width() * h.height() / 3) << "the water fills the lower part of the view";
    const double fragments = water->getViewReport(h.camera()).fragments[PASS_SURFACE];
    EXPECT_GE(fragments, double(waterPixels));
    EXPECT_LE(fragments, 2.5 * waterPixels);
}
