// The lake demo, run headless as a user would run it, and its screenshot checked for what can only
// be there if the water works: trees mirrored below the shoreline, the bed visible through shallow
// water and not through deep water. Each effect is switched off once to show the check depends on it.
#include "node/WaterNodeImpl.h"
#include "optics/Srgb.h"
#include "GLHarness.h"
#include "../apps/common/Floaters.h"
#include "../apps/common/Pond.h"
#include "../apps/common/SceneWater.h"
#include <unistd.h>
#include "../apps/osgwatergenlake/LakeModel.h"
#include <osgWater/WaterNode>
#include <osgWater/WaterTypes>
#include <osgDB/ReadFile>
#include <osg/io_utils>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <utility>
#include <vector>

namespace {

const int W = 480, H = 360;
const osg::Vec3d kEye(0, -42, 4.5), kCenter(0, 10, -1);

struct Shot {
    osg::ref_ptr<osg::Image> image;
    osg::Vec3 at(const osg::Vec2d& px) const
    {
        const unsigned char* p = image->data(int(px.x()), int(px.y()));
        return osg::Vec3(p[0], p[1], p[2]) / 255.0f;
    }
};

bool runDemo(const std::string& extra, Shot& shot, std::string& why)
{
    if (!std::getenv("DISPLAY")) { why = "DISPLAY is not set"; return false; }
    // the process id too: tests run in parallel (ctest -j) ask for the same options
    const std::string png = std::string(OSGWATER_TEST_TMP) + "/lake_" + std::to_string(getpid()) + "_"
                            + std::to_string(std::hash<std::string>()(extra) % 100000) + ".png";
    std::remove(png.c_str());
    char cmd[2048];
    std::snprintf(cmd, sizeof(cmd),
                  "\"%s\" \"%s\" --headless --no-hud --no-compare --frames 2 --size %d %d --eye %g %g %g --center %g %g %g "
                  "--time 10 --screenshot \"%s\" %s > /dev/null 2>&1",
                  OSGWATER_LAKE_APP, OSGWATER_LAKE_SCENE, W, H, kEye.x(), kEye.y(), kEye.z(), kCenter.x(), kCenter.y(),
                  kCenter.z(), png.c_str(), extra.c_str());
    const int rc = std::system(cmd);
    if (rc != 0) { why = std::string("osgwaterlake failed: ") + cmd; return false; }
    shot.image = osgDB::readRefImageFile(png);
    if (!shot.image.valid()) { why = "no screenshot " + png; return false; }
    std::remove(png.c_str());
    return true;
}

// pixel (origin bottom left, as osg::Image) of a world point in the demo's camera
osg::Vec2d project(const osg::Vec3d& p)
{
    const osg::Matrixd vp = osg::Matrixd::lookAt(kEye, kCenter, osg::Vec3d(0, 0, 1)) *
                            osg::Matrixd::perspective(45.0, double(W) / H, 0.1, 2000.0);
    const osg::Vec4d c = osg::Vec4d(p, 1.0) * vp;
    return osg::Vec2d((c.x() / c.w() * 0.5 + 0.5) * W, (c.y() / c.w() * 0.5 + 0.5) * H);
}

// the demo's scene loaded as the demo loads it, and its water (null if the file is missing)
osg::ref_ptr<osgWater::WaterNode> loadLake(osg::ref_ptr<osg::Node>& scene)
{
    scene = osgDB::readRefNodeFile(OSGWATER_LAKE_SCENE);
    return scene.valid() ? osgWaterApps::findOrAddWater(scene, OSGWATER_LAKE_SCENE) : nullptr;
}

float luminance(const osg::Vec3& c) { return 0.2126f * c.x() + 0.7152f * c.y() + 0.0722f * c.z(); }

// where the eye ray through a pixel meets the water plane, if nothing above the water is in the way
bool waterPoint(int x, int y, osg::Vec3d& hit)
{
    const osg::Matrixd inv = osg::Matrixd::inverse(osg::Matrixd::lookAt(kEye, kCenter, osg::Vec3d(0, 0, 1)) *
                                                   osg::Matrixd::perspective(45.0, double(W) / H, 0.1, 2000.0));
    const double nx = (x + 0.5) / W * 2 - 1, ny = (y + 0.5) / H * 2 - 1;
    osg::Vec3d d = osg::Vec3d(nx, ny, 1) * inv - osg::Vec3d(nx, ny, -1) * inv;
    d.normalize();
    if (d.z() > -0.02) return false;
    const double t = -kEye.z() / d.z();
    for (double s = 0.5; s < t; s += 0.5) { // terrain, trees' ground, shore in front of the water?
        const osg::Vec3d p = kEye + d * s;
        if (lake::height(float(p.x()), float(p.y())) > p.z() - 0.3) return false;
    }
    hit = kEye + d * t;
    return lake::height(float(hit.x()), float(hit.y())) < -0.05f;
}

}


// the demo with `a` and with `b` added to its options (the second switches one effect off)
#define RUN_DEMO_PAIR(a, b, first, second)                     \
    Shot first, second;                                        \
    {                                                          \
        std::string why;                                       \
        testing_gl::ContextProbe p{ runDemo(a, first, why), why };                \
        REQUIRE_GL(p);                                         \
        ASSERT_TRUE(runDemo(b, second, why)) << why;           \
    }

// What the demo says of the frames it times is what it timed, and a size it cannot render is
// refused with a message, not an FBO error
TEST(LakeDemo, ItTimesTheFramesAskedForAndRefusesAnImpossibleSize)
{
    ASSERT_TRUE(std::getenv("DISPLAY")) << "DISPLAY is not set (scripts/with-display.sh sets one)";
    const std::string log = std::string(OSGWATER_TEST_TMP) + "/lake_frames_" + std::to_string(getpid()) + ".log";
    const std::string png = std::string(OSGWATER_TEST_TMP) + "/lake_frames_" + std::to_string(getpid()) + ".png";
    auto run = [&](const std::string& extra) {
        const std::string cmd = std::string("\"") + OSGWATER_LAKE_APP + "\" \"" + OSGWATER_LAKE_SCENE +
                                "\" --headless --no-hud --caustics-size 64 --screenshot \"" + png + "\" " + extra +
                                " > \"" + log + "\" 2>&1";
        const int rc = std::system(cmd.c_str());
        std::ifstream in(log);
        std::stringstream text;
        text << in.rdbuf();
        return std::make_pair(rc, text.str());
    };
    const auto two = run("--size 64 48 --frames 2");
    EXPECT_EQ(two.first, 0) << two.second;
    EXPECT_NE(two.second.find("median over 2 alternating blocks of the mean of 1 frame:"), std::string::npos) << two.second;
    const auto ten = run("--size 64 48 --frames 10");
    EXPECT_NE(ten.second.find("median over 5 alternating blocks of the mean of 2 frames:"), std::string::npos) << ten.second;
    const auto none = run("--size 0 0");
    EXPECT_NE(none.first, 0) << none.second;
    EXPECT_NE(none.second.find("--size 0 0: expected 16 to 8192 pixels per side"), std::string::npos) << none.second;
    EXPECT_EQ(none.second.find("FBO"), std::string::npos) << none.second;
    std::remove(log.c_str());
    std::remove(png.c_str());
}

// --help lists, for each option that names a value, every name the kit's table for it knows (a
// value added to the kit shows without touching the demo); --quality applies its preset first, so
// the options after it come on top, and a name it does not know is refused with the names it knows
TEST(LakeDemo, ItsHelpListsEveryNameTheKitKnowsAndTheQualityPresetComesFirst)
{
    ASSERT_TRUE(std::getenv("DISPLAY")) << "DISPLAY is not set (scripts/with-display.sh sets one)";
    const std::string log = std::string(OSGWATER_TEST_TMP) + "/lake_help_" + std::to_string(getpid()) + ".log";
    const std::string png = std::string(OSGWATER_TEST_TMP) + "/lake_help_" + std::to_string(getpid()) + ".png";
    auto run = [&](const std::string& args) {
        const std::string cmd = std::string("\"") + OSGWATER_LAKE_APP + "\" " + args + " > \"" + log + "\" 2>&1";
        const int rc = std::system(cmd.c_str());
        std::ifstream in(log);
        std::stringstream text;
        text << in.rdbuf();
        return std::make_pair(rc, text.str());
    };
    const std::string help = run("--help").second;
    // the help's entry of an option (to the next option: a long one wraps), and the names a table
    // lists (split at its separator)
    auto lineOf = [&](const std::string& option) {
        const size_t at = help.find("  " + option + " <");
        return at == std::string::npos ? std::string() : help.substr(at, help.find("\n  -", at) - at);
    };
    auto split = [](const std::string& names, const std::string& separator) {
        std::vector<std::string> out;
        for (size_t from = 0, to; from <= names.size(); from = to + separator.size()) {
            to = std::min(names.find(separator, from), names.size());
            out.push_back(names.substr(from, to - from));
        }
        return out;
    };
    using S = osgWater::WaterSettings;
    using F = osgWater::WaterSurface;
    const std::pair<const char*, std::vector<std::string>> tables[] = {
        { "--quality", split(S::qualityNames(), "|") },
        { "--lookup", split(S::refractionLookupNames(), "|") },
        { "--reflection-lookup", split(S::reflectionLookupNames(), "|") },
        { "--fresnel", split(S::fresnelModelNames(), "|") },
        { "--gather", split(S::causticsGatherNames(), "|") },
        { "--caustics", split(S::causticsMethodNames(), "|") },
        { "--underwater-model", split(S::underwaterModelNames(), "|") },
        { "--tone", split(S::toneCurveNames(), "|") },
        { "--waves", split(F::waveModelNames(), "|") },
        { "--mesh", split(F::meshLayoutNames(), "|") },
        { "--water-type", split(osgWater::waterTypeNames(), ", ") },
    };
    for (const auto& table : tables) {
        const std::string line = lineOf(table.first);
        ASSERT_FALSE(line.empty()) << table.first << " is not in the help:\n" << help;
        for (const std::string& name : table.second)
            EXPECT_NE(line.find(name), std::string::npos) << table.first << " lacks " << name << ": " << line;
    }
    const std::string common = std::string("\"") + OSGWATER_LAKE_SCENE + "\" --headless --no-hud --no-compare --frames 2 " +
                               "--size 64 48 --screenshot \"" + png + "\" ";
    const auto fast = run(common + "--quality fast");
    EXPECT_EQ(fast.first, 0) << fast.second;
    EXPECT_NE(fast.second.find("settings: quality fast, refraction one-step"), std::string::npos) << fast.second;
    const auto onTop = run(common + "--lookup iterative --quality exact --steps 2");
    EXPECT_NE(onTop.second.find("settings: quality custom, refraction iterative/2"), std::string::npos) << onTop.second;
    const auto unknown = run(common + "--quality best");
    EXPECT_NE(unknown.first, 0);
    EXPECT_NE(unknown.second.find("--quality best: not one of fast|balanced|exact"), std::string::npos) << unknown.second;
    std::remove(log.c_str());
    std::remove(png.c_str());
}

TEST(LakeDemo, TreesAreMirroredBelowTheShoreline)
{
    // calm water: the lake's short waves tilt the mirror rays by up to tens of degrees, and the
    // reflection's search follows each ray to its own hit, so over waves the trees' images break up
    RUN_DEMO_PAIR("--calm", "--calm --no-reflection", on, off);
    int mirrored = 0, checked = 0;
    for (const lake::Tree& t : lake::kTrees) {
        const float base = lake::height(t.x, t.y);
        const osg::Vec3d crown(t.x, t.y, -(base + 0.5 * t.height));        // mirror image of the crown's middle
        const osg::Vec3d beside(t.x + 0.45 * t.height, t.y, -(base + 0.9 * t.height)); // mirror image of sky beside it
        const osg::Vec2d a = project(crown), b = project(beside);
        const osg::Vec2d shore = project(osg::Vec3d(t.x, t.y, base));
        if (a.x() < 5 || a.x() > W - 5 || b.x() < 5 || b.x() > W - 5 || a.y() < 5 || b.y() < 5) continue;
        ++checked;
        EXPECT_LT(a.y(), shore.y()) << "a mirror image lies below the shoreline";
        const float ratioOn = luminance(on.at(a)) / std::max(luminance(on.at(b)), 1e-3f);
        const float ratioOff = luminance(off.at(a)) / std::max(luminance(off.at(b)), 1e-3f);
        // the dark crown in the water next to bright reflected sky; without reflection both are water
        // (clear water shows the bed differently at the two points: compare with that, not with 1)
        if (ratioOn < 0.75f && ratioOn < 0.6f * ratioOff) ++mirrored;
        RecordProperty("tree_" + std::to_string(checked), std::to_string(ratioOn) + " / " + std::to_string(ratioOff));
    }
    ASSERT_GE(checked, 3);
    EXPECT_GE(mirrored, checked - 1) << mirrored << " of " << checked << " trees mirrored";
}

TEST(LakeDemo, BedVisibleInShallowWaterNotInDeep)
{
    // reflection off, so the sky mirrored at grazing angles does not hide what refraction shows
    RUN_DEMO_PAIR("--no-reflection", "--no-reflection --no-refraction", on, off);
    osg::Vec3 shallowOn, deepOn, shallowOff;
    int nShallow = 0, nDeep = 0;
    for (int y = 0; y < H / 2; y += 3)
        for (int x = 0; x < W; x += 3) {
            osg::Vec3d hit;
            if (!waterPoint(x, y, hit)) continue;
            if ((osg::Vec2d(hit.x(), hit.y()) - osg::Vec2d(lake::kCrateX, lake::kCrateY)).length() < 4.0) continue;
            const float depth = -lake::height(float(hit.x()), float(hit.y()));
            if (depth > 0.2f && depth < 1.0f) { shallowOn += on.at(osg::Vec2d(x, y)); shallowOff += off.at(osg::Vec2d(x, y)); ++nShallow; }
            if (depth > 6.0f) { deepOn += on.at(osg::Vec2d(x, y)); ++nDeep; }
        }
    ASSERT_GT(nShallow, 50);
    ASSERT_GT(nDeep, 50);
    shallowOn /= float(nShallow);
    shallowOff /= float(nShallow);
    deepOn /= float(nDeep);
    // sand through shallow water (red channel: water colour has none), the water colour over deep water;
    // the sun on the sand is the caustic irradiance, (1 - F) exp(-k d) ~ 0.7 of the sun at these depths
    EXPECT_GT(shallowOn.x(), 0.15f) << "shallow " << shallowOn;
    EXPECT_LT(deepOn.x(), 0.08f) << "deep " << deepOn;
    EXPECT_GT(luminance(shallowOn), luminance(deepOn) + 0.1f);
    // and it is the refraction that shows it
    EXPECT_LT(shallowOff.x(), shallowOn.x() - 0.1f) << "without refraction " << shallowOff;
}

TEST(LakeDemo, CausticsChangeTheShallowBedAndNothingAboveTheWater)
{
    RUN_DEMO_PAIR("--no-reflection", "--no-reflection --no-caustics", on, off);
    double changedBed = 0, changedDry = 0;
    int nBed = 0, nDry = 0;
    for (int y = 0; y < H; y += 3)
        for (int x = 0; x < W; x += 3) {
            const osg::Vec3 a = on.at(osg::Vec2d(x, y)), b = off.at(osg::Vec2d(x, y));
            const double d = std::max(std::fabs(a.x() - b.x()), std::max(std::fabs(a.y() - b.y()), std::fabs(a.z() - b.z())));
            osg::Vec3d hit;
            if (!waterPoint(x, y, hit)) {
                if (y > H / 2 + 40) { changedDry = std::max(changedDry, d); ++nDry; } // sky, trees, dry shore
                continue;
            }
            const float depth = -lake::height(float(hit.x()), float(hit.y()));
            if (depth > 0.2f && depth < 2.0f) { changedBed += d; ++nBed; }
        }
    ASSERT_GT(nBed, 50);
    ASSERT_GT(nDry, 50);
    EXPECT_LE(changedDry, 2.0 / 255.0) << "caustics changed something above the water";
    EXPECT_GT(changedBed / nBed, 0.02) << "caustics did not change the shallow bed";
}

TEST(LakeDemo, UnderwaterViewIsFiniteAndFadesWithDistance)
{
    // The lake from the demo's underwater view (--underwater), in a float target: every pixel finite,
    // and eq. 10: the bed a few metres away is further from the water colour than the bed far away.
    testing_gl::Harness h(240, 180);
    REQUIRE_GL(h);
    osg::ref_ptr<osgWater::WaterNode> kit = new osgWater::WaterNode; // links the kit: its osgDB wrappers
    osg::ref_ptr<osg::Node> lake = osgDB::readRefNodeFile(OSGWATER_LAKE_SCENE);
    ASSERT_TRUE(lake.valid()) << OSGWATER_LAKE_SCENE;
    h.setScene(lake.get());
    // 2 m down over the slope of the bed, looking down it towards the deep centre
    const osg::Vec3d eye(0, -26, -2);
    h.lookAt(eye, osg::Vec3d(0, -20, -7), 50.0);
    h.frame(10.0);
    h.frame(10.0 + 1.0 / 60.0);
    osg::ref_ptr<osg::Image> img = h.readColor();
    ASSERT_TRUE(img.valid());
    EXPECT_TRUE(testing_gl::allFinite(img.get()));
    // the lake's water colour (its .osgt keeps the default), linear light, as the view shows it
    const glm::vec3 body = osgWater::optics::encodeSrgb(glm::vec3(0.0f, 0.2f, 0.1f));
    const osg::Vec3 water(body.x, body.y, body.z);
    auto distanceToWater = [&](const osg::Vec3d& p) {
        const osg::Vec4d c = osg::Vec4d(p, 1.0) * h.camera()->getViewMatrix() * h.camera()->getProjectionMatrix();
        const int x = int((c.x() / c.w() * 0.5 + 0.5) * h.width()), y = int((c.y() / c.w() * 0.5 + 0.5) * h.height());
        EXPECT_TRUE(x >= 0 && x < h.width() && y >= 0 && y < h.height()) << p << " is out of view";
        if (!(x >= 0 && x < h.width() && y >= 0 && y < h.height())) return 0.0f;
        const float* v = testing_gl::pixel(img.get(), x, y);
        return (osg::Vec3(v[0], v[1], v[2]) - water).length();
    };
    // bed points straight ahead on the view's centre line (heights from the lake model)
    const osg::Vec3d nearBed(0, -24, lake::height(0.0f, -24.0f)), farBed(0, -18, lake::height(0.0f, -18.0f));
    ASSERT_LT((nearBed - eye).length(), (farBed - eye).length());
    EXPECT_GT(distanceToWater(nearBed), distanceToWater(farBed) + 0.01f);
    EXPECT_LT(distanceToWater(farBed), 0.05f) << "~10 m of water (k = 0.5) leave under 1% of the bed";
}

TEST(LakeDemo, TheBuoyAndTheBoatRideTheWaves)
{
    // the demo's floaters on the lake, drawn by a viewer frame after frame: each one's origin at
    // the water's height at its position, less its draft, within 1 mm, and its z axis along the
    // surface normal
    testing_gl::Harness h(64, 48);
    REQUIRE_GL(h);
    osg::ref_ptr<osg::Node> lake;
    osg::ref_ptr<osgWater::WaterNode> water = loadLake(lake);
    ASSERT_TRUE(water.valid());
    osg::ref_ptr<osg::Switch> floaters = osgWaterApps::addFloaters(water.get(), osgWaterApps::kLakeBuoy, osgWaterApps::kLakeBoat, true);
    ASSERT_EQ(floaters->getNumChildren(), 2u);
    h.setScene(lake.get());
    h.lookAt(osg::Vec3d(0, -42, 4.5), osg::Vec3d(0, -24, 0));
    double worst = 0.0, rise = 0.0;
    double first[2] = { 0.0, 0.0 };
    for (int f = 0; f < 60; ++f) {
        const double t = 10.0 + f / 30.0;
        h.frame(t);
        for (unsigned int i = 0; i < 2; ++i) {
            const osgWater::FloatingTransform* ft = dynamic_cast<const osgWater::FloatingTransform*>(floaters->getChild(i));
            ASSERT_TRUE(ft);
            const osg::Vec2d at = ft->getPosition();
            osg::Vec3d n;
            const double z = water->getSurfaceHeightAt(at.x(), at.y(), t, &n) - ft->getDraft();
            const osg::Matrixd& m = ft->getMatrix();
            worst = std::max(worst, std::fabs(m.getTrans().z() - z));
            EXPECT_NEAR((osg::Vec3d(m(2, 0), m(2, 1), m(2, 2)) - n).length(), 0.0, 1e-6) << ft->getName();
            if (f == 0) first[i] = m.getTrans().z();
            rise = std::max(rise, std::fabs(m.getTrans().z() - first[i]));
        }
    }
    EXPECT_LT(worst, 1e-3) << "a floater left the surface";
    EXPECT_GT(rise, 0.005) << "the floaters should move with the waves";
    EXPECT_TRUE(testing_gl::allFinite(h.readColor().get()));
}

TEST(LakeDemo, ThePondAboveTheLakeIsWaterWithPassesOfItsOwn)
{
    // the demo's pond (--pond) seen across the lake: where its surface is, the image shows water
    // (sky reflected over the dark murky body: blue the largest channel, unlike grass and stone)
    // and not what is there without it; it renders passes for the view and none inside the lake's
    testing_gl::Harness h(400, 250);
    REQUIRE_GL(h);
    osg::ref_ptr<osg::Node> lake;
    osg::ref_ptr<osgWater::WaterNode> water = loadLake(lake);
    ASSERT_TRUE(water.valid());
    osg::ref_ptr<osgWater::WaterNode> pond;
    osg::ref_ptr<osg::Switch> sw = osgWaterApps::addPond(water.get(), osgWaterApps::kLakePond, false, &pond);
    ASSERT_TRUE(pond.valid());
    const double level = pond->getSurface()->getLevel();
    EXPECT_NEAR(level - lake::height(float(osgWaterApps::kLakePond.x()), float(osgWaterApps::kLakePond.y())),
                osgWaterApps::kPondWaterAboveGround, 0.05) << "built on the rim's ground";
    h.setScene(lake.get());
    h.lookAt(osgWaterApps::kPondViewEye, osgWaterApps::kPondViewCenter);
    h.frame(10.0);
    osg::ref_ptr<osg::Image> without = h.readColor();
    sw->setAllChildrenOn();
    h.frame(10.0);
    osg::ref_ptr<osg::Image> with = h.readColor();

    ASSERT_NE(osgWater::internals(*pond).getViewPasses(h.camera()), nullptr);
    osgWater::ViewPasses* lakePasses = osgWater::internals(*water).getViewPasses(h.camera());
    ASSERT_NE(lakePasses, nullptr);
    EXPECT_EQ(osgWater::internals(*pond).getViewPasses(lakePasses->getReflectionCamera()), nullptr) << "no passes inside the lake's";
    int water_ = 0, checked = 0;
    for (double dx : { -1.2, 0.0, 1.2 })
        for (double dy : { 0.0, 0.8, 1.5 }) { // the far part: the near wall hides the near one
            const osg::Vec2d px = h.pixelOf(osg::Vec3d(osgWaterApps::kLakePond.x() + dx, osgWaterApps::kLakePond.y() + dy, level));
            const float* c = testing_gl::pixel(with.get(), int(px.x()), int(px.y()));
            const float* o = testing_gl::pixel(without.get(), int(px.x()), int(px.y()));
            ++checked;
            const bool blue = c[2] > c[1] && c[2] > c[0];
            const bool changed = std::fabs(c[0] - o[0]) + std::fabs(c[1] - o[1]) + std::fabs(c[2] - o[2]) > 0.1f;
            if (blue && changed) ++water_;
        }
    EXPECT_EQ(water_, checked) << "pond surface pixels that show water";
}

