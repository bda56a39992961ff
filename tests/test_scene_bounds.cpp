// Where sunlight can enter the water and land (findLitWater): the window the caustics passes are
// focused on. Checked on scenes whose lit water follows from their geometry: a bed in a hole of a
// shore above the water, a shore's shadow under an oblique sun, a sky dome's inside (no shade),
// the outside of a dome (shades everything).
#include <gtest/gtest.h>
#include "frame/SceneBounds.h"
#include <osgWater/WaterNode>
#include "UpdateTraversal.h"
#include <osg/Geode>
#include <osg/Geometry>
#include <osg/MatrixTransform>
#include <cmath>

using namespace osgWater;

namespace {

// a quad at height z, wound counter-clockwise seen from above (facing up) unless `down`
osg::Geode* quad(float x0, float y0, float x1, float y1, float z, bool down = false)
{
    osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array;
    v->push_back(osg::Vec3(x0, y0, z));
    v->push_back(osg::Vec3(x1, y0, z));
    v->push_back(osg::Vec3(x1, y1, z));
    v->push_back(osg::Vec3(x0, y1, z));
    if (down) std::swap((*v)[1], (*v)[3]);
    osg::Geometry* g = new osg::Geometry;
    g->setVertexArray(v.get());
    g->addPrimitiveSet(new osg::DrawArrays(GL_QUADS, 0, 4));
    osg::Geode* geode = new osg::Geode;
    geode->addDrawable(g);
    return geode;
}

// a bed at z = -2 under a hole [-4, 4]^2 in a shore at z = +1, over a 20 m water square (the shore
// reaches past it, so slanted rays into the water's edge meet it), with a deep floor at z = -6 under
// everything (like a sky dome's lower half under the ground)
osg::ref_ptr<osg::Group> bedInAHole()
{
    osg::ref_ptr<osg::Group> g = new osg::Group;
    g->addChild(quad(-4, -4, 4, 4, -2));
    g->addChild(quad(-12, -12, -4, 12, 1));
    g->addChild(quad(4, -12, 12, 12, 1));
    g->addChild(quad(-4, -12, 4, -4, 1));
    g->addChild(quad(-4, 4, 4, 12, 1));
    g->addChild(quad(-12, -12, 12, 12, -6));
    return g;
}

const osg::BoundingBox kWater(-10, -10, 0, 10, 10, 0);
const double kCell = 20.0 / 128; // the default grid over the water's side

}

TEST(SceneBounds, TheSunOverheadLightsTheHoleInTheShore)
{
    osg::ref_ptr<osg::Group> scene = bedInAHole();
    const LitWater found = findLitWater(*scene, kWater, 0.0, osg::Vec3(0, 0, 1));
    const osg::BoundingBox& lit = found.box;
    ASSERT_TRUE(lit.valid());
    // the entry points of the lit rays, grown by a cell and a half (half from cell centres)
    for (float edge : { lit.xMin(), lit.yMin() }) EXPECT_NEAR(edge, -4.0, 1.6 * kCell);
    for (float edge : { lit.xMax(), lit.yMax() }) EXPECT_NEAR(edge, 4.0, 1.6 * kCell);
    EXPECT_NEAR(lit.zMin(), -2.0 * 1.25, 1e-4) << "the bed, a quarter deeper for refracted rays";
    EXPECT_FLOAT_EQ(lit.zMax(), 0.0f) << "the crest";
    // the lookup planes' defaults: every lit ray lands on the bed at -2, every other meets the shore at +1
    EXPECT_NEAR(found.meanBedZ, -2.0, 1e-6);
    ASSERT_TRUE(found.shaded);
    EXPECT_NEAR(found.meanShadeZ, 1.0, 1e-6);
}

TEST(SceneBounds, AnObliqueSunLightsWhereTheShoreDoesNotShadeTheWater)
{
    osg::ref_ptr<osg::Group> scene = bedInAHole();
    // towards the sun: 45 degrees up, towards -x. A ray entering the crest plane at x crossed the
    // shore's height (1 m up) at x - 1: the shore at x >= 4 shades the water from x = 5 on, and
    // the shore at x <= -4 up to x = -3.
    const osg::BoundingBox lit = findLitWater(*scene, kWater, 0.0, osg::Vec3(-1, 0, 1)).box;
    ASSERT_TRUE(lit.valid());
    EXPECT_NEAR(lit.xMin(), -3.0, 1.6 * kCell);
    EXPECT_NEAR(lit.xMax(), 5.0, 1.6 * kCell);
    EXPECT_NEAR(lit.yMin(), -4.0, 1.6 * kCell) << "across the sun: the hole's own edges";
    EXPECT_NEAR(lit.yMax(), 4.0, 1.6 * kCell);
    // the deepest first hit: rays entering at x in (4, 5) pass the bed's edge (they would meet
    // z = -2 past x = 6) down to the floor at -6
    EXPECT_NEAR(lit.zMin(), -6.0 * 1.25, 1e-3);
}

TEST(SceneBounds, ADomesInsideDoesNotShadeButItsOutsideShadesEverything)
{
    osg::ref_ptr<osg::Group> scene = bedInAHole();
    scene->addChild(quad(-50, -50, 50, 50, 40, true)); // a sky's ceiling, facing down
    EXPECT_TRUE(findLitWater(*scene, kWater, 0.0, osg::Vec3(0, 0, 1)).box.valid());
    scene->addChild(quad(-50, -50, 50, 50, 45)); // a ceiling facing the sun
    EXPECT_FALSE(findLitWater(*scene, kWater, 0.0, osg::Vec3(0, 0, 1)).box.valid())
        << "no light reaches the water: the caustics fall back to the unfocused window";
}

TEST(SceneBounds, TransformsPlaceTheGeometryAndNothingUnderTheWaterLightsNothing)
{
    osg::ref_ptr<osg::MatrixTransform> moved = new osg::MatrixTransform(osg::Matrix::translate(3, 0, 0));
    moved->addChild(quad(-1, -1, 1, 1, -3));
    osg::ref_ptr<osg::Group> scene = new osg::Group;
    scene->addChild(moved.get());
    const osg::BoundingBox lit = findLitWater(*scene, kWater, 0.0, osg::Vec3(0, 0, 1)).box;
    ASSERT_TRUE(lit.valid());
    EXPECT_NEAR(lit.xMin(), 2.0, 1.6 * kCell);
    EXPECT_NEAR(lit.xMax(), 4.0, 1.6 * kCell);

    osg::ref_ptr<osg::Group> dry = new osg::Group;
    dry->addChild(quad(-5, -5, 5, 5, 2));
    EXPECT_FALSE(findLitWater(*dry, kWater, 0.0, osg::Vec3(0, 0, 1)).box.valid());
    EXPECT_FALSE(findLitWater(*scene, kWater, 0.0, osg::Vec3(1, 0, 0)).box.valid()) << "the sun on the horizon";
    EXPECT_FALSE(findLitWater(*scene, kWater, 0.0, osg::Vec3(NAN, 0, 1)).box.valid());
}

TEST(SceneBounds, TheLookupPlanesDefaultToTheShadeAboveAndTheBedBelow)
{
    // the plane-offset lookups' planes when the settings leave them at 0: the mean depth of the bed
    // where light lands and the mean height of what shades the water, from the same sun rays
    osg::ref_ptr<WaterNode> water = new WaterNode;
    water->getSurface()->setWaves({});
    water->getSurface()->setSize(20.0f);
    water->getSettings()->setSunDirection(osg::Vec3(0, 0, 1));
    water->getSettings()->setRefractionLookup(WaterSettings::PLANE_OFFSET);
    osg::ref_ptr<osg::Group> scene = bedInAHole();
    for (unsigned int i = 0; i < scene->getNumChildren(); ++i) water->addChild(scene->getChild(i));
    testing_update::update(water.get(), 0.0, 1);
    EXPECT_NEAR(water->getLookupPlanes().x(), 1.0, 1e-5) << "the shore 1 m above the level";
    EXPECT_NEAR(water->getLookupPlanes().y(), 2.0, 1e-5) << "the bed 2 m below it";
    water->getSettings()->setReflectionPlaneHeight(4.0f);
    water->getSettings()->setRefractionPlaneDepth(0.5f);
    testing_update::update(water.get(), 0.0, 2);
    EXPECT_FLOAT_EQ(water->getLookupPlanes().x(), 4.0f) << "as set";
    EXPECT_FLOAT_EQ(water->getLookupPlanes().y(), 0.5f);
    // nothing shades the water: the reflection plane at the reflection scale c
    osg::ref_ptr<WaterNode> open = new WaterNode;
    open->getSurface()->setWaves({});
    open->getSettings()->setReflectionLookup(WaterSettings::REFLECTION_PLANE);
    open->addChild(scene->getChild(0)); // the bed alone
    testing_update::update(open.get(), 0.0, 1);
    EXPECT_FLOAT_EQ(open->getLookupPlanes().x(), open->getSettings()->getReflectionScale());
}
