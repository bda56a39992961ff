// FloatingTransform: children ride the waves at the height (and normal) the water reports, with
// damping, written and read back through .osgt/.osgb exactly. No GPU.
#include <osgWater/FloatingTransform>
#include <osgWater/WaterNode>
#include <osgDB/ReadFile>
#include <osgDB/WriteFile>
#include "UpdateTraversal.h"
#include <gtest/gtest.h>
#include <cmath>

using namespace osgWater;
using testing_update::update;

namespace {

osg::Vec3d axis(const osg::Matrixd& m, int i)
{
    return osg::Vec3d(m(i, 0), m(i, 1), m(i, 2));
}

}

class FloatingOnEitherWaves : public ::testing::TestWithParam<WaterSurface::WaveModel> {};
INSTANTIATE_TEST_SUITE_P(Floating, FloatingOnEitherWaves, ::testing::Values(WaterSurface::WAVES_SUM, WaterSurface::WAVES_WIND),
                         [](const ::testing::TestParamInfo<WaterSurface::WaveModel>& i) {
                             return std::string(WaterSurface::waveModelName(i.param));
                         });

TEST_P(FloatingOnEitherWaves, ChildrenRideTheWavesAtTheQueriedHeightAndNormal)
{
    osg::ref_ptr<WaterNode> water = new WaterNode;
    water->getSurface()->setLevel(0.7);
    water->getSurface()->setWaveModel(GetParam()); // the wind's: a 5 m/s breeze over the 100 m water
    osg::ref_ptr<FloatingTransform> buoy = new FloatingTransform;
    buoy->setPosition(osg::Vec2d(3.0, -2.0));
    buoy->setDraft(0.25);
    buoy->setHeading(0.4);
    water->addChild(buoy.get()); // finds its water above it
    double worst = 0.0;
    for (unsigned int f = 1; f <= 120; ++f) {
        const double t = 5.0 + f / 60.0;
        update(water.get(), t, f);
        osg::Vec3d n;
        const double h = water->getSurfaceHeightAt(3.0, -2.0, t, &n);
        const osg::Matrixd& m = buoy->getMatrix();
        EXPECT_NEAR(m.getTrans().x(), 3.0, 1e-12);
        EXPECT_NEAR(m.getTrans().y(), -2.0, 1e-12);
        worst = std::max(worst, std::fabs(m.getTrans().z() - (h - 0.25)));
        EXPECT_NEAR((axis(m, 2) - n).length(), 0.0, 1e-9) << "the z axis along the surface normal";
    }
    EXPECT_LT(worst, 1e-3) << "within 1 mm of the query every frame";
    EXPECT_LT(worst, 1e-9);
    EXPECT_EQ(buoy->getWater(), water.get());

    // upright without tilt, the heading turning its x axis about +z
    buoy->setTilt(false);
    update(water.get(), 7.0, 200);
    EXPECT_NEAR((axis(buoy->getMatrix(), 2) - osg::Vec3d(0, 0, 1)).length(), 0.0, 1e-12);
    EXPECT_NEAR((axis(buoy->getMatrix(), 0) - osg::Vec3d(std::cos(0.4), std::sin(0.4), 0)).length(), 0.0, 1e-12);
}

TEST(Floating, DampingLagsLikeAFirstOrderSystem)
{
    // flat water whose level steps up 1 m: with a 1 s time constant, after 1 s (60 frames) the
    // transform has covered 1 - 1/e of the step
    osg::ref_ptr<WaterNode> water = new WaterNode;
    water->getSurface()->setWaves({});
    osg::ref_ptr<FloatingTransform> boat = new FloatingTransform;
    boat->setDamping(1.0);
    water->addChild(boat.get());
    update(water.get(), 0.0, 1);
    EXPECT_NEAR(boat->getMatrix().getTrans().z(), 0.0, 1e-12) << "the first frame starts on the surface";
    water->getSurface()->setLevel(1.0);
    for (unsigned int f = 1; f <= 60; ++f) update(water.get(), f / 60.0, f + 1);
    EXPECT_NEAR(boat->getMatrix().getTrans().z(), 1.0 - std::exp(-1.0), 1e-9);
}

TEST(Floating, BadValuesAreClampedAndItRoundTripsExactly)
{
    osg::ref_ptr<FloatingTransform> f = new FloatingTransform;
    f->setPosition(osg::Vec2d(std::nan(""), 1e30));
    f->setDamping(-3.0);
    EXPECT_EQ(f->getPosition(), osg::Vec2d(0.0, 1.0e7));
    EXPECT_EQ(f->getDamping(), 0.0);

    osg::ref_ptr<WaterNode> water = new WaterNode;
    f->setPosition(osg::Vec2d(1234.5678901234567, -0.1));
    f->setHeading(2.25);
    f->setDraft(0.3333333333333333);
    f->setDamping(0.75);
    f->setTilt(false);
    water->addChild(f.get());
    for (const char* ext : { "osgt", "osgb" }) {
        const std::string file = std::string(OSGWATER_TEST_TMP) + "/floating." + ext;
        ASSERT_TRUE(osgDB::writeNodeFile(*water, file)) << ext;
        osg::ref_ptr<osg::Node> back = osgDB::readRefNodeFile(file);
        WaterNode* w = dynamic_cast<WaterNode*>(back.get());
        ASSERT_TRUE(w && w->getNumChildren() == 1) << ext;
        FloatingTransform* g = dynamic_cast<FloatingTransform*>(w->getChild(0));
        ASSERT_TRUE(g) << ext;
        EXPECT_EQ(g->getPosition(), f->getPosition()) << ext;
        EXPECT_EQ(g->getHeading(), 2.25) << ext;
        EXPECT_EQ(g->getDraft(), 0.3333333333333333) << ext;
        EXPECT_EQ(g->getDamping(), 0.75) << ext;
        EXPECT_FALSE(g->getTilt()) << ext;
    }
}
