// Caustics (thesis ch. 8): the caustics texture holds the sun power per area seen from the sun,
// in units of the sun's irradiance. Flat water must give the transmitted, attenuated irradiance
// everywhere; a lens-shaped bump must focus where geometric optics says and conserve energy; the
// three gather paths must agree; no target may hold NaN/Inf, whatever the sun's elevation. Each
// for both methods: photon splatting and the area-ratio mesh (RenderCausticsMethod).
#include "node/WaterNodeImpl.h"
#include "GLHarness.h"
#include "WarnCapture.h"
#include <osgWater/WaterNode>
#include "optics/Optics.h"
#include "optics/Srgb.h"
#include "caustics/ProceduralCaustics.h"
#include <osgWater/WaterSurface>
#include <osgWater/WaterTypes>
#include <osg/Geometry>
#include <osg/Material>
#include "frame/PassMath.h"
#include <osg/io_utils>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <set>

using namespace testing_gl;
using namespace osgWater;

namespace {

const float kK = 0.5f; // attenuation per metre

// A square water mesh of side `size` with a Gaussian bump h0 exp(-r^2 / 2 s^2) at (x0, y0):
// exact positions and normals on a fine grid.
osg::Geometry* bumpMesh(float size, int n, float x0, float y0, float h0, float s)
{
    osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array, nn = new osg::Vec3Array;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            const float x = -size / 2 + size * i / n, y = -size / 2 + size * j / n;
            const float dx = x - x0, dy = y - y0, h = h0 * std::exp(-(dx * dx + dy * dy) / (2 * s * s));
            v->push_back(osg::Vec3(x, y, h));
            osg::Vec3 N(h * dx / (s * s), h * dy / (s * s), 1.0f); // (-dh/dx, -dh/dy, 1)
            N.normalize();
            nn->push_back(N);
        }
    osg::ref_ptr<osg::DrawElementsUInt> tris = new osg::DrawElementsUInt(GL_TRIANGLES);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const unsigned a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
            for (unsigned k : { a, b, d, a, d, c }) tris->push_back(k);
        }
    osg::Geometry* g = new osg::Geometry;
    g->setVertexArray(v.get());
    g->setNormalArray(nn.get(), osg::Array::BIND_PER_VERTEX);
    g->addPrimitiveSet(tris.get());
    return g;
}

// A lit horizontal quad (white diffuse, no ambient or emission): its colour is the sun it receives.
osg::Geode* litQuad(float x0, float y0, float x1, float y1, float z)
{
    osg::Geode* g = emissiveQuad(osg::Vec3(x0, y0, z), osg::Vec3(x1, y0, z), osg::Vec3(x1, y1, z), osg::Vec3(x0, y1, z),
                                 osg::Vec4(1, 1, 1, 1));
    osg::ref_ptr<osg::Material> m = new osg::Material;
    m->setDiffuse(osg::Material::FRONT_AND_BACK, osg::Vec4(1, 1, 1, 1));
    m->setAmbient(osg::Material::FRONT_AND_BACK, osg::Vec4(0, 0, 0, 1));
    m->setEmission(osg::Material::FRONT_AND_BACK, osg::Vec4(0, 0, 0, 1));
    g->getOrCreateStateSet()->setAttribute(m.get());
    return g;
}

struct CausticsScene {
    Harness h{ 64, 64 };
    osg::ref_ptr<WaterNode> water = new WaterNode;
    float bedZ;

    CausticsScene(float size, int res, int grid, osg::Vec3 sun, float bed, osg::Geometry* mesh = nullptr)
        : bedZ(bed)
    {
        if (!h.ok()) return;
        water->getSurface()->setWaves({});
        water->getSurface()->setSize(size);
        if (mesh) water->getSurface()->setMesh(mesh);
        WaterSettings* s = water->getSettings();
        s->setCausticsResolution(res);
        s->setPhotonGridSize(grid);
        s->setSunDirection(sun);
        s->setAttenuation(kK);
        s->setReflectionEnabled(false); // only the caustics passes matter here
        s->setRefractionEnabled(false);
        const float b = size / 2;
        water->addChild(emissiveQuad(osg::Vec3(-b, -b, bed), osg::Vec3(b, -b, bed), osg::Vec3(b, b, bed),
                                     osg::Vec3(-b, b, bed), osg::Vec4(1, 1, 1, 1)));
        h.setScene(water.get());
        h.lookAt(osg::Vec3d(0, -1, 30), osg::Vec3d(0, 0, 0));
    }

    void setGather(WaterSettings::CausticsGather g) { water->getSettings()->setCausticsGather(g); }

    // the bed as a lit white surface (its colour: the sun it receives) seen through the refraction
    // pass, a white sun, no ambient
    void lightTheBed(float size)
    {
        water->removeChildren(0, water->getNumChildren());
        water->addChild(litQuad(-size / 2, -size / 2, size / 2, size / 2, bedZ));
        WaterSettings* s = water->getSettings();
        s->setRefractionEnabled(true);
        s->setAmbientColor(osg::Vec3(0, 0, 0));
        s->setSunColor(osg::Vec3(1, 1, 1));
    }

    // a frame, then the colour the refraction pass shows at local point p
    osg::Vec3 refracted(const osg::Vec3d& p)
    {
        h.frame(1.0);
        RefractionCamera* rc = osgWater::internals(*water).getViewPasses(h.camera())->getRefractionCamera();
        osg::ref_ptr<osg::Image> img = h.readTexture(rc->getColorTexture());
        const osg::Vec3d t = projectToTexture(p, rc->getViewMatrix(), rc->getProjectionMatrix());
        const float* c = pixel(img.get(), int(t.x() * img->s()), int(t.y() * img->t()));
        return osg::Vec3(c[0], c[1], c[2]);
    }

    osg::ref_ptr<osg::Image> render()
    {
        h.frame(1.0);
        CausticsCamera* c = osgWater::internals(*water).getCausticsCamera();
        if (!c) return nullptr;
        return h.readTexture(c->getCausticsTexture());
    }

    // the bed point under caustics texel (i, j): where that texel's sun ray meets z = bedZ
    osg::Vec3d bedPoint(const osg::Image* img, int i, int j) const
    {
        const osg::Matrixd inv = osg::Matrixd::inverse(osgWater::internals(*water).getCausticsCamera()->getLighting().localToSun);
        const double u = (i + 0.5) / img->s(), v = (j + 0.5) / img->t();
        const osg::Vec3d p0 = osg::Vec3d(u, v, 0.0) * inv, p1 = osg::Vec3d(u, v, 1.0) * inv;
        return p0 + (p1 - p0) * ((bedZ - p0.z()) / (p1.z() - p0.z()));
    }

    // sun-projected area of one caustics texel, m^2
    double texelArea(const osg::Image* img) const
    {
        const osg::Vec3d& w = osgWater::internals(*water).getCausticsCamera()->getWindow();
        return w.x() * w.y() / (double(img->s()) * img->t());
    }
};

double value(const osg::Image* img, int i, int j) { return pixel(img, i, j)[0]; }

std::string methodName(const testing::TestParamInfo<WaterSettings::CausticsMethod>& info)
{
    return info.param == WaterSettings::CAUSTICS_AREA_MESH   ? "AreaMesh"
           : info.param == WaterSettings::CAUSTICS_PROCEDURAL ? "Procedural"
                                                              : "Photons";
}

// Transmitted, attenuated irradiance under flat water of depth H, sun at cosine cosL (Schlick, q 5),
// extinction k per metre of the sun's path.
double flatIrradiance(double cosL, double H, double k = kK)
{
    const float f = optics::normalReflectance(1.0f, 1.333f);
    const double F = optics::fresnelSchlick(float(cosL), f, 5.0f);
    const double eta = 1.0 / 1.333, cosT = std::sqrt(1.0 - eta * eta * (1.0 - cosL * cosL));
    return (1.0 - F) * std::exp(-k * H / cosT);
}


// Every gather path's caustics against the CPU's (the mirror), within 2% of the CPU's largest
// value; returns the CPU's.
osg::ref_ptr<osg::Image> expectGatherPathsAgree(CausticsScene& sc)
{
    osg::ref_ptr<osg::Image> ref;
    double refMax = 0;
    for (WaterSettings::CausticsGather g : { WaterSettings::GATHER_CPU, WaterSettings::GATHER_POINTS_COPY,
                                             WaterSettings::GATHER_POINTS_TEXTURE }) {
        sc.setGather(g);
        osg::ref_ptr<osg::Image> img = sc.render();
        if (!img.valid()) {
            ADD_FAILURE() << "no caustics with " << causticsGatherLabel(g);
            return ref;
        }
        EXPECT_EQ(sc.water->getActiveCausticsGather(), g);
        if (!ref.valid()) {
            ref = img;
            for (int j = 0; j < img->t(); ++j)
                for (int i = 0; i < img->s(); ++i) refMax = std::max(refMax, value(img.get(), i, j));
            EXPECT_GT(refMax, 0.1);
            continue;
        }
        double worst = 0;
        for (int j = 0; j < img->t(); ++j)
            for (int i = 0; i < img->s(); ++i)
                worst = std::max(worst, std::fabs(value(img.get(), i, j) - value(ref.get(), i, j)));
        EXPECT_LE(worst, 0.02 * refMax) << causticsGatherLabel(g) << " vs CPU";
    }
    return ref;
}

class RenderCausticsMethod : public testing::TestWithParam<WaterSettings::CausticsMethod> {};
// the methods calibrated to flat water: the photons' two and the procedural construction
class RenderCausticsOnFlatWater : public testing::TestWithParam<WaterSettings::CausticsMethod> {};

}

INSTANTIATE_TEST_SUITE_P(Caustics, RenderCausticsMethod,
                         testing::Values(WaterSettings::CAUSTICS_PHOTONS, WaterSettings::CAUSTICS_AREA_MESH), methodName);
INSTANTIATE_TEST_SUITE_P(Caustics, RenderCausticsOnFlatWater,
                         testing::Values(WaterSettings::CAUSTICS_PHOTONS, WaterSettings::CAUSTICS_AREA_MESH,
                                         WaterSettings::CAUSTICS_PROCEDURAL), methodName);

TEST_P(RenderCausticsOnFlatWater, FlatWaterGivesTheTransmittedIrradianceEverywhere)
{
    for (const osg::Vec3 sun : { osg::Vec3(0, 0, 1), osg::Vec3(0.3f, 0.2f, 0.93f) }) {
        CausticsScene sc(20.0f, 64, 128, sun, -2.0f);
        REQUIRE_GL(sc.h);
        sc.water->getSettings()->setCausticsMethod(GetParam());
        osg::ref_ptr<osg::Image> img = sc.render();
        ASSERT_TRUE(img.valid()) << "no caustics pass ran";
        osg::Vec3 L = sun;
        L.normalize();
        const double expected = flatIrradiance(L.z(), 2.0);
        double lo = 1e30, hi = -1e30, sum = 0;
        int n = 0;
        for (int j = 0; j < img->t(); ++j)
            for (int i = 0; i < img->s(); ++i) {
                const osg::Vec3d p = sc.bedPoint(img.get(), i, j);
                if (std::fabs(p.x()) > 7 || std::fabs(p.y()) > 7) continue; // away from the water's edge
                const double c = value(img.get(), i, j);
                lo = std::min(lo, c);
                hi = std::max(hi, c);
                sum += c;
                ++n;
            }
        ASSERT_GT(n, 500);
        const double mean = sum / n;
        EXPECT_NEAR(mean, expected, 0.02 * expected) << "sun " << L;
        EXPECT_LE(hi - lo, 0.02 * mean) << "sun " << L << ": min " << lo << " max " << hi;
    }
}

TEST(RenderCaustics, ProceduralCausticsOverASineWaveAreTheirCpuMirrorsTexelByTexel)
{
    // one 2 m wave, 3 cm high, over a bed 2 m down; 3 cm texels. Each texel against the CPU
    // construction at its own bed point (osgWater/caustics/ProceduralCaustics.h, double precision): the lines
    // must be where the construction puts them, not just as bright on average
    for (const osg::Vec3 sun : { osg::Vec3(0, 0, 1), osg::Vec3(0.5f, 0.2f, 0.85f) }) {
        CausticsScene sc(8.0f, 256, 64, sun, -2.0f);
        REQUIRE_GL(sc.h);
        sc.water->getSurface()->setWaves({ makeWave(1, 0, 2.0f, 0.03f) });
        sc.water->getSettings()->setCausticsMethod(WaterSettings::CAUSTICS_PROCEDURAL);
        osg::ref_ptr<osg::Image> img = sc.render();
        ASSERT_TRUE(img.valid()) << "no caustics pass ran";
        osg::Vec3 L = sun;
        L.normalize();
        const glm::dvec3 towardsSun(L.x(), L.y(), L.z());
        const double transmitted = 1.0 - optics::fresnelSchlick(L.z(), optics::normalReflectance(1.0f, 1.333f), 5.0f);
        const double flat = flatIrradiance(L.z(), 2.0); // the sun's disc seen straight through flat water
        int n = 0, off = 0, litGpu = 0, litCpu = 0;
        double worst = 0.0;
        for (int j = 8; j < img->t() - 8; ++j)
            for (int i = 8; i < img->s() - 8; ++i) {
                const osg::Vec3d p = sc.bedPoint(img.get(), i, j);
                if (std::fabs(p.x()) > 3 || std::fabs(p.y()) > 3) continue; // the backward ray stays on the water
                const procedural::Backtrace tr = procedural::backtrace(glm::dvec3(p.x(), p.y(), p.z()), towardsSun,
                                                                       *sc.water->getSurface(), 1.0, 1.0, 1.333);
                const double cpu = procedural::causticLight(tr, transmitted, kK);
                const double gpu = value(img.get(), i, j);
                ++n;
                litGpu += gpu > 0.5 * flat;
                litCpu += cpu > 0.5 * flat;
                // at the disc's rim the light steps from 1 to the halo's quarter: a texel there may
                // fall either side in float
                if (std::fabs(gpu - cpu) > 0.02) ++off;
                worst = std::max(worst, std::fabs(gpu - cpu));
            }
        ASSERT_GT(n, 10000);
        EXPECT_GT(litCpu, n / 100) << "the construction lights lines";
        EXPECT_NEAR(litGpu, litCpu, 0.02 * n + 1) << "sun " << L;
        EXPECT_LT(off, n / 50) << "sun " << L << ": " << off << " of " << n << " texels off by over 0.02 (worst " << worst << ")";
    }
}

TEST(RenderCaustics, ProceduralCausticsPerPixelAreTheConstructionAtEachFragmentsOwnPlace)
{
    // the paper's screen-space variant: no photon or gather pass, the scene program makes the light
    // per fragment. The bed (lit, white, no ambient) seen in the refraction pass: on flat water n.l
    // times the calibrated (1 - F) exp(-k d); over one 2 m wave, 3 cm high, every texel whose bed
    // point lies on the water against the CPU construction at that point, times n.l
    for (const bool wave : { false, true }) {
        const osg::Vec3 sun = osg::Vec3(0.5f, 0.2f, 0.85f);
        CausticsScene sc(8.0f, 256, 64, sun, -2.0f);
        REQUIRE_GL(sc.h);
        if (wave) sc.water->getSurface()->setWaves({ makeWave(1, 0, 2.0f, 0.03f) });
        sc.water->getSettings()->setCausticsMethod(WaterSettings::CAUSTICS_PROCEDURAL_SCREEN);
        sc.lightTheBed(8.0f);
        sc.h.frame(1.0);
        sc.h.frame(1.0);
        const PassPlan plan = osgWater::internals(*sc.water).getPassPlan(sc.h.camera());
        EXPECT_FALSE(plan.runs(PASS_PHOTONS) || plan.runs(PASS_GATHER)) << plan.describe();
        EXPECT_TRUE(osgWater::internals(*sc.water).getCausticsCamera()->getLighting().procedural);

        RefractionCamera* rc = osgWater::internals(*sc.water).getViewPasses(sc.h.camera())->getRefractionCamera();
        osg::ref_ptr<osg::Image> img = sc.h.readTexture(rc->getColorTexture());
        ASSERT_TRUE(img.valid());
        const osg::Matrixd inv = osg::Matrixd::inverse(rc->getViewMatrix() * rc->getProjectionMatrix());
        osg::Vec3 L = sun;
        L.normalize();
        const glm::dvec3 towardsSun(L.x(), L.y(), L.z());
        const double transmitted = 1.0 - optics::fresnelSchlick(L.z(), optics::normalReflectance(1.0f, 1.333f), 5.0f);
        int n = 0, off = 0, lit = 0;
        for (int j = 0; j < img->t(); ++j)
            for (int i = 0; i < img->s(); ++i) {
                const double x = (i + 0.5) / img->s() * 2 - 1, y = (j + 0.5) / img->t() * 2 - 1;
                const osg::Vec3d a = osg::Vec3d(x, y, -1) * inv, b = osg::Vec3d(x, y, 1) * inv;
                const osg::Vec3d p = a + (b - a) * ((-2.0 - a.z()) / (b.z() - a.z()));
                if (std::fabs(p.x()) > 3 || std::fabs(p.y()) > 3) continue; // the backward ray stays on the water
                const double cpu = L.z() * (wave ? procedural::causticLight(procedural::backtrace(glm::dvec3(p.x(), p.y(), p.z()), towardsSun,
                                                                                                 *sc.water->getSurface(), 1.0, 1.0, 1.333),
                                                                             transmitted, kK)
                                                 : flatIrradiance(L.z(), 2.0));
                const double gpu = pixel(img.get(), i, j)[0];
                ++n;
                lit += gpu > 0.5 * L.z() * flatIrradiance(L.z(), 2.0);
                // tolerance: 0.02 (the 8-bit target, and the disc's rim, where the light steps)
                off += std::fabs(gpu - cpu) > 0.02;
            }
        std::printf("per pixel, %s: %d texels, %d lit, %d off by 0.02\n", wave ? "one wave" : "flat", n, lit, off);
        ASSERT_GT(n, 3000);
        if (wave) EXPECT_GT(lit, n / 100) << "the lines are lit";
        EXPECT_LE(off, n / 50) << (wave ? "wave" : "flat") << ": " << off << " of " << n << " texels off";
    }
    // with reflective caustics, whose passes run anyway: into the texture, the photon pass empty
    CausticsScene sc(8.0f, 256, 64, osg::Vec3(0.5f, 0.2f, 0.85f), -2.0f);
    REQUIRE_GL(sc.h);
    sc.water->addChild(litQuad(3.0f, -1.0f, 3.5f, 1.0f, 1.0f)); // something above the water to light
    sc.water->getSettings()->setCausticsMethod(WaterSettings::CAUSTICS_PROCEDURAL_SCREEN);
    sc.water->getSettings()->setReflectiveCaustics(true);
    sc.h.frame(1.0);
    EXPECT_FALSE(osgWater::internals(*sc.water).getCausticsCamera()->getLighting().procedural);
    EXPECT_TRUE(osgWater::internals(*sc.water).getPassPlan(sc.h.camera()).runs(PASS_GATHER)) << osgWater::internals(*sc.water).getPassPlan(sc.h.camera()).describe();
}

TEST(RenderCaustics, TheCausticsTextureHasMipmapsOfItsOwnTexelsEveryFrame)
{
    // the procedural caustics' paper mipmaps its texture against aliasing (and so do the other
    // methods, through the same texture): level 1 must be the 2 x 2 means of level 0 in every frame
    // (the waves move), and it is read through the mipmaps
    CausticsScene sc(8.0f, 256, 64, osg::Vec3(0.3f, 0.2f, 0.93f), -2.0f);
    REQUIRE_GL(sc.h);
    sc.water->getSurface()->setWaves({ makeWave(1, 0, 2.0f, 0.03f) });
    sc.water->getSettings()->setCausticsMethod(WaterSettings::CAUSTICS_PROCEDURAL);
    for (double t : { 1.0, 1.7 }) {
        sc.h.frame(t);
        osg::Texture2D* c = osgWater::internals(*sc.water).getCausticsCamera()->getCausticsTexture();
        EXPECT_EQ(c->getFilter(osg::Texture::MIN_FILTER), osg::Texture::LINEAR_MIPMAP_LINEAR);
        osg::ref_ptr<osg::Image> base = sc.h.readTexture(c, 0), half = sc.h.readTexture(c, 1);
        ASSERT_TRUE(base.valid() && half.valid());
        ASSERT_EQ(half->s(), base->s() / 2);
        double worst = 0.0, lit = 0.0;
        for (int j = 0; j < half->t(); ++j)
            for (int i = 0; i < half->s(); ++i) {
                const double mean = 0.25 * (pixel(base.get(), 2 * i, 2 * j)[0] + pixel(base.get(), 2 * i + 1, 2 * j)[0] +
                                            pixel(base.get(), 2 * i, 2 * j + 1)[0] + pixel(base.get(), 2 * i + 1, 2 * j + 1)[0]);
                worst = std::max(worst, std::fabs(pixel(half.get(), i, j)[0] - mean));
                lit = std::max(lit, mean);
            }
        EXPECT_GT(lit, 0.01) << "the construction lights lines at t = " << t;
        // tolerance: two steps of the 16-bit target
        EXPECT_LT(worst, 2.0 / 65535.0) << "level 1 is not the means of level 0 at t = " << t;
    }
}

TEST(RenderCaustics, ProceduralCausticsGiveTheirPhotonsBackToATileAndToTheSunsReflection)
{
    // procedural caustics empty the photon pass; tiled after them, the tile's photons are drawn again
    // (flat water: 1 - F in every texel of the tile), and the reflective caustics keep theirs
    const osg::Vec3 sun(0.3f, 0.2f, 0.93f);
    osg::Vec3 L = sun;
    L.normalize();
    const double transmitted = 1.0 - optics::fresnelSchlick(L.z(), optics::normalReflectance(1.0f, 1.333f), 5.0f);
    CausticsScene sc(20.0f, 32, 128, sun, -2.0f);
    REQUIRE_GL(sc.h);
    WaterSettings* s = sc.water->getSettings();
    s->setCausticsMethod(WaterSettings::CAUSTICS_PROCEDURAL);
    s->setReflectiveCaustics(true);
    sc.water->addChild(litQuad(-1, -1, 1, 1, 1.0f)); // something above the water for the sun's reflection
    ASSERT_TRUE(sc.render().valid());
    EXPECT_TRUE(osgWater::internals(*sc.water).getCausticsCamera()->getPhotonCamera()->isEmpty());
    ASSERT_TRUE(osgWater::internals(*sc.water).getReflectedCausticsCamera() != nullptr);
    EXPECT_FALSE(osgWater::internals(*sc.water).getReflectedCausticsCamera()->getPhotonCamera()->isEmpty());
    EXPECT_EQ(osgWater::internals(*sc.water).getReflectedCausticsCamera()->getGather()->getCausticsMethod(), WaterSettings::CAUSTICS_PHOTONS);
    s->setCausticsTileSize(4.0f);
    osg::ref_ptr<osg::Image> img = sc.render();
    ASSERT_TRUE(img.valid());
    EXPECT_FALSE(osgWater::internals(*sc.water).getCausticsCamera()->getPhotonCamera()->isEmpty());
    for (int j = 0; j < img->t(); ++j)
        for (int i = 0; i < img->s(); ++i)
            ASSERT_NEAR(value(img.get(), i, j), transmitted, 0.02 * transmitted) << i << ", " << j;
}

TEST(RenderCaustics, FocusedOnTheLitWaterTheyKeepTheirSpacingWithFewerPhotons)
{
    // flat water over a bed at -2 m in a hole [-4, 4]^2 of a shore 1 m above the water, a floor at
    // -6 m under it all: light lands only in the hole, about 8 of the water's 20 metres
    const osg::Vec3 sun(0.3f, 0.2f, 0.93f);
    osg::Vec3 L = sun;
    L.normalize();
    const double expected = flatIrradiance(L.z(), 2.0);
    int grid[2] = { 0, 0 };
    double area[2] = { 0, 0 };
    for (bool focused : { false, true }) {
        CausticsScene sc(20.0f, 64, 128, sun, -2.0f);
        REQUIRE_GL(sc.h);
        sc.water->removeChildren(0, sc.water->getNumChildren());
        const osg::Vec4 white(1, 1, 1, 1);
        auto quad = [&](float x0, float y0, float x1, float y1, float z) {
            sc.water->addChild(emissiveQuad(osg::Vec3(x0, y0, z), osg::Vec3(x1, y0, z), osg::Vec3(x1, y1, z),
                                            osg::Vec3(x0, y1, z), white));
        };
        quad(-4, -4, 4, 4, -2);
        quad(-12, -12, -4, 12, 1);
        quad(4, -12, 12, 12, 1);
        quad(-4, -12, 4, -4, 1);
        quad(-4, 4, 4, 12, 1);
        quad(-12, -12, 12, 12, -6);
        sc.water->getSettings()->setCausticsFocused(focused);
        osg::ref_ptr<osg::Image> img = sc.render();
        ASSERT_TRUE(img.valid()) << "no caustics pass ran";
        grid[focused] = osgWater::internals(*sc.water).getCausticsCamera()->getGridSize();
        area[focused] = sc.texelArea(img.get());
        double sum = 0, lo = 1e30, hi = -1e30;
        int n = 0;
        for (int j = 0; j < img->t(); ++j)
            for (int i = 0; i < img->s(); ++i) {
                const osg::Vec3d p = sc.bedPoint(img.get(), i, j);
                if (std::fabs(p.x()) > 3 || std::fabs(p.y()) > 3) continue; // the bed, off its edges
                const double c = value(img.get(), i, j);
                sum += c;
                lo = std::min(lo, c);
                hi = std::max(hi, c);
                ++n;
            }
        ASSERT_GT(n, 50) << "focused " << focused;
        EXPECT_NEAR(sum / n, expected, 0.02 * expected) << "focused " << focused;
        EXPECT_LE(hi - lo, 0.02 * expected) << "focused " << focused << ": min " << lo << " max " << hi;
    }
    EXPECT_LE(grid[1], 0.6 * grid[0]) << "photons only where light can land: " << grid[1] << " against " << grid[0];
    EXPECT_NEAR(area[1], area[0], 0.25 * area[0]) << "the texel's size on the bed is kept";
}

TEST_P(RenderCausticsMethod, SupersampledTheGatherKeepsTheIrradianceAndTheGpuPathsTheirMirror)
{
    // flat water: the four shifted quarter-energy passes give the same uniform irradiance
    const osg::Vec3 sun(0.3f, 0.2f, 0.93f);
    osg::Vec3 L = sun;
    L.normalize();
    const double expected = flatIrradiance(L.z(), 2.0);
    {
        CausticsScene sc(20.0f, 64, 128, sun, -2.0f);
        REQUIRE_GL(sc.h);
        sc.water->getSettings()->setCausticsMethod(GetParam());
        sc.water->getSettings()->setCausticsSupersampling(true);
        osg::ref_ptr<osg::Image> img = sc.render();
        ASSERT_TRUE(img.valid());
        EXPECT_TRUE(osgWater::internals(*sc.water).getCausticsCamera()->getGather()->getSupersampled());
        double sum = 0, lo = 1e30, hi = -1e30;
        int n = 0;
        for (int j = 0; j < img->t(); ++j)
            for (int i = 0; i < img->s(); ++i) {
                const osg::Vec3d p = sc.bedPoint(img.get(), i, j);
                if (std::fabs(p.x()) > 7 || std::fabs(p.y()) > 7) continue;
                const double c = value(img.get(), i, j);
                sum += c;
                lo = std::min(lo, c);
                hi = std::max(hi, c);
                ++n;
            }
        ASSERT_GT(n, 500);
        EXPECT_NEAR(sum / n, expected, 0.02 * expected);
        EXPECT_LE(hi - lo, 0.02 * expected);
    }
    // a lens: every GPU path's four passes against the CPU's (the mirror)
    const float size = 8.0f;
    CausticsScene sc(size, 64, 128, osg::Vec3(0.2f, 0.1f, 0.97f), -2.0f, bumpMesh(size, 120, 0.5f, 0.5f, 0.25f, 0.5f));
    REQUIRE_GL(sc.h);
    sc.water->getSettings()->setCausticsMethod(GetParam());
    sc.water->getSettings()->setCausticsSupersampling(true);
    const osg::ref_ptr<osg::Image> ref = expectGatherPathsAgree(sc);
    ASSERT_TRUE(ref.valid());
    double refMax = 0;
    for (int j = 0; j < ref->t(); ++j)
        for (int i = 0; i < ref->s(); ++i) refMax = std::max(refMax, value(ref.get(), i, j));
    // and the four passes are not one: the single pass differs from them somewhere
    sc.water->getSettings()->setCausticsSupersampling(false);
    const osg::ref_ptr<osg::Image> single = sc.render();
    double differ = 0;
    for (int j = 0; j < single->t(); ++j)
        for (int i = 0; i < single->s(); ++i)
            differ = std::max(differ, std::fabs(value(single.get(), i, j) - value(ref.get(), i, j)));
    EXPECT_GT(differ, 0.02 * refMax);
}

TEST_P(RenderCausticsMethod, LensBumpFocusesAtTheAnalyticFocusAndConservesEnergy)
{
    // Paraxial focus of a refracting surface of apex curvature radius r = s^2 / h0 (air -> water):
    // f = n2 r / (n2 - n1) below the apex; an overhead sun focuses on the bump's axis there.
    const float size = 8.0f, x0 = 1.0f, y0 = -0.5f, h0 = 0.25f, s = 0.5f;
    const double r = s * s / h0, f = 1.333 * r / 0.333;
    const float bed = float(h0 - f);
    CausticsScene sc(size, 128, 256, osg::Vec3(0, 0, 1), bed, bumpMesh(size, 200, x0, y0, h0, s));
    REQUIRE_GL(sc.h);
    sc.water->getSettings()->setCausticsMethod(GetParam());
    osg::ref_ptr<osg::Image> img = sc.render();
    ASSERT_TRUE(img.valid());
    int bi = 0, bj = 0;
    double peak = -1, total = 0;
    for (int j = 0; j < img->t(); ++j)
        for (int i = 0; i < img->s(); ++i) {
            const double c = value(img.get(), i, j);
            total += c;
            if (c > peak) { peak = c; bi = i; bj = j; }
        }
    const osg::Vec3d p = sc.bedPoint(img.get(), bi, bj);
    const double texel = size / img->s();
    EXPECT_LE(std::fabs(p.x() - x0), texel) << "peak at " << p;
    EXPECT_LE(std::fabs(p.y() - y0), texel) << "peak at " << p;
    EXPECT_GT(peak, 3.0 * flatIrradiance(1.0, -bed)) << "no focus";

    // energy: the photons' analytic transmitted, attenuated power over the water, on a fine grid
    double expected = 0;
    const int m = 800;
    const double cell = size / m;
    for (int j = 0; j < m; ++j)
        for (int i = 0; i < m; ++i) {
            const double x = -size / 2 + (i + 0.5) * cell, y = -size / 2 + (j + 0.5) * cell;
            const double dx = x - x0, dy = y - y0, hgt = h0 * std::exp(-(dx * dx + dy * dy) / (2 * s * s));
            const glm::vec3 N = glm::normalize(glm::vec3(hgt * dx / (s * s), hgt * dy / (s * s), 1.0));
            const glm::vec3 T = optics::refract(glm::vec3(0, 0, -1), N, 1.0f / 1.333f);
            const float F = optics::fresnelSchlick(N.z, optics::normalReflectance(1.0f, 1.333f), 5.0f);
            const double d = (hgt - bed) / -T.z;
            expected += (1.0 - F) * std::exp(-kK * d) * cell * cell;
        }
    const double gathered = total * sc.texelArea(img.get());
    EXPECT_NEAR(gathered, expected, 0.02 * expected);
}

// Under the wind's waves (the cascades' texture, read by the photons or the area-ratio mesh) the
// bed gathers the sun's transmitted, attenuated power over the water, computed on the CPU from the
// height query's surface on a 1 cm grid (tolerance 3%: the photons' 3 cm spacing against the 6 cm
// ripples, and the light refracted past the water's edge; measured 0.99 and 1.01 of it), and the
// waves focus it into a pattern (the texels' spread over their mean: 0.63 and 1.84 measured, 0.02
// and 0.003 with the slopes left out).
TEST_P(RenderCausticsMethod, UnderTheWindsWavesTheyConserveEnergyAndFocus)
{
    const float size = 8.0f, bed = -2.0f;
    CausticsScene sc(size, 128, 256, osg::Vec3(0, 0, 1), bed);
    REQUIRE_GL(sc.h);
    WaterSurface* surface = sc.water->getSurface();
    WindWaves breeze; // 5 m/s over the lake's 140 m, on an 8 m square of it
    breeze.fetch = 140.0f;
    surface->setWind(breeze);
    surface->setWaveModel(WaterSurface::WAVES_WIND);
    sc.water->getSettings()->setCausticsMethod(GetParam());
    osg::ref_ptr<osg::Image> img = sc.render(); // at t = 1
    ASSERT_TRUE(img.valid());
    double total = 0.0, total2 = 0.0;
    for (int j = 0; j < img->t(); ++j)
        for (int i = 0; i < img->s(); ++i) {
            total += value(img.get(), i, j);
            total2 += value(img.get(), i, j) * value(img.get(), i, j);
        }
    double expected = 0.0;
    const int m = 800;
    const double cell = size / m;
    const float f0 = optics::normalReflectance(1.0f, 1.333f);
    for (int j = 0; j < m; ++j)
        for (int i = 0; i < m; ++i) {
            const double x = -size / 2 + (i + 0.5) * cell, y = -size / 2 + (j + 0.5) * cell;
            const osg::Vec3d n = surface->normal(x, y, 1.0);
            const glm::vec3 N(float(n.x()), float(n.y()), float(n.z()));
            const glm::vec3 T = optics::refract(glm::vec3(0, 0, -1), N, 1.0f / 1.333f);
            const float F = optics::fresnelSchlick(N.z, f0, 5.0f);
            const double d = (surface->height(x, y, 1.0) - bed) / -T.z;
            expected += (1.0 - F) * std::exp(-kK * d) * cell * cell;
        }
    RecordProperty("gathered_over_expected", std::to_string(total * sc.texelArea(img.get()) / expected));
    EXPECT_NEAR(total * sc.texelArea(img.get()), expected, 0.03 * expected);
    // a pattern, not the flat water's even light: the texels' spread over their mean
    const double n = double(img->s()) * img->t(), mean = total / n;
    const double spread = std::sqrt(std::max(total2 / n - mean * mean, 0.0)) / mean;
    RecordProperty("contrast", std::to_string(spread));
    EXPECT_GT(spread, 0.1);
}

TEST_P(RenderCausticsMethod, TheThreeGatherPathsAgree)
{
    const float size = 8.0f;
    CausticsScene sc(size, 64, 128, osg::Vec3(0.2f, 0.1f, 0.97f), -2.0f, bumpMesh(size, 120, 0.5f, 0.5f, 0.25f, 0.5f));
    REQUIRE_GL(sc.h);
    sc.water->getSettings()->setCausticsMethod(GetParam());
    expectGatherPathsAgree(sc);
}

TEST_P(RenderCausticsMethod, WithoutFloatTargetsTheCpuFallbackGivesTheSameCaustics)
{
    const float size = 8.0f;
    osg::ref_ptr<osg::Image> imgs[2];
    for (int pass = 0; pass < 2; ++pass) {
        if (pass == 1) setenv("OSGWATER_NO_FLOAT_TARGETS", "1", 1);
        CausticsScene sc(size, 64, 128, osg::Vec3(0, 0, 1), -2.0f, bumpMesh(size, 120, 0.0f, 0.0f, 0.25f, 0.5f));
        if (!sc.h.ok()) unsetenv("OSGWATER_NO_FLOAT_TARGETS");
        REQUIRE_GL(sc.h);
        sc.water->getSettings()->setCausticsMethod(GetParam());
        imgs[pass] = sc.render();
        unsetenv("OSGWATER_NO_FLOAT_TARGETS");
        ASSERT_TRUE(imgs[pass].valid());
        EXPECT_EQ(osgWater::internals(*sc.water).getCausticsCamera()->hasFloatTargets(), pass == 0);
        if (pass == 1) {
            EXPECT_EQ(sc.water->getActiveCausticsGather(), WaterSettings::GATHER_CPU);
            const float scale = osgWater::internals(*sc.water).getCausticsCamera()->getGather()->getValueScale();
            double worst = 0, top = 0;
            for (int j = 0; j < 64; ++j)
                for (int i = 0; i < 64; ++i) {
                    top = std::max(top, value(imgs[0].get(), i, j));
                    worst = std::max(worst, std::fabs(scale * value(imgs[1].get(), i, j) - value(imgs[0].get(), i, j)));
                }
            EXPECT_LE(worst, 0.02 * top);
        }
    }
}

TEST_P(RenderCausticsMethod, NoNaNOrInfAtAnySunElevation)
{
    for (double elevation : { 90.0, 45.0, 1.0, 1e-3, 0.0, -10.0 }) {
        const double e = osg::DegreesToRadians(elevation);
        const osg::Vec3 sun(0.0f, float(std::cos(e)), float(std::sin(e)));
        CausticsScene sc(20.0f, 64, 128, sun, -2.0f);
        REQUIRE_GL(sc.h);
        sc.water->getSettings()->setCausticsMethod(GetParam());
        sc.water->getSettings()->setRefractionEnabled(true);
        sc.water->getSettings()->setReflectiveCaustics(true); // with a post standing in the water
        sc.water->addChild(litQuad(-1, -1, 1, 1, 2.0f));
        sc.water->getSurface()->setWaves({ Wave() });
        sc.h.frame(1e7);
        CausticsCamera* c = osgWater::internals(*sc.water).getCausticsCamera();
        if (CausticsCamera* r = osgWater::internals(*sc.water).getReflectedCausticsCamera()) {
            EXPECT_TRUE(allFinite(sc.h.readTexture(r->getCausticsTexture()).get())) << elevation;
            EXPECT_TRUE(allFinite(sc.h.readTexture(r->getPhotonTexture()).get())) << elevation;
        } else {
            EXPECT_LE(elevation, 0.0) << "no reflective caustics with the sun at " << elevation << " deg";
        }
        if (elevation <= 0.0) {
            EXPECT_EQ(c, nullptr) << "caustics rendered with the sun at " << elevation << " deg";
        } else {
            ASSERT_NE(c, nullptr) << elevation;
            EXPECT_TRUE(allFinite(sc.h.readTexture(c->getCausticsTexture()).get())) << elevation;
            EXPECT_TRUE(allFinite(sc.h.readTexture(c->getPhotonTexture()).get())) << elevation;
            EXPECT_TRUE(allFinite(sc.h.readTexture(c->getDepthTexture()).get())) << elevation;
            EXPECT_TRUE(allFinite(sc.h.readTexture(c->getShadeTexture()).get())) << elevation;
        }
        EXPECT_TRUE(allFinite(sc.h.readColor().get())) << elevation;
    }
}

TEST(RenderCaustics, TheBedIsLitByTheCausticsAndShadowedByUnderwaterObjects)
{
    // sun 30 degrees from the zenith; a lit bed at -2 m and a lit slab at -1 m over x in [2, 4]
    const osg::Vec3 sun(0.5f, 0.0f, 0.8660254f);
    CausticsScene sc(20.0f, 64, 128, sun, -2.0f);
    REQUIRE_GL(sc.h);
    sc.lightTheBed(20.0f);
    sc.water->addChild(litQuad(2, -1, 4, 1, -1.0f));
    WaterSettings* s = sc.water->getSettings();
    auto bedColour = [&](const osg::Vec3d& p) { return double(sc.refracted(p).x()); };
    const double ndl = sun.z();
    // lit bed: n.L times the caustic irradiance C of flat water
    EXPECT_NEAR(bedColour(osg::Vec3d(-3, 0, -2)), ndl * flatIrradiance(ndl, 2.0), 0.01);
    // the slab's shadow along the sun (x in [1.42, 3.42] on the bed; the part left of the slab
    // is what the eye sees)
    EXPECT_NEAR(bedColour(osg::Vec3d(1.8, 0, -2)), 0.0, 0.01);
    // caustics off: the full sun, no shadow
    s->setCausticsEnabled(false);
    EXPECT_NEAR(bedColour(osg::Vec3d(-3, 0, -2)), ndl, 0.01);
    EXPECT_NEAR(bedColour(osg::Vec3d(1.8, 0, -2)), ndl, 0.01);
}

TEST(RenderCaustics, TheSunReflectedOffFlatWaterLightsAWallAboveItByTheReflectedShareF)
{
    // the sun 20 degrees above the horizon towards +x; a white wall at x = -3 facing +x, standing
    // on the water: the direct sun gives it n.L = cos 20 deg, the sun's mirror image under flat
    // water as much again times the reflected share F at the sun's incidence (the settings' model); a sun
    // of half strength keeps the sum below white, in linear light, shown encoded
    const double e = osg::DegreesToRadians(20.0);
    const osg::Vec3 sun(float(std::cos(e)), 0.0f, float(std::sin(e)));
    CausticsScene sc(20.0f, 64, 128, sun, -2.0f);
    REQUIRE_GL(sc.h);
    osg::Geode* wall = litQuad(0, 0, 0, 0, 0); // a white diffuse material on a wall of its own
    wall->removeDrawables(0, wall->getNumDrawables());
    wall->addDrawable(emissiveQuad(osg::Vec3(-3, -3, 0.2f), osg::Vec3(-3, 3, 0.2f), osg::Vec3(-3, 3, 3),
                                   osg::Vec3(-3, -3, 3), osg::Vec4(1, 1, 1, 1))->getDrawable(0));
    sc.water->addChild(wall);
    WaterSettings* s = sc.water->getSettings();
    s->setAmbientColor(osg::Vec3(0, 0, 0));
    const float sunLight = 0.5f;
    s->setSunColor(osg::Vec3(sunLight, sunLight, sunLight));
    s->setGlowEnabled(false);
    s->setReflectiveCaustics(true);
    sc.h.lookAt(osg::Vec3d(5, 0, 1.6), osg::Vec3d(-3, 0, 1.6));
    auto wallColour = [&]() {
        sc.h.frame(1.0);
        osg::ref_ptr<osg::Image> img = sc.h.readColor();
        return double(pixel(img.get(), img->s() / 2, img->t() / 2)[0]);
    };
    const double F = optics::fresnelModel(s->getFresnelModel(), float(std::sin(e)), s->getAirIOR(), s->getWaterIOR(),
                                          s->getFresnelModelExponent());
    EXPECT_NEAR(wallColour(), optics::encodeSrgb(float(sunLight * std::cos(e) * (1.0 + F))), 0.01) << "F " << F;
    CausticsCamera* r = osgWater::internals(*sc.water).getReflectedCausticsCamera();
    ASSERT_NE(r, nullptr);
    EXPECT_TRUE(r->isReflected());
    // the reflective caustics texture: F where the reflected light lands (on the mirrored wall)
    osg::ref_ptr<osg::Image> img = sc.h.readTexture(r->getCausticsTexture());
    double top = 0;
    for (int j = 0; j < img->t(); ++j)
        for (int i = 0; i < img->s(); ++i) top = std::max(top, value(img.get(), i, j));
    EXPECT_NEAR(top, F, 0.02 * F);
    EXPECT_TRUE(allFinite(img.get()));
    s->setReflectiveCaustics(false);
    EXPECT_NEAR(wallColour(), optics::encodeSrgb(float(sunLight * std::cos(e))), 0.01) << "off: the direct sun alone";
    EXPECT_EQ(osgWater::internals(*sc.water).getReflectedCausticsCamera(), nullptr);
}

TEST_P(RenderCausticsMethod, TiledTheCausticsOfOneTileRepeatWhatTheWholeWaterGives)
{
    // flat water: the tile holds the transmitted share 1 - F everywhere, edges included (they
    // wrap); the bed under it receives that faded by its own depth: the analytic irradiance
    const osg::Vec3 sun(0.3f, 0.2f, 0.93f);
    osg::Vec3 L = sun;
    L.normalize();
    const double transmitted = 1.0 - optics::fresnelSchlick(L.z(), optics::normalReflectance(1.0f, 1.333f), 5.0f);
    const double fade = flatIrradiance(L.z(), 2.0) / transmitted; // over the 2 m the sun's path takes
    {
        CausticsScene sc(20.0f, 32, 128, sun, -2.0f);
        REQUIRE_GL(sc.h);
        sc.water->getSettings()->setCausticsMethod(GetParam());
        sc.water->getSettings()->setCausticsTileSize(4.0f);
        osg::ref_ptr<osg::Image> img = sc.render();
        ASSERT_TRUE(img.valid());
        EXPECT_TRUE(osgWater::internals(*sc.water).getCausticsCamera()->getLighting().tiled);
        for (int j = 0; j < img->t(); ++j)
            for (int i = 0; i < img->s(); ++i)
                ASSERT_NEAR(value(img.get(), i, j), transmitted, 0.02 * transmitted) << i << ", " << j;
        sc.lightTheBed(20.0f);
        const double ndl = L.z();
        for (const osg::Vec3d p : { osg::Vec3d(-3, 1, -2), osg::Vec3d(2.5, -1.5, -2) })
            EXPECT_NEAR(sc.refracted(p).x(), ndl * flatIrradiance(ndl, 2.0), 0.01) << p;
    }
    // waves that repeat over the 4 m tile (two cycles along x, one along y): the tile's caustics,
    // wrapped and faded by the bed's depth, against the whole water's at the same bed points
    // (blocks of 2 x 2 texels, 0.25 m)
    const float size = 8.0f, tile = 4.0f;
    std::vector<Wave> waves = { makeWave(1, 0, 2.0f, 0.02f), makeWave(0, 1, 4.0f, 0.03f) };
    osg::ref_ptr<osg::Image> whole, tiled;
    osg::Matrixd wholeToSun, localToTile;
    for (bool tiling : { false, true }) {
        CausticsScene sc(size, tiling ? 32 : 64, tiling ? 128 : 256, sun, -2.0f);
        REQUIRE_GL(sc.h);
        sc.water->getSurface()->setWaves(waves);
        sc.water->getSettings()->setCausticsMethod(GetParam());
        sc.water->getSettings()->setCausticsFocused(false);
        sc.water->getSettings()->setCausticsTileSize(tiling ? tile : 0.0f);
        (tiling ? tiled : whole) = sc.render();
        ASSERT_TRUE((tiling ? tiled : whole).valid());
        const CausticsLighting& l = osgWater::internals(*sc.water).getCausticsCamera()->getLighting();
        (tiling ? localToTile : wholeToSun) = tiling ? l.localToTile : l.localToSun;
    }
    const osg::Matrixd tileToLocal = osg::Matrixd::inverse(localToTile);
    double sum = 0, worst = 0;
    int blocks = 0;
    for (int bj = 0; bj < tiled->t(); bj += 2)
        for (int bi = 0; bi < tiled->s(); bi += 2) {
            double t = 0, w = 0;
            for (int j = bj; j < bj + 2; ++j)
                for (int i = bi; i < bi + 2; ++i) {
                    t += fade * value(tiled.get(), i, j) / 4;
                    // the bed point under this tile texel, in the whole water's texture
                    const osg::Vec3d p = osg::Vec3d((i + 0.5) / tiled->s(), (j + 0.5) / tiled->t(), 0.0) * tileToLocal;
                    const osg::Vec3d q = osg::Vec3d(p.x(), p.y(), -2.0) * wholeToSun;
                    w += value(whole.get(), int(q.x() * whole->s()), int(q.y() * whole->t())) / 4;
                }
            sum += w;
            worst = std::max(worst, std::fabs(t - w));
            ++blocks;
        }
    // the worst of the 256 blocks; measured: 5.0% (photons), 4.2% (area mesh)
    EXPECT_LE(worst, 0.06 * sum / blocks) << "mean " << sum / blocks;
}

TEST(RenderCaustics, TiledOverWavesThatDoNotRepeatOverTheTileItSaysSo)
{
    CausticsScene sc(20.0f, 32, 128, osg::Vec3(0, 0, 1), -2.0f);
    REQUIRE_GL(sc.h);
    sc.water->getSurface()->setWaves({ makeWave(1, 0, 1.7f, 0.02f) });
    sc.water->getSettings()->setCausticsTileSize(4.0f);
    ScopedWarnCapture capture;
    sc.render();
    sc.render();
    const std::string said = capture.str();
    EXPECT_NE(said.find("do not repeat over the caustics tile"), std::string::npos) << said;
    EXPECT_EQ(said.find("do not repeat"), said.rfind("do not repeat")) << "said once";
}

TEST(RenderCaustics, UnderAPerChannelWaterEachChannelOfTheSunFadesByItsOwnExtinction)
{
    // the photons carry one energy; the bed's red and blue must still fade by their own sun
    // extinction K = a + b_b over the refracted path (clear lake: red far faster than green)
    const osg::Vec3 sun(0.5f, 0.0f, 0.8660254f);
    CausticsScene sc(20.0f, 64, 128, sun, -3.0f);
    REQUIRE_GL(sc.h);
    sc.lightTheBed(20.0f);
    applyWaterType(*sc.water->getSettings(), *findWaterType("clear-lake"));
    const osg::Vec3 c = sc.refracted(osg::Vec3d(-3, 0, -3));
    const WaterOptics& o = findWaterType("clear-lake")->optics;
    const double ndl = sun.z();
    for (int i = 0; i < 3; ++i) {
        const double K = o.absorption[i] + o.backscattering[i];
        EXPECT_NEAR(c[i], ndl * flatIrradiance(ndl, 3.0, K), 0.01) << "channel " << i;
    }
    EXPECT_LT(c[0], 0.5 * c[1]) << "red fades first";
}

TEST(RenderCaustics, SunDepthMapIsRedrawnOnlyWhenTheSunMoves)
{
    CausticsScene sc(20.0f, 64, 128, osg::Vec3(0.3f, 0.2f, 0.93f), -2.0f);
    REQUIRE_GL(sc.h);
    sc.h.frame(1.0);
    ASSERT_NE(osgWater::internals(*sc.water).getCausticsCamera(), nullptr);
    EXPECT_TRUE(osgWater::internals(*sc.water).getCausticsCamera()->getDepthDrawn());
    sc.h.frame(2.0); // waves move, the sun does not: the underwater scene's depth is unchanged
    EXPECT_FALSE(osgWater::internals(*sc.water).getCausticsCamera()->getDepthDrawn());
    sc.water->getSettings()->setSunDirection(osg::Vec3(0.1f, 0.2f, 0.95f));
    sc.h.frame(3.0);
    EXPECT_TRUE(osgWater::internals(*sc.water).getCausticsCamera()->getDepthDrawn());
    osgWater::internals(*sc.water).getCausticsCamera()->dirtyDepth();
    sc.h.frame(4.0);
    EXPECT_TRUE(osgWater::internals(*sc.water).getCausticsCamera()->getDepthDrawn());
    sc.h.frame(5.0);
    EXPECT_FALSE(osgWater::internals(*sc.water).getCausticsCamera()->getDepthDrawn());
}

TEST(RenderCaustics, AutoGatherTimesEveryPathThenKeepsOne)
{
    CausticsScene sc(20.0f, 64, 128, osg::Vec3(0.3f, 0.2f, 0.93f), -2.0f);
    REQUIRE_GL(sc.h);
    std::set<int> seen;
    for (int i = 0; i < 40; ++i) {
        sc.h.frame(1.0 + i / 60.0);
        seen.insert(int(sc.water->getActiveCausticsGather()));
    }
    EXPECT_EQ(seen.size(), 3u) << "not every gather was tried";
    const WaterSettings::CausticsGather kept = sc.water->getActiveCausticsGather();
    for (int i = 0; i < 10; ++i) {
        sc.h.frame(2.0 + i / 60.0);
        EXPECT_EQ(sc.water->getActiveCausticsGather(), kept);
    }
}
