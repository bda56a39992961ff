// A buoy and a small boat that float on a WaterNode (osgWater::FloatingTransform), shared by the
// lake demo and its test.
#pragma once
#include <osgWater/FloatingTransform>
#include <osgWater/WaterNode>
#include <osg/Switch>

namespace osgWaterApps {

//! Where they float in the lake demo: in the default view's water, 3-4 m deep.
const osg::Vec2d kLakeBuoy(-4.0, -26.0), kLakeBoat(5.0, -22.0);

//! Adds a Switch holding a buoy at `buoy` and a boat at `boat` (x, y in the water's frame) to the
//! water's children, so they are mirrored and refracted with the scene; shown when `on`.
osg::ref_ptr<osg::Switch> addFloaters(osgWater::WaterNode* water, const osg::Vec2d& buoy, const osg::Vec2d& boat, bool on);

}
