#include "Floaters.h"
#include "Solid.h"

namespace osgWaterApps {

osg::ref_ptr<osg::Switch> addFloaters(osgWater::WaterNode* water, const osg::Vec2d& buoyAt, const osg::Vec2d& boatAt, bool on)
{
    // a red spar buoy: 0.5 m of its 1.4 m below the surface; both follow the waves exactly (no
    // damping: the lake's ripples are short and low)
    osg::ref_ptr<osgWater::FloatingTransform> buoy = new osgWater::FloatingTransform;
    buoy->setName("buoy");
    buoy->setPosition(buoyAt);
    buoy->setDraft(0.5);
    buoy->addChild(solid(osg::Vec4(0.85f, 0.1f, 0.08f, 1.0f),
                         { new osg::Cylinder(osg::Vec3(0, 0, 0.6f), 0.25f, 1.2f), new osg::Sphere(osg::Vec3(0, 0, 1.3f), 0.18f) }));

    // a small wooden boat: a 3.6 m hull drawing 0.2 m
    osg::ref_ptr<osgWater::FloatingTransform> boat = new osgWater::FloatingTransform;
    boat->setName("boat");
    boat->setPosition(boatAt);
    boat->setHeading(0.6);
    boat->setDraft(0.2);
    boat->addChild(solid(osg::Vec4(0.45f, 0.3f, 0.17f, 1.0f),
                         { new osg::Box(osg::Vec3(0, 0, 0.25f), 3.6f, 1.3f, 0.5f), new osg::Box(osg::Vec3(-0.6f, 0, 0.75f), 1.0f, 0.9f, 0.5f) }));

    osg::ref_ptr<osg::Switch> floaters = new osg::Switch;
    floaters->setName("floaters");
    floaters->addChild(buoy.get(), on);
    floaters->addChild(boat.get(), on);
    water->addChild(floaters.get());
    return floaters;
}

}
