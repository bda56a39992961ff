// osgDB wrappers: .osgt against an expected text, exact .osgt/.osgb round trips, and bad files.
#include "serialize/LayoutVersion.h"
#include <osgWater/Sky>
#include <osgWater/WaterNode>
#include <osgDB/ReadFile>
#include <osgDB/Registry>
#include <osgDB/WriteFile>
#include <osg/Notify>
#include "WarnCapture.h"
#include <gtest/gtest.h>
#include <cmath>
#include <algorithm>
#include <fstream>
#include <functional>
#include <random>
#include <tuple>
#include <sstream>

using namespace osgWater;

namespace {

std::string slurp(const std::string& path)
{
    std::ifstream in(path.c_str(), std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

void spit(const std::string& path, const std::string& text)
{
    std::ofstream out(path.c_str(), std::ios::binary);
    out << text;
}

std::string tmp(const std::string& name) { return std::string(OSGWATER_TEST_TMP) + "/" + name; }

// the non-default node of tests/data/waternode_expected.osgt
osg::ref_ptr<WaterNode> pond()
{
    osg::ref_ptr<WaterNode> w = new WaterNode;
    w->setName("pond");
    WaterSettings* s = w->getSettings();
    s->setWaterIOR(1.34f);
    s->setWaterColor(osg::Vec3(0.1f, 0.3f, 0.2f));
    s->setAttenuation(0.25f);
    s->setFresnelModel(WaterSettings::FRESNEL_RECIPROCAL);
    s->setFresnelReciprocalPower(7.5f);
    s->setRefractionLookup(WaterSettings::BRACKETED);
    s->setSearchSteps(5);
    s->setFovExtensionNear(1.4f);
    s->setReflectionTextureSize(256);
    s->setRefractionCameraRotation(false);
    s->setRefractionCameraApparentEye(false);
    s->setReflectionEnabled(false);
    s->setPhotonGridSize(128);
    s->setCausticsFocused(false);
    s->setCausticsGather(WaterSettings::GATHER_CPU);
    s->setCausticsMethod(WaterSettings::CAUSTICS_AREA_MESH);
    s->setCausticsSupersampling(true);
    s->setReflectiveCaustics(true);
    s->setCausticsTileSize(12.5f);
    s->setEnvironmentMapEnabled(true);
    s->setEnvironmentMapSize(128);
    s->setUnderwaterModel(WaterSettings::UNDERWATER_THESIS);
    s->setGlowEnabled(false);
    s->setGlowRadius(5.0f);
    s->setExposure(1.5f);
    WaterSurface* f = w->getSurface();
    f->setLevel(1.5);
    f->setSize(60.0f);
    f->setResolution(33);
    f->setMeshLayout(WaterSurface::MESH_GRID);
    Wave wave;
    wave.direction.set(0.6f, 0.8f);
    wave.wavelength = 5.0f;
    wave.amplitude = 0.04f;
    wave.phase = 0.5f;
    f->setWaves({ wave });
    return w;
}


osg::ref_ptr<WaterNode> readWater(const std::string& path)
{
    osg::ref_ptr<osg::Node> n = osgDB::readRefNodeFile(path);
    return dynamic_cast<WaterNode*>(n.get());
}

}

TEST(Serialization, OsgtMatchesTheExpectedText)
{
    ASSERT_TRUE(osgDB::writeNodeFile(*pond(), tmp("pond.osgt")));
    EXPECT_EQ(slurp(tmp("pond.osgt")), slurp(std::string(OSGWATER_TEST_DATA) + "/waternode_expected.osgt"));
}

TEST(Serialization, ExpectedTextReadsBackIntoTheSameNode)
{
    osg::ref_ptr<WaterNode> w = readWater(std::string(OSGWATER_TEST_DATA) + "/waternode_expected.osgt");
    ASSERT_TRUE(w.valid());
    const WaterSettings* s = w->getSettings();
    EXPECT_EQ(w->getName(), "pond");
    EXPECT_FLOAT_EQ(s->getWaterIOR(), 1.34f);
    EXPECT_EQ(s->getWaterColor(), osg::Vec3(0.1f, 0.3f, 0.2f));
    EXPECT_FLOAT_EQ(s->getAttenuation(), 0.25f);
    EXPECT_EQ(s->getFresnelModel(), WaterSettings::FRESNEL_RECIPROCAL);
    EXPECT_FLOAT_EQ(s->getFresnelReciprocalPower(), 7.5f);
    EXPECT_FLOAT_EQ(s->getFresnelExponent(), 5.0f); // absent: default
    EXPECT_EQ(s->getRefractionLookup(), WaterSettings::BRACKETED);
    EXPECT_EQ(s->getSearchSteps(), 5);
    EXPECT_FLOAT_EQ(s->getFovExtensionNear(), 1.4f);
    EXPECT_EQ(s->getReflectionTextureSize(), 256);
    EXPECT_EQ(s->getRefractionTextureSize(), 512); // absent: default
    EXPECT_FALSE(s->getRefractionCameraRotation());
    EXPECT_FALSE(s->getRefractionCameraApparentEye());
    EXPECT_FALSE(s->getReflectionEnabled());
    EXPECT_TRUE(s->getRefractionEnabled());
    EXPECT_EQ(s->getPhotonGridSize(), 128);
    EXPECT_FALSE(s->getCausticsFocused());
    EXPECT_EQ(s->getCausticsGather(), WaterSettings::GATHER_CPU);
    EXPECT_EQ(s->getCausticsMethod(), WaterSettings::CAUSTICS_AREA_MESH);
    EXPECT_TRUE(s->getCausticsSupersampling());
    EXPECT_TRUE(s->getReflectiveCaustics());
    EXPECT_FLOAT_EQ(s->getCausticsTileSize(), 12.5f);
    EXPECT_TRUE(s->getEnvironmentMapEnabled());
    EXPECT_EQ(s->getEnvironmentMapSize(), 128);
    EXPECT_EQ(s->getCausticsResolution(), 256); // absent: default
    EXPECT_EQ(s->getUnderwaterModel(), WaterSettings::UNDERWATER_THESIS);
    EXPECT_FALSE(s->getGlowEnabled());
    EXPECT_FLOAT_EQ(s->getGlowRadius(), 5.0f);
    EXPECT_FLOAT_EQ(s->getGlowResolution(), 0.25f); // absent: default
    EXPECT_FLOAT_EQ(s->getExposure(), 1.5f);
    EXPECT_EQ(s->getToneCurve(), WaterSettings::TONE_CLIP);
    const WaterSurface* f = w->getSurface();
    EXPECT_DOUBLE_EQ(f->getLevel(), 1.5);
    EXPECT_FLOAT_EQ(f->getSize(), 60.0f);
    EXPECT_EQ(f->getResolution(), 33u);
    EXPECT_EQ(f->getMeshLayout(), WaterSurface::MESH_GRID);
    ASSERT_EQ(f->getWaves().size(), 1u);
    EXPECT_NEAR(f->getWaves()[0].direction.x(), 0.6f, 1e-6f);
    EXPECT_FLOAT_EQ(f->getWaves()[0].wavelength, 5.0f);
    EXPECT_FLOAT_EQ(f->getWaves()[0].amplitude, 0.04f);
    // the grid is rebuilt from the parameters, never stored
    EXPECT_EQ(f->getGeometry()->getVertexArray()->getNumElements(), 33u * 33u);
}

TEST(Serialization, OsgtAndOsgbRoundTripExactly)
{
    for (const char* ext : { "osgt", "osgb" }) {
        const std::string a = tmp(std::string("rt_a.") + ext), b = tmp(std::string("rt_b.") + ext);
        osg::ref_ptr<WaterNode> written = pond();
        written->getSettings()->setToneCurve(WaterSettings::TONE_ACES); // not the default: it must be read
        ASSERT_TRUE(osgDB::writeNodeFile(*written, a));
        osg::ref_ptr<WaterNode> w = readWater(a);
        ASSERT_TRUE(w.valid()) << ext;
        ASSERT_TRUE(osgDB::writeNodeFile(*w, b));
        EXPECT_EQ(slurp(a), slurp(b)) << ext;
        EXPECT_EQ(w->getSettings()->getFresnelModel(), WaterSettings::FRESNEL_RECIPROCAL) << ext;
        EXPECT_EQ(w->getSettings()->getToneCurve(), WaterSettings::TONE_ACES) << ext;
        EXPECT_EQ(w->getSurface()->getWaves().size(), 1u) << ext;
    }
}

// OSG writes text numbers with six digits: a 1234.5678901 m level came back as 1234.57, and a value a
// hair from its default was written, read back as the default and dropped (found by the fuzz target)
TEST(Serialization, OsgtKeepsEveryBitOfEveryNumber)
{
    osg::ref_ptr<WaterNode> w = pond();
    WaterSettings* s = w->getSettings();
    s->setAirIOR(std::nextafter(1.0f, 2.0f));
    s->setWaterIOR(1.3330001f);
    s->setSunDirection(osg::Vec3(0.123456789f, -0.3f, 0.7f));
    s->setWaterColor(osg::Vec3(0.1f / 3.0f, 0.2f / 3.0f, 0.7f / 3.0f));
    WaterSurface* f = w->getSurface();
    f->setLevel(1234.5678901234567);
    f->setCenter(osg::Vec2(1.0f / 3.0f, -2.0f / 7.0f));
    Wave wave = f->getWaves()[0];
    wave.phase = 0.123456789f;
    wave.amplitude = 0.04f / 3.0f;
    f->setWaves({ wave });
    ASSERT_TRUE(osgDB::writeNodeFile(*w, tmp("bits.osgt")));
    osg::ref_ptr<WaterNode> back = readWater(tmp("bits.osgt"));
    ASSERT_TRUE(back.valid());
    const WaterSettings* t = back->getSettings();
    EXPECT_EQ(t->getAirIOR(), s->getAirIOR());
    EXPECT_EQ(t->getWaterIOR(), s->getWaterIOR());
    EXPECT_EQ(t->getSunDirection(), s->getSunDirection());
    EXPECT_EQ(t->getWaterColor(), s->getWaterColor());
    const WaterSurface* g = back->getSurface();
    EXPECT_EQ(g->getLevel(), f->getLevel());
    EXPECT_EQ(g->getCenter(), f->getCenter());
    ASSERT_EQ(g->getWaves().size(), 1u);
    EXPECT_EQ(g->getWaves()[0].phase, wave.phase);
    EXPECT_EQ(g->getWaves()[0].amplitude, wave.amplitude);
    // and the file stays readable: the common values keep their short form
    const std::string text = slurp(tmp("bits.osgt"));
    EXPECT_NE(text.find("WaterIOR 1.3330001 "), std::string::npos);
    EXPECT_NE(text.find("Resolution 33 "), std::string::npos);
    EXPECT_NE(text.find("Size 60 "), std::string::npos);
}

// OSG's own text parser misses the last bit of most doubles: levels are read exactly
TEST(Serialization, OsgtKeepsEveryLevelExactly)
{
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> mantissa(1.0, 10.0);
    int wrong = 0;
    for (double scale : { 1e-300, 1e-6, 1e-3, 1.0, 1e3, 1e6 })
        for (int i = 0; i < 20; ++i) {
            osg::ref_ptr<WaterNode> w = new WaterNode;
            const double level = (i % 2 ? -1.0 : 1.0) * mantissa(random) * scale;
            w->getSurface()->setLevel(level);
            std::ostringstream out;
            osg::ref_ptr<osgDB::Options> opts = new osgDB::Options;
            opts->setPluginStringData("fileType", "Ascii");
            osgDB::ReaderWriter* rw = osgDB::Registry::instance()->getReaderWriterForExtension("osgt");
            ASSERT_TRUE(rw->writeNode(*w, out, opts.get()).success());
            std::istringstream in(out.str());
            osg::ref_ptr<WaterNode> back = dynamic_cast<WaterNode*>(rw->readNode(in, nullptr).getNode());
            ASSERT_TRUE(back.valid());
            if (back->getSurface()->getLevel() != level) ++wrong;
        }
    EXPECT_EQ(wrong, 0) << "of 120 levels";
}

TEST(Serialization, MissingFieldsTakeDefaults)
{
    spit(tmp("minimal.osgt"), "#Ascii Scene\n#Version 161\n#Generator OpenSceneGraph 3.6.5\n\nosgWater::WaterNode {\n  UniqueID 1\n"
                              "  Settings TRUE {\n    osgWater::WaterSettings {\n      UniqueID 2\n      Attenuation 0.9\n    }\n  }\n}\n");
    osg::ref_ptr<WaterNode> w = readWater(tmp("minimal.osgt"));
    ASSERT_TRUE(w.valid());
    EXPECT_FLOAT_EQ(w->getSettings()->getAttenuation(), 0.9f);
    EXPECT_FLOAT_EQ(w->getSettings()->getFresnelExponent(), 5.0f);
    EXPECT_EQ(w->getSettings()->getRefractionLookup(), WaterSettings::ITERATIVE);
    ASSERT_TRUE(w->getSurface()); // no Surface in the file: the default grid
    EXPECT_EQ(w->getSurface()->getResolution(), 49u);
}

TEST(Serialization, OutOfRangeValuesAreClampedWithAWarning)
{
    // properties in the wrappers' order: osgDB reads them in that order
    spit(tmp("bad_values.osgt"),
         "#Ascii Scene\n#Version 161\n#Generator OpenSceneGraph 3.6.5\n\nosgWater::WaterNode {\n  UniqueID 1\n"
         "  Settings TRUE {\n    osgWater::WaterSettings {\n      UniqueID 2\n      WaterColor 2 0.5 -3\n      SearchSteps 99\n"
         "      ReflectionTextureSize -5\n      RefractionTextureSize 1000000000\n    }\n  }\n"
         "  Surface TRUE {\n    osgWater::WaterSurface {\n      UniqueID 3\n      Resolution 0\n    }\n  }\n}\n");
    ScopedWarnCapture warn;
    osg::ref_ptr<WaterNode> w = readWater(tmp("bad_values.osgt"));
    ASSERT_TRUE(w.valid());
    const WaterSettings* s = w->getSettings();
    EXPECT_EQ(s->getReflectionTextureSize(), 16);
    EXPECT_EQ(s->getRefractionTextureSize(), 4096);
    EXPECT_EQ(s->getSearchSteps(), 8);
    EXPECT_EQ(s->getWaterColor(), osg::Vec3(1.0f, 0.5f, 0.0f));
    EXPECT_EQ(w->getSurface()->getResolution(), 2u);
    EXPECT_NE(warn.str().find("reflectionTextureSize = -5"), std::string::npos);
    EXPECT_NE(warn.str().find("clamped"), std::string::npos);
}

TEST(Serialization, NaNColourIsReplacedWithAWarning)
{
    // a binary file carries a NaN exactly: patch the colour (0.1, 0.3, 0.2) of a written .osgb
    ASSERT_TRUE(osgDB::writeNodeFile(*pond(), tmp("nan.osgb")));
    std::string bin = slurp(tmp("nan.osgb"));
    const float colour[3] = { 0.1f, 0.3f, 0.2f };
    const size_t p = bin.find(std::string(reinterpret_cast<const char*>(colour), sizeof(colour)));
    ASSERT_NE(p, std::string::npos);
    const float nan = NAN;
    bin.replace(p, sizeof(float), std::string(reinterpret_cast<const char*>(&nan), sizeof(float)));
    spit(tmp("nan.osgb"), bin);
    ScopedWarnCapture warn;
    osg::ref_ptr<WaterNode> w = readWater(tmp("nan.osgb"));
    ASSERT_TRUE(w.valid());
    EXPECT_FLOAT_EQ(w->getSettings()->getWaterColor().x(), 0.0f); // the default's red
    EXPECT_FLOAT_EQ(w->getSettings()->getWaterColor().y(), 0.3f);
    EXPECT_NE(warn.str().find("NaN"), std::string::npos);
    // in text, "nan" is a parse error of osgDB's: it must not crash, and nothing non-finite gets in
    spit(tmp("nan.osgt"), "#Ascii Scene\n#Version 161\n#Generator OpenSceneGraph 3.6.5\n\nosgWater::WaterNode {\n  UniqueID 1\n"
                          "  Settings TRUE {\n    osgWater::WaterSettings {\n      UniqueID 2\n      WaterColor nan nan nan\n"
                          "      Attenuation nan\n    }\n  }\n}\n");
    osg::ref_ptr<WaterNode> t = readWater(tmp("nan.osgt"));
    if (t.valid()) {
        EXPECT_TRUE(t->getSettings()->getWaterColor().valid());
        EXPECT_TRUE(std::isfinite(t->getSettings()->getAttenuation()));
    }
}

TEST(Serialization, TruncatedAndGarbageFilesFailCleanly)
{
    ASSERT_TRUE(osgDB::writeNodeFile(*pond(), tmp("whole.osgt")));
    const std::string text = slurp(tmp("whole.osgt"));
    ScopedWarnCapture quiet; // osgDB reports the errors; they are expected here
    // truncated at many points: osgDB's error or a partial node, never a crash
    for (size_t cut = 1; cut < text.size(); cut += 37) {
        spit(tmp("cut.osgt"), text.substr(0, cut));
        osg::ref_ptr<osg::Node> n = osgDB::readRefNodeFile(tmp("cut.osgt"));
        if (WaterNode* w = dynamic_cast<WaterNode*>(n.get())) // a partial node: still sane values
            EXPECT_TRUE(w->getSettings()->getWaterColor().valid() && w->getSurface() != nullptr);
    }
    // (truncated .osgb is left out: osgDB 3.6's binary reader takes sizes and counts from failed
    // reads, i.e. from uninitialised memory, and can loop or allocate for minutes; upstream, not ours)
    std::string garbage;
    for (int i = 0; i < 4096; ++i) garbage += char((i * 7919 + 13) & 0xff);
    spit(tmp("garbage.osgt"), garbage);
    spit(tmp("garbage.osgb"), garbage);
    EXPECT_FALSE(osgDB::readRefNodeFile(tmp("garbage.osgt")).valid());
    EXPECT_FALSE(osgDB::readRefNodeFile(tmp("garbage.osgb")).valid());
    // a garbage wave count is refused, not allocated
    std::string huge = text;
    const size_t p = huge.find("Waves 1");
    ASSERT_NE(p, std::string::npos);
    huge.replace(p, 7, "Waves 4000000000");
    spit(tmp("huge.osgt"), huge);
    osg::ref_ptr<WaterNode> w = readWater(tmp("huge.osgt"));
    if (w.valid()) EXPECT_LE(w->getSurface()->getWaves().size(), WaterSurface::MAX_WAVES);
    EXPECT_FALSE(osgDB::readRefNodeFile(tmp("does_not_exist.osgt")).valid());
}

namespace {
// the settings a quality preset bundles, as one comparable tuple
std::tuple<int, int, float, int, int, int, int, float, float> speedSettings(const WaterSettings& s)
{
    return { s.getRefractionLookup(), s.getSearchSteps(), s.getPassTargetScale(), s.getReflectionTextureSize(),
             s.getRefractionTextureSize(), s.getCausticsResolution(), s.getPhotonGridSize(),
             s.getCausticsMotionTolerance(), s.getGlowResolution() };
}
}

TEST(Serialization, QualityPresetsRoundTrip)
{
    for (WaterSettings::Quality q : { WaterSettings::QUALITY_FAST, WaterSettings::QUALITY_BALANCED, WaterSettings::QUALITY_EXACT })
        for (const char* ext : { "osgt", "osgb" }) {
            osg::ref_ptr<WaterNode> w = new WaterNode;
            w->getSettings()->setQuality(q);
            ASSERT_EQ(w->getSettings()->getQuality(), q);
            const std::string file = tmp(std::string("quality.") + ext);
            ASSERT_TRUE(osgDB::writeNodeFile(*w, file));
            osg::ref_ptr<WaterNode> back = readWater(file);
            ASSERT_TRUE(back.valid());
            EXPECT_EQ(back->getSettings()->getQuality(), q) << WaterSettings::qualityName(q) << " " << ext;
            EXPECT_EQ(speedSettings(*back->getSettings()), speedSettings(*w->getSettings()));
            if (std::string(ext) == "osgt" && q != WaterSettings::QUALITY_BALANCED)
                EXPECT_NE(slurp(file).find(std::string("Quality ") + WaterSettings::qualityName(q)), std::string::npos);
        }
    // FAST with one setting put back to its default is a custom set: written field by field and read
    // back as it was, not as the preset
    osg::ref_ptr<WaterNode> w = new WaterNode;
    w->getSettings()->setQuality(WaterSettings::QUALITY_FAST);
    w->getSettings()->setCausticsMotionTolerance(0.5f);
    EXPECT_EQ(w->getSettings()->getQuality(), WaterSettings::QUALITY_CUSTOM);
    ASSERT_TRUE(osgDB::writeNodeFile(*w, tmp("custom.osgt")));
    EXPECT_EQ(slurp(tmp("custom.osgt")).find("Quality"), std::string::npos);
    osg::ref_ptr<WaterNode> back = readWater(tmp("custom.osgt"));
    ASSERT_TRUE(back.valid());
    EXPECT_EQ(speedSettings(*back->getSettings()), speedSettings(*w->getSettings()));
}

TEST(Serialization, TheBinarySeedsReadAsTheirTextTwins)
{
    // .osgb is positional: a field added in the middle of a wrapper makes every older binary file
    // read shifted (garbage, clamped with warnings). The pond seed is one scene in both formats
    // (the lake seed's text keeps OSG's six digits, its binary every bit: not twins); when this
    // fails, the binary layout changed: say so where it is documented and write the .osgb again
    for (const char* name : { "pond" }) {
        const std::string dir = std::string(OSGWATER_FUZZ_SEEDS) + "/" + name;
        osg::ref_ptr<WaterNode> binary = readWater(dir + ".osgb"), text = readWater(dir + ".osgt");
        ASSERT_TRUE(binary.valid() && text.valid()) << name;
        ASSERT_TRUE(osgDB::writeNodeFile(*binary, tmp(std::string(name) + "_from_osgb.osgt")));
        ASSERT_TRUE(osgDB::writeNodeFile(*text, tmp(std::string(name) + "_from_osgt.osgt")));
        EXPECT_EQ(slurp(tmp(std::string(name) + "_from_osgb.osgt")), slurp(tmp(std::string(name) + "_from_osgt.osgt")))
            << name;
    }
}

// Each osgWater object in a .osgb starts with the kit's binary layout number: a file of another
// layout, or of none, is refused with a message that says so and what to do, never read shifted
TEST(Serialization, ABinaryFileOfAnotherLayoutIsRefusedWithAMessage)
{
    osg::ref_ptr<WaterNode> w = pond();
    ASSERT_TRUE(osgDB::writeNodeFile(*w, tmp("layout.osgb")));
    const std::string bytes = slurp(tmp("layout.osgb"));
    // the stamp, little-endian: the layout in the low half of 0x6F57xxxx ("oW")
    const std::string stamp = std::string(1, char(detail::kBinaryLayout)) + std::string("\x00\x57\x6F", 3);
    const size_t at = bytes.find(stamp);
    ASSERT_NE(at, std::string::npos) << "no layout stamp in the file";
    ASSERT_TRUE(readWater(tmp("layout.osgb")).valid()) << "this layout's own file did not read";

    std::string other = bytes;
    other[at] = char(detail::kBinaryLayout + 1); // the next layout where the WaterNode starts
    spit(tmp("layout_next.osgb"), other);
    std::string unstamped = bytes;
    unstamped.erase(at, 4); // a file from before layouts were numbered
    spit(tmp("unstamped.osgb"), unstamped);
    const std::string next = "written in binary layout " + std::to_string(detail::kBinaryLayout + 1);
    const std::pair<const char*, const char*> cases[] = { { "layout_next.osgb", next.c_str() },
                                                          { "unstamped.osgb", "before binary layouts were numbered" } };
    for (const auto& c : cases) {
        ScopedWarnCapture warnings;
        EXPECT_FALSE(readWater(tmp(c.first)).valid()) << c.first;
        EXPECT_NE(warnings.str().find(c.second), std::string::npos) << warnings.str();
        EXPECT_NE(warnings.str().find("osgWater::WaterNode"), std::string::npos) << warnings.str();
        EXPECT_NE(warnings.str().find("Write the .osgb again from its .osgt"), std::string::npos) << warnings.str();
    }
}

// The wind's waves are kept as the wind's own fields (not arrays of waves), in both formats
TEST(Serialization, TheWindsWavesRoundTripAsTheirFields)
{
    osg::ref_ptr<WaterNode> w = new WaterNode;
    WindWaves wind;
    wind.speed = 7.25f;
    wind.direction.set(0.6f, 0.8f);
    wind.fetch = 1234.5f;
    wind.depth = 3.5f;
    wind.spread = 0.25f;
    wind.swell = 0.5f;
    wind.choppiness = 0.75f;
    wind.seed = 42;
    w->getSurface()->setWind(wind);
    w->getSurface()->setWaveModel(WaterSurface::WAVES_WIND);
    for (const char* ext : { "osgt", "osgb" }) {
        const std::string a = tmp(std::string("wind_a.") + ext), b = tmp(std::string("wind_b.") + ext);
        ASSERT_TRUE(osgDB::writeNodeFile(*w, a));
        osg::ref_ptr<WaterNode> r = readWater(a);
        ASSERT_TRUE(r.valid()) << ext;
        EXPECT_EQ(r->getSurface()->getWaveModel(), WaterSurface::WAVES_WIND) << ext;
        EXPECT_TRUE(r->getSurface()->getWind() == wind) << ext;
        ASSERT_TRUE(osgDB::writeNodeFile(*r, b));
        EXPECT_EQ(slurp(a), slurp(b)) << ext;
    }
    const std::string text = slurp(tmp("wind_a.osgt"));
    EXPECT_NE(text.find("WaveModel WAVES_WIND"), std::string::npos);
    EXPECT_NE(text.find("Speed 7.25"), std::string::npos);
    EXPECT_NE(text.find("Seed 42"), std::string::npos);
    EXPECT_NE(text.find("Choppiness 0.75"), std::string::npos);
}

// A hand-written wind out of range is clamped with a warning, like every other field
TEST(Serialization, AnAbsurdWindIsClampedWithAWarning)
{
    const std::string file = tmp("badwind.osgt");
    spit(file, "#Ascii Scene\n#Version 161\n#Generator OpenSceneGraph 3.6.5\n\n"
               "osgWater::WaterNode {\n  UniqueID 1\n  Surface TRUE {\n    osgWater::WaterSurface {\n      UniqueID 2\n"
               "      WaveModel WAVES_WIND\n      Wind {\n        Speed 900\n        Direction 0 0\n        Fetch -5\n"
               "        Depth 0\n        Spread 0\n        Swell 0\n        Seed 3\n      }\n    }\n  }\n}\n");
    ScopedWarnCapture capture;
    osg::ref_ptr<WaterNode> w = readWater(file);
    ASSERT_TRUE(w.valid());
    const WindWaves& wind = w->getSurface()->getWind();
    EXPECT_EQ(wind.speed, 40.0f);
    EXPECT_EQ(wind.direction, osg::Vec2(1.0f, 0.0f));
    EXPECT_EQ(wind.fetch, 0.0f);
    EXPECT_EQ(wind.seed, 3u);
    EXPECT_NE(capture.str().find("wind speed"), std::string::npos);
    EXPECT_TRUE(std::isfinite(w->getSurfaceHeightAt(1.0, 2.0, 3.0)));
}

namespace {

// one file of the bad-file corpus: what it must say, and the node it must read as
struct BadFile {
    const char* name;
    std::vector<std::string> says;             // each a whole warning line: line, class, field, why
    std::function<void(WaterNode&)> faultKept; // pond() with the faulty fields as a new node has them
};

std::string osgtOf(const WaterNode& node, const std::string& name)
{
    EXPECT_TRUE(osgDB::writeNodeFile(node, tmp(name)));
    return slurp(tmp(name));
}

size_t countLines(const std::string& text) { return size_t(std::count(text.begin(), text.end(), '\n')); }

}

// tests/data/bad_osgt holds tests/data/waternode_expected.osgt written by hand with faults: unknown
// fields (one line, a block, another class's), fields in another order, values that are not of
// their field's type, out of range, negative counts, unknown names, wrong wave counts and a wind
// block with all three. Each fault is said once, on its line, and every other field reads intact.
TEST(Serialization, EachFaultOfTheBadFileCorpusIsSaidOnItsLineAndEveryOtherFieldIsRead)
{
    const std::string S = "osgWater::WaterSettings ", F = "osgWater::WaterSurface ";
    const std::vector<BadFile> corpus = {
        { "unknown_field", { "osgWater: line 14: " + S + "Foam: is not a field of this class; skipped to its end, the fields after it are read" },
          [](WaterNode&) {} },
        { "unknown_block_field", { "osgWater: line 15: " + S + "Foam: is not a field of this class; skipped to its end, the fields after it are read" },
          [](WaterNode&) {} },
        { "field_of_another_class", { "osgWater: line 36: " + S + "Resolution: is not a field of this class; skipped to its end, the fields after it are read" },
          [](WaterNode& w) { w.getSurface()->setResolution(49); } },
        { "fields_in_another_order", {}, [](WaterNode&) {} },
        { "not_a_number", { "osgWater: line 13: " + S + "Attenuation: \"x\" is not a number; keeping 0.5" },
          [](WaterNode& w) { w.getSettings()->setAttenuation(0.5f); } },
        { "inf_and_nan",
          { "osgWater: line 12: " + S + "WaterColor: \"nan\" is not a finite number; keeping 0 0.2 0.1",
            "osgWater: line 13: " + S + "Attenuation: \"inf\" is not a finite number; keeping 0.5" },
          [](WaterNode& w) {
              w.getSettings()->setWaterColor(osg::Vec3(0.0f, 0.2f, 0.1f));
              w.getSettings()->setAttenuation(0.5f);
          } },
        { "out_of_range",
          { "osgWater: line 23: " + S + "PhotonGridSize: \"99999999999\" is out of range; keeping 512",
            "osgWater: line 34: " + S + "GlowRadius: \"1e999\" is out of range; keeping 3" },
          [](WaterNode& w) {
              w.getSettings()->setPhotonGridSize(512);
              w.getSettings()->setGlowRadius(3.0f);
          } },
        { "negative_count", { "osgWater: line 43: " + F + "Resolution: \"-5\" is negative; keeping 49" },
          [](WaterNode& w) { w.getSurface()->setResolution(49); } },
        { "exponent_in_integer", { "osgWater: line 17: " + S + "SearchSteps: \"1e9\" is not a whole number; keeping 3" },
          [](WaterNode& w) { w.getSettings()->setSearchSteps(3); } },
        { "unknown_enum_name",
          { "osgWater: line 16: " + S + "RefractionLookup: \"FOO\" is not one of "
                                        "ONE_STEP|ITERATIVE|PLANE_OFFSET|BRACKETED|VIRTUAL_VERTICES; keeping ITERATIVE" },
          [](WaterNode& w) { w.getSettings()->setRefractionLookup(WaterSettings::ITERATIVE); } },
        { "not_a_switch", { "osgWater: line 22: " + S + "ReflectionEnabled: \"maybe\" is not TRUE or FALSE; keeping TRUE" },
          [](WaterNode& w) { w.getSettings()->setReflectionEnabled(true); } },
        { "unknown_quality",
          { "osgWater: line 11: " + S + "Quality: \"superb\" is not one of fast|balanced|exact; keeping the settings as they are" },
          [](WaterNode&) {} },
        { "size_zero", { "osgWater::WaterSurface: size 0 out of (0.01, 1e7], keeping 100" },
          [](WaterNode& w) { w.getSurface()->setSize(100.0f); } },
        { "wave_count_not_a_number", { "osgWater: line 44: " + F + "Waves: count \"x\" is not a number; keeping the 4 waves" },
          [](WaterNode& w) { w.getSurface()->setWaves(defaultWaves()); } },
        { "wave_count_wrong",
          { "osgWater: line 45: " + F + "Waves: 2 waves are five numbers each, 10, and the block holds 5; keeping the 4 waves" },
          [](WaterNode& w) { w.getSurface()->setWaves(defaultWaves()); } },
        { "wind_with_bad_fields",
          { "osgWater: line 48: " + F + "Wind Gusts: is not a field of the wind; skipped to its end",
            "osgWater: line 51: " + F + "Wind Fetch: \"fast\" is not a number; keeping its default",
            "osgWater: line 52: " + F + "Wind Seed: \"-1\" is negative; keeping its default" },
          [](WaterNode& w) {
              WindWaves wind;
              wind.speed = 12.0f;
              wind.swell = 0.5f;
              w.getSurface()->setWind(wind);
              w.getSurface()->setWaveModel(WaterSurface::WAVES_WIND);
          } },
    };
    for (const BadFile& c : corpus) {
        ScopedWarnCapture capture;
        osg::ref_ptr<WaterNode> read = readWater(std::string(OSGWATER_TEST_DATA) + "/bad_osgt/" + c.name + ".osgt");
        ASSERT_TRUE(read.valid()) << c.name;
        const std::string said = capture.str();
        for (const std::string& line : c.says) EXPECT_NE(said.find(line + "\n"), std::string::npos) << c.name << " said:\n" << said;
        EXPECT_EQ(countLines(said), c.says.size()) << c.name << " said:\n" << said;
        osg::ref_ptr<WaterNode> expected = pond();
        c.faultKept(*expected);
        EXPECT_EQ(osgtOf(*read, "bad_read.osgt"), osgtOf(*expected, "bad_expected.osgt")) << c.name;
    }
}

// A Sky among the water's children keeps its sun, turbidity and luminance scale in both formats, and
// is read back as one triangle of its own making (its state and triangle are never stored)
TEST(Serialization, ASkyRoundTripsAsItsSettings)
{
    osg::ref_ptr<WaterNode> w = new WaterNode;
    osg::ref_ptr<Sky> sky = new Sky;
    sky->setSunDirection(osg::Vec3(0.3f, 0.4f, 0.866f));
    sky->setTurbidity(4.0f);
    sky->setLuminanceScale(0.1f);
    w->addChild(sky.get());
    for (const char* ext : { "osgt", "osgb" }) {
        const std::string a = tmp(std::string("sky_a.") + ext), b = tmp(std::string("sky_b.") + ext);
        ASSERT_TRUE(osgDB::writeNodeFile(*w, a)) << ext;
        osg::ref_ptr<WaterNode> r = readWater(a);
        ASSERT_TRUE(r.valid()) << ext;
        ASSERT_EQ(r->getNumChildren(), 1u) << ext;
        const Sky* read = dynamic_cast<const Sky*>(r->getChild(0));
        ASSERT_NE(read, nullptr) << ext;
        EXPECT_EQ(read->getSunDirection(), sky->getSunDirection()) << ext;
        EXPECT_EQ(read->getTurbidity(), 4.0f) << ext;
        EXPECT_EQ(read->getLuminanceScale(), 0.1f) << ext;
        EXPECT_EQ(read->getNumDrawables(), 1u) << ext;
        ASSERT_TRUE(osgDB::writeNodeFile(*r, b));
        EXPECT_EQ(slurp(a), slurp(b)) << ext;
    }
    const std::string text = slurp(tmp("sky_a.osgt"));
    EXPECT_NE(text.find("osgWater::Sky"), std::string::npos);
    EXPECT_NE(text.find("Turbidity 4"), std::string::npos);
    EXPECT_EQ(text.find("osgWater_SkyA"), std::string::npos) << "the sky's state was stored";
}
