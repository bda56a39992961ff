// A red quad above flat water must appear mirrored in the reflection texture at the pixel the
// geometry predicts, and in the final image where the eye sees its mirror image.
#include "node/WaterNodeImpl.h"
#include "GLHarness.h"
#include <osgWater/WaterNode>
#include "optics/Optics.h"
#include <osgWater/WaterTypes>
#include <osgWater/WaterSurface>
#include "frame/ViewPasses.h"
#include <algorithm>
#include <functional>
#include <cmath>
#include <vector>

using namespace testing_gl;
using namespace osgWater;

namespace {

osg::ref_ptr<WaterNode> flatWater()
{
    osg::ref_ptr<WaterNode> water = new WaterNode;
    water->getSurface()->setWaves({});
    water->getSurface()->setSize(400.0f);
    water->getSettings()->setFovExtension(1.5f, 1.5f, 10.0f);
    return water;
}

// texture pixel of a local point seen through `view` with `proj` (independent of the kit's code)
osg::Vec2d texel(const osg::Vec3d& p, const osg::Matrixd& view, const osg::Matrixd& proj, int size)
{
    const osg::Vec4d c = osg::Vec4d(p, 1.0) * view * proj;
    return osg::Vec2d((c.x() / c.w() * 0.5 + 0.5) * size, (c.y() / c.w() * 0.5 + 0.5) * size);
}

bool isRed(const float* p) { return p[0] > 0.9f && p[1] < 0.1f && p[2] < 0.1f; }

// the wind's waves on `surface`: `speed` m/s towards `direction` over `fetch` metres (0: the water's size)
void raiseWind(WaterSurface& surface, float speed, float fetch, const osg::Vec2& direction)
{
    WindWaves wind;
    wind.speed = speed;
    wind.fetch = fetch;
    wind.direction = direction;
    surface.setWind(wind);
    surface.setWaveModel(WaterSurface::WAVES_WIND);
}

}

TEST(RenderReflection, RedQuadAppearsMirroredWhereGeometryPredicts)
{
    Harness h(320, 240);
    REQUIRE_GL(h);
    osg::ref_ptr<WaterNode> water = flatWater();
    water->getSettings()->setRefractionEnabled(false); // F = 1: the water shows the reflection alone
    // red quad: x in [-1, 1], z in [1, 3], at y = 12
    water->addChild(emissiveQuad(osg::Vec3(-1, 12, 1), osg::Vec3(1, 12, 1), osg::Vec3(1, 12, 3), osg::Vec3(-1, 12, 3),
                                 osg::Vec4(1, 0, 0, 1)));
    h.setScene(water.get());
    const osg::Vec3d eye(0, 0, 2);
    h.lookAt(eye, osg::Vec3d(0, 12, 0));
    h.frame(0.0);

    ViewPasses* passes = osgWater::internals(*water).getViewPasses(h.camera());
    ASSERT_TRUE(passes);
    osg::ref_ptr<osg::Image> refl = h.readTexture(passes->getReflectionCamera()->getColorTexture());
    ASSERT_TRUE(refl.valid());
    ASSERT_TRUE(allFinite(refl.get()));
    const int size = refl->s();
    EXPECT_EQ(size, 512);

    // expected: mirror (z -> -z) then the main camera with its tangents widened 1.5x
    const osg::Matrixd view = h.camera()->getViewMatrix();
    const osg::Matrixd proj = h.camera()->getProjectionMatrix() * osg::Matrixd::scale(1 / 1.5, 1 / 1.5, 1.0);
    const osg::Matrixd mirrorView = osg::Matrixd::scale(1, 1, -1) * view;
    double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
    for (const osg::Vec3d& c : { osg::Vec3d(-1, 12, 1), osg::Vec3d(1, 12, 1), osg::Vec3d(1, 12, 3), osg::Vec3d(-1, 12, 3) }) {
        const osg::Vec2d t = texel(c, mirrorView, proj, size);
        x0 = std::min(x0, t.x()); x1 = std::max(x1, t.x());
        y0 = std::min(y0, t.y()); y1 = std::max(y1, t.y());
    }
    ASSERT_GT(x1 - x0, 8.0);
    ASSERT_GT(y1 - y0, 8.0);
    // inside (1 px in from the predicted edges) red; 2 px outside not red: tolerance 1.5 px
    const double tol = 1.5;
    int inside = 0, insideRed = 0, ring = 0, ringRed = 0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const double cx = x + 0.5, cy = y + 0.5;
            const bool in = cx > x0 + tol && cx < x1 - tol && cy > y0 + tol && cy < y1 - tol;
            const bool out = cx < x0 - tol || cx > x1 + tol || cy < y0 - tol || cy > y1 + tol;
            const bool red = isRed(pixel(refl.get(), x, y));
            if (in) { ++inside; insideRed += red; }
            if (out) { ++ring; ringRed += red; }
        }
    EXPECT_EQ(insideRed, inside) << "predicted rect " << x0 << ".." << x1 << " x " << y0 << ".." << y1;
    EXPECT_EQ(ringRed, 0);

    // the final image: where the eye sees the mirror image of the quad's centre, the water is red;
    // beside it, the reflected sky (the clear colour)
    osg::ref_ptr<osg::Image> img = h.readColor();
    ASSERT_TRUE(allFinite(img.get()));
    const osg::Matrixd mainProj = h.camera()->getProjectionMatrix();
    const osg::Vec2d q = texel(osg::Vec3d(0, 12, -2), view, mainProj, 1);
    const float* c = pixel(img.get(), int(q.x() * h.width()), int(q.y() * h.height()));
    EXPECT_NEAR(c[0], 1.0f, 0.02f);
    EXPECT_NEAR(c[1], 0.0f, 0.02f);
    const osg::Vec2d s = texel(osg::Vec3d(5, 12, -2), view, mainProj, 1);
    const float* sky = pixel(img.get(), int(s.x() * h.width()), int(s.y() * h.height()));
    EXPECT_NEAR(sky[0], 0.2f, 0.02f);
    EXPECT_NEAR(sky[1], 0.3f, 0.02f);
    EXPECT_NEAR(sky[2], 0.8f, 0.02f);
}

TEST(RenderReflection, PlaneOffsetLooksUpTheMirrorRaysHitOnThePlane)
{
    // DeepWater's reflection lookup on flat water: the point the shader looks up (debug output) is
    // where the mirror ray meets the plane 3 m above the level, in closed form per pixel
    Harness h(160, 120);
    REQUIRE_GL(h);
    osg::ref_ptr<WaterNode> water = flatWaterOverBed(1.5f);
    water->getSettings()->setReflectionLookup(WaterSettings::REFLECTION_PLANE);
    water->getSettings()->setReflectionPlaneHeight(3.0f);
    water->setDebugOutput(DEBUG_REFLECTION_LOOKUP);
    h.setScene(water.get());
    const osg::Vec3d eye(0, -3, 2.5);
    h.lookAt(eye, osg::Vec3d(0, 8, -1.5));
    h.frame(0.0);
    osg::ref_ptr<osg::Image> img = h.readColor();
    const osg::Matrixd inv = osg::Matrixd::inverse(h.camera()->getViewMatrix() * h.camera()->getProjectionMatrix());
    int checked = 0;
    double worst = 0.0;
    for (int y = 0; y < h.height(); y += 3)
        for (int x = 0; x < h.width(); x += 3) {
            const double nx = (x + 0.5) / h.width() * 2 - 1, ny = (y + 0.5) / h.height() * 2 - 1;
            osg::Vec3d d = osg::Vec3d(nx, ny, 1) * inv - osg::Vec3d(nx, ny, -1) * inv;
            d.normalize();
            if (d.z() > -0.05) continue;
            const osg::Vec3d U = eye + d * (-eye.z() / d.z());
            const osg::Vec3d R(d.x(), d.y(), -d.z()); // the mirror ray
            const osg::Vec3d P = U + R * (3.0 / R.z());
            const float* c = pixel(img.get(), x, y);
            ASSERT_NEAR(c[3], 2.0f, 1e-3f) << "a point, at pixel " << x << ", " << y;
            worst = std::max(worst, (osg::Vec3d(c[0], c[1], c[2]) - P).length() / (P - U).length());
            ++checked;
        }
    EXPECT_GT(checked, 500);
    EXPECT_LT(worst, 1e-3) << "relative to the lookup distance";
}

namespace {

// Where the reflection lookup (debug output) lands against the exact hit of each pixel's mirror
// ray on a red wall, over water with waves, in reflection-texture texels. The eye ray meets the
// analytic surface (the drawn grid is fine enough to be within a millimetre of it), the mirror ray
// leaves it along the analytic normal, and its hit on the wall's plane is closed form.
struct MirrorLookupErrors {
    std::vector<double> texels;
    int notPoints = 0; //!< pixels whose ray meets the wall but whose lookup is not a point
    double meanReads = 0.0; //!< the reflection search's depth reads a pixel, over the same pixels
};

// Where the wall stands and the eye looks from: the sum's waves seen across 12 m from 2 m up; the
// wind's (ripples of 6 cm) from 1 m up across 4 m, each pixel's ray met within `reach` metres of the
// eye's foot, where a pixel spans less than the finest texel and the GPU's normal is the CPU's
// (level 0, bilinear)
struct WallView {
    bool wind = false, flat = false; //!< flat: no waves at all
    double eyeHeight = 2.0, wallY = 12.0, reach = 1e9;
    float budget = 0.25f; //!< the settings' ErrorBudget, texels
    int steps = 3;
    double top = 4.7; //!< the highest wall point checked (the reflection pass sees the wall up to it)
    int width = 240, height = 180;
};

MirrorLookupErrors mirrorLookupOnAWall(WaterSettings::ReflectionLookup lookup, bool eyeBelow, const WallView& view = WallView())
{
    MirrorLookupErrors out;
    Harness h(view.width, view.height);
    if (!h.ok()) return out;
    osg::ref_ptr<WaterNode> water = new WaterNode;
    WaterSurface* surface = water->getSurface();
    surface->setSize(60.0f);
    if (view.flat) {
        surface->setWaves({});
    } else if (view.wind) {
        raiseWind(*surface, 5.0f, 140.0f, osg::Vec2(0.3f, 1.0f)); // a breeze over the lake's 140 m
    } else {
        surface->setResolution(385); // 0.16 m between vertices: the grid within 0.5 mm of the waves
        surface->setWaves({ makeWave(0.3f, 1.0f, 3.0f, 0.04f), makeWave(1.0f, -0.4f, 2.2f, 0.025f) });
    }
    water->getSettings()->setReflectionLookup(lookup);
    water->getSettings()->setFovExtension(1.5f, 1.5f, 10.0f);
    water->getSettings()->setErrorBudget(view.budget);
    water->getSettings()->setSearchSteps(view.steps);
    water->setDebugOutput(DEBUG_REFLECTION_LOOKUP);
    // the wall: y = 12, x in [-8, 8], from 0.3 m to 5 m on the eye's side of the water
    const double s = eyeBelow ? -1.0 : 1.0, y0 = view.wallY, x0 = 8.0, z0 = 0.3 * s, z1 = 5.0 * s;
    water->addChild(emissiveQuad(osg::Vec3(-x0, y0, z0), osg::Vec3(x0, y0, z0), osg::Vec3(x0, y0, z1), osg::Vec3(-x0, y0, z1),
                                 osg::Vec4(1, 0, 0, 1)));
    h.setScene(water.get());
    const osg::Vec3d eye(0, 0, view.eyeHeight * s);
    h.lookAt(eye, osg::Vec3d(0, y0, 0));
    const double t = 0.0;
    h.frame(t);
    ViewPasses* passes = osgWater::internals(*water).getViewPasses(h.camera());
    if (!passes) return out;
    const osg::Matrixd reflMVP = passes->getReflectionCamera()->getViewProjection();
    const int size = passes->getReflectionCamera()->getTargetWidth();
    auto texel = [&](const osg::Vec3d& p) {
        const osg::Vec4d c = osg::Vec4d(p, 1.0) * reflMVP;
        return osg::Vec2d((c.x() / c.w() * 0.5 + 0.5) * size, (c.y() / c.w() * 0.5 + 0.5) * size);
    };
    osg::ref_ptr<osg::Image> img = h.readColor();
    water->setDebugOutput(DEBUG_WORK);
    h.frame(t);
    osg::ref_ptr<osg::Image> work = h.readColor();
    double reads = 0.0;
    const osg::Matrixd inv = osg::Matrixd::inverse(h.camera()->getViewMatrix() * h.camera()->getProjectionMatrix());
    for (int y = 0; y < h.height(); y += 2)
        for (int x = 0; x < h.width(); x += 2) {
            const double nx = (x + 0.5) / h.width() * 2 - 1, ny = (y + 0.5) / h.height() * 2 - 1;
            osg::Vec3d d = osg::Vec3d(nx, ny, 1) * inv - osg::Vec3d(nx, ny, -1) * inv;
            d.normalize();
            double ratio;
            osg::Vec3d U, N;
            if (!surface->intersect(eye, eye + d * 200.0, t, ratio, U, N)) continue;
            if (osg::Vec2d(U.x(), U.y()).length() > view.reach) continue;
            if (N * d > 0.0) N = -N;
            const osg::Vec3d R = d - N * (2.0 * (d * N));
            if (!(R.y() > 1e-3)) continue;
            const osg::Vec3d X = U + R * ((y0 - U.y()) / R.y());
            // the wall's inside, a margin from its edges (the texels there mix wall and sky)
            if (std::fabs(X.x()) > x0 - 0.3 || s * X.z() < 0.6 || s * X.z() > view.top) continue;
            const float* c = pixel(img.get(), x, y);
            if (!(std::fabs(c[3] - 2.0f) < 1e-3f)) { ++out.notPoints; continue; }
            out.texels.push_back((texel(osg::Vec3d(c[0], c[1], c[2])) - texel(X)).length());
            reads += pixel(work.get(), x, y)[1];
        }
    out.meanReads = out.texels.empty() ? 0.0 : reads / double(out.texels.size());
    std::sort(out.texels.begin(), out.texels.end());
    return out;
}

void expectMirrorSearchFindsTheWall(bool eyeBelow)
{
    Harness probe(8, 8);
    REQUIRE_GL(probe);
    const MirrorLookupErrors search = mirrorLookupOnAWall(WaterSettings::REFLECTION_SEARCH, eyeBelow);
    const MirrorLookupErrors offset = mirrorLookupOnAWall(WaterSettings::REFLECTION_OFFSET, eyeBelow);
    ASSERT_GT(search.texels.size(), 1000u);
    const double median = search.texels[search.texels.size() / 2], worst = search.texels.back();
    // a ray whose flat-water line of sight passes over the wall's top, and whose far end does too,
    // is taken for the sky: a few pixels along the top edge
    EXPECT_LE(search.notPoints, int(search.texels.size() / 500)) << "of " << search.texels.size();
    EXPECT_LT(median, 0.1) << "texels";
    EXPECT_LT(worst, 0.5) << "texels";
    // the thesis's U + c R looks up a point a metre from the water: tens of texels from the wall
    ASSERT_GT(offset.texels.size(), 1000u);
    EXPECT_GT(offset.texels[offset.texels.size() / 2], 10.0) << "texels";
}

}

TEST(RenderReflection, SearchFindsTheMirrorImageOfAWallOverWaves)
{
    expectMirrorSearchFindsTheWall(false);
}

TEST(RenderReflection, SearchFindsTheMirrorImageOfAWallUnderWaterSeenFromBelow)
{
    expectMirrorSearchFindsTheWall(true);
}

// The same under the wind's waves: the mirror rays leave the cascades' surface (its first crossing
// with each pixel's ray and its bilinear normal there, as the height query has them). From 1 m up,
// 4 m from the wall, the water within 2 m: a pixel spans a centimetre there, less than the finest
// texel (1.6 cm), so the shader's normal is the query's (from 2.3 m on its filtering starts, and a
// few pixels' lookups are 0.5 to 1 texel off). The wall up to 2.5 m: what the reflection pass's
// frustum holds from this close. Measured: median 0.009 texels, p99 0.26, worst 0.66.
TEST(RenderReflection, SearchFindsTheMirrorImageOfAWallOverTheWindsWaves)
{
    Harness probe(8, 8);
    REQUIRE_GL(probe);
    WallView view;
    view.wind = true;
    view.eyeHeight = 1.0;
    view.wallY = 4.0;
    view.reach = 2.0;
    view.top = 2.5;
    view.width = 480;
    view.height = 360;
    const MirrorLookupErrors search = mirrorLookupOnAWall(WaterSettings::REFLECTION_SEARCH, false, view);
    ASSERT_GT(search.texels.size(), 1000u);
    const double median = search.texels[search.texels.size() / 2];
    const double p99 = search.texels[size_t(0.99 * double(search.texels.size()))];
    RecordProperty("median_texels", std::to_string(median));
    RecordProperty("p99_texels", std::to_string(p99));
    RecordProperty("worst_texels", std::to_string(search.texels.back()));
    RecordProperty("pixels", std::to_string(search.texels.size()));
    EXPECT_LE(search.notPoints, int(search.texels.size() / 500)) << "of " << search.texels.size();
    EXPECT_LT(median, 0.1) << "texels";
    EXPECT_LT(p99, 0.5) << "texels";
}

// The search's error budget: over flat water and over the sum's waves, each budget's lookups lie
// within it of the exact hit on the wall at 99% of the pixels, and at every pixel within it plus
// the half texel a nearest-filtered depth map can add (the tolerance the search has always been
// held to). Over flat water the first guess is the hit: two depth reads (U's line of sight, the
// guess) at every budget; over waves a coarser budget reads fewer (counted by the work debug
// output, not timed). Eight steps, so the budget stops the search.
TEST(RenderReflection, TheSearchStopsWithinItsErrorBudgetAndSoonerForACoarserOne)
{
    Harness probe(8, 8);
    REQUIRE_GL(probe);
    for (bool flat : { true, false }) {
        std::vector<double> reads;
        for (float budget : { 1.0f / 16.0f, 0.25f, 1.0f, 4.0f }) {
            WallView view;
            view.flat = flat;
            view.budget = budget;
            view.steps = 8;
            const MirrorLookupErrors search = mirrorLookupOnAWall(WaterSettings::REFLECTION_SEARCH, false, view);
            ASSERT_GT(search.texels.size(), 1000u);
            const double p99 = search.texels[size_t(0.99 * double(search.texels.size()))];
            const char* water = flat ? "flat" : "waves";
            EXPECT_LT(p99, budget) << "texels, budget " << budget << ", " << water;
            EXPECT_LT(search.texels.back(), budget + 0.5) << "texels, budget " << budget << ", " << water;
            reads.push_back(search.meanReads);
            std::printf("%s, budget %.4f texels: p99 %.3f texels, worst %.3f, %.2f depth reads a pixel\n", water, budget,
                        p99, search.texels.back(), search.meanReads);
        }
        if (flat) {
            for (double r : reads) EXPECT_LT(r, 2.05) << "depth reads a pixel over flat water";
        } else {
            for (size_t i = 1; i < reads.size(); ++i) EXPECT_LT(reads[i], reads[i - 1]) << i;
        }
    }
}

namespace {

// flat water over a uniform grey bed: every water pixel is eq. 9 of eq. 5 of the bed and the
// reflected sky, with the settings' Fresnel model and attenuation eq. 4 along the exact refracted
// path, per channel with the water model's extinction and body colour
void expectShadingAsTheOpticsMirror(const std::function<void(WaterSettings&)>& configure)
{
    Harness h(160, 120);
    REQUIRE_GL(h);
    const float depth = 1.5f;
    osg::ref_ptr<WaterNode> water = flatWaterOverBed(depth);
    water->getSettings()->setFovExtension(1.5f, 1.5f, 10.0f);
    configure(*water->getSettings());
    h.setScene(water.get());
    const osg::Vec3d eye(0, -3, 2.5);
    h.lookAt(eye, osg::Vec3d(0, 8, -1.5));
    h.frame(0.0);
    osg::ref_ptr<osg::Image> img = h.readColor();
    ASSERT_TRUE(allFinite(img.get()));

    const MirrorComparison m = compareFlatWaterWithOptics(h, img.get(), *water->getSettings(), osg::Matrixd(), 0.0,
                                                          -depth, kBedGrey, 7);
    EXPECT_FALSE(m.bedMissed);
    EXPECT_GT(m.checked, 100);
    EXPECT_LT(m.worst, 2.0 / 255.0) << "eq. 9 in linear light, half-float pass textures: tolerance 2/255";
}

}

// The water models: the thesis's one k and colour, and each per-channel preset.
class RenderWaterModel : public ::testing::TestWithParam<std::string> {};

TEST_P(RenderWaterModel, ShadedColourMatchesTheOpticsMirror)
{
    expectShadingAsTheOpticsMirror([](WaterSettings& s) {
        if (const WaterType* type = findWaterType(GetParam())) applyWaterType(s, *type);
    });
}

INSTANTIATE_TEST_SUITE_P(Models, RenderWaterModel, waterModels(), waterModelTestName);

// The Fresnel models, each held to its CPU mirror (optics::fresnelModel) by the shaded colour
class RenderFresnelModel : public ::testing::TestWithParam<WaterSettings::FresnelModel> {};

TEST_P(RenderFresnelModel, ShadedColourMatchesTheOpticsMirror)
{
    expectShadingAsTheOpticsMirror([](WaterSettings& s) { s.setFresnelModel(GetParam()); });
}

INSTANTIATE_TEST_SUITE_P(Fresnel, RenderFresnelModel,
                         ::testing::Values(WaterSettings::FRESNEL_SCHLICK, WaterSettings::FRESNEL_POWER,
                                           WaterSettings::FRESNEL_EXACT, WaterSettings::FRESNEL_RECIPROCAL),
                         [](const ::testing::TestParamInfo<WaterSettings::FresnelModel>& info) {
                             return std::string(WaterSettings::fresnelModelName(info.param));
                         });

namespace {

// The far water's reflection of white stripes on a black sky, seen from 30 m over water 3 km
// wide: for each image row of water between 250 m and 1 km out, how much the stripes still show
// (the standard deviation of the row's luminance over its mean), median over the rows.
double farStripesContrast(bool wind)
{
    Harness h(240, 180);
    if (!h.ok()) return -1.0;
    osg::ref_ptr<WaterNode> water = new WaterNode;
    WaterSurface* surface = water->getSurface();
    surface->setSize(3000.0f);
    if (wind) {
        raiseWind(*surface, 8.0f, 0.0f, osg::Vec2(0.0f, 1.0f)); // over the water's 3 km
    } else {
        surface->setWaves({}); // a mirror: every slope drawn (none), no roughness
    }
    water->getSettings()->setRefractionEnabled(false); // F alone weighs the reflection
    water->getSettings()->setCausticsEnabled(false);
    water->getSettings()->setGlowEnabled(false);
    // stripes 30 m wide every 60 m, 1.4 km beyond the water's far edge: 0.013 rad apart seen from
    // the eye; the reflection pass holds about 600 texels a radian, so 8 texels a stripe
    const float y = 3000.0f;
    for (float x = -4000.0f; x < 4000.0f; x += 60.0f)
        water->addChild(emissiveQuad(osg::Vec3(x, y, -50), osg::Vec3(x + 30, y, -50), osg::Vec3(x + 30, y, 2000),
                                     osg::Vec3(x, y, 2000), osg::Vec4(1, 1, 1, 1)));
    h.camera()->setClearColor(osg::Vec4(0, 0, 0, 1));
    h.setScene(water.get());
    const osg::Vec3d eye(0, 0, 30);
    h.lookAt(eye, osg::Vec3d(0, 1000, 10));
    h.frame(0.0);
    osg::ref_ptr<osg::Image> img = h.readColor();
    std::vector<double> contrast;
    // the rows between where flat water 250 m and 1 km out lands
    const double near = h.pixelOf(osg::Vec3d(0, 250, 0)).y(), far = h.pixelOf(osg::Vec3d(0, 1000, 0)).y();
    for (int row = 0; row < h.height(); ++row) {
        if (row < near || row > far) continue;
        double sum = 0.0, sum2 = 0.0;
        int n = 0;
        for (int x = 20; x < h.width() - 20; ++x) {
            const float* c = pixel(img.get(), x, row);
            const double l = 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
            sum += l;
            sum2 += l * l;
            ++n;
        }
        const double mean = sum / n;
        if (mean > 1e-4) contrast.push_back(std::sqrt(std::max(sum2 / n - mean * mean, 0.0)) / mean);
    }
    if (contrast.size() < 10) return -2.0;
    std::sort(contrast.begin(), contrast.end());
    return contrast[contrast.size() / 2];
}

}

// Slopes too fine for the pixel turn the mirrored ray each its own way: the reflection there is the
// scene blurred over the cone they spread (twice their deviation, about 0.3 rad at 8 m/s by Cox
// and Munk), not one sharp point of it, so stripes 0.013 rad apart must merge to their mean.
// Calm water (no slope below any pixel) keeps them sharp. Read at the texture's level 0 the far
// water showed every stripe, scattered by the waves (contrast about 1).
TEST(RenderReflection, UnderTheWindFarWaterReflectsThroughTheSlopesBelowItsPixelsBlurred)
{
    Harness probe(8, 8);
    REQUIRE_GL(probe);
    const double calm = farStripesContrast(false), windy = farStripesContrast(true);
    ASSERT_GE(calm, 0.0);
    ASSERT_GE(windy, 0.0);
    EXPECT_GT(calm, 0.5) << "the calm reflection shows the stripes";
    EXPECT_LT(windy, 0.1) << "the stripes merged (calm: " << calm << ")";
}
