#include "Pond.h"
#include "Solid.h"
#include <osgWater/WaterTypes>
#include <osgUtil/IntersectionVisitor>
#include <osg/MatrixTransform>
#include <osgUtil/LineSegmentIntersector>

namespace osgWaterApps {

namespace {

// the ground of the lake's scene at (x, y): the first surface met going down from 50 m above the
// water (below the sky dome; the rim stands above the water)
double groundAt(osgWater::WaterNode* lake, double x, double y)
{
    const double z = lake->getSurface()->getLevel();
    osg::ref_ptr<osgUtil::LineSegmentIntersector> down =
        new osgUtil::LineSegmentIntersector(osg::Vec3d(x, y, z + 50.0), osg::Vec3d(x, y, z - 50.0));
    osgUtil::IntersectionVisitor iv(down.get());
    lake->accept(iv);
    return down->containsIntersections() ? down->getFirstIntersection().getWorldIntersectPoint().z() : z;
}

}

osg::ref_ptr<osg::Switch> addPond(osgWater::WaterNode* lake, const osg::Vec2d& at, bool on,
                                  osg::ref_ptr<osgWater::WaterNode>* pondOut)
{
    const double ground = groundAt(lake, at.x(), at.y());
    const float side = 5.0f, wall = 0.3f, rim = 0.55f, depth = 0.9f; // basin, metres
    const double level = ground + kPondWaterAboveGround;

    // the basin in the pond's frame (the lake's, moved to the pond): floor and four stone walls
    // standing rim metres above the ground, sunk to depth below the water
    const float h = side / 2, top = rim, bottom = float(kPondWaterAboveGround) - depth;
    const float wallH = top - bottom, wallZ = (top + bottom) / 2;
    osg::ref_ptr<osg::Geode> basin = solid(osg::Vec4(0.5f, 0.48f, 0.44f, 1.0f), {
        new osg::Box(osg::Vec3(0, 0, bottom - 0.05f), side, side, 0.1f),
        new osg::Box(osg::Vec3(0, h - wall / 2, wallZ), side, wall, wallH),
        new osg::Box(osg::Vec3(0, -h + wall / 2, wallZ), side, wall, wallH),
        new osg::Box(osg::Vec3(h - wall / 2, 0, wallZ), wall, side, wallH),
        new osg::Box(osg::Vec3(-h + wall / 2, 0, wallZ), wall, side, wallH) });
    osg::ref_ptr<osg::MatrixTransform> placed = new osg::MatrixTransform(osg::Matrixd::translate(at.x(), at.y(), ground));
    placed->addChild(basin.get());

    // its water: a murky garden pond between the walls, with small ripples of its own
    osg::ref_ptr<osgWater::WaterNode> pond = new osgWater::WaterNode;
    pond->setName("pond");
    osgWater::applyWaterType(*pond->getSettings(), "murky-pond");
    osgWater::WaterSurface* s = pond->getSurface();
    s->setSize(side - 2 * wall);
    s->setCenter(osg::Vec2(float(at.x()), float(at.y())));
    s->setLevel(level);
    osgWater::Wave a, b;
    a.direction.set(0.8f, 0.6f);
    a.wavelength = 0.7f;
    a.amplitude = 0.004f;
    b.direction.set(-0.5f, 0.87f);
    b.wavelength = 0.45f;
    b.amplitude = 0.003f;
    b.phase = 1.3f;
    s->setWaves({ a, b });
    pond->addChild(placed.get());

    osg::ref_ptr<osg::Switch> sw = new osg::Switch;
    sw->setName("pond");
    sw->addChild(pond.get(), on);
    lake->addChild(sw.get());
    if (pondOut) *pondOut = pond;
    return sw;
}

}
