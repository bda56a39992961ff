// A second body of water for the lake demo: a stone-rimmed garden pond on the lake's north rim,
// its water above the lake's, a WaterNode among the lake's children (see WaterNode: several
// bodies of water). Shared by the lake demo and its test.
#pragma once
#include <osgWater/WaterNode>
#include <osg/Switch>

namespace osgWaterApps {

//! Where it sits in the lake demo, and a view of it across the lake.
const osg::Vec2d kLakePond(10.0, 44.0);
const osg::Vec3d kPondViewEye(12.0, 18.0, 9.0), kPondViewCenter(10.0, 44.0, 2.5);
//! The pond's water stands this far above the ground it is built on.
const double kPondWaterAboveGround = 0.45;

//! Adds a Switch holding the pond at `at` (x, y in the lake's frame), built on the ground the
//! lake's scene has there (found by a line-segment intersection), to the lake's children; shown
//! when `on`. `pond` receives the pond's WaterNode.
osg::ref_ptr<osg::Switch> addPond(osgWater::WaterNode* lake, const osg::Vec2d& at, bool on,
                                  osg::ref_ptr<osgWater::WaterNode>* pond = nullptr);

}
