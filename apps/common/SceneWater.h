// The WaterNode of a loaded scene, shared by the demo and the benchmark.
#pragma once
#include <osgWater/WaterNode>
#include <string>

namespace osgWaterApps {

//! The first osgWater::WaterNode in `root`; if there is none, a new WaterNode (water at z = 0)
//! becomes the root with the model as its child, and `added` is set.
osg::ref_ptr<osgWater::WaterNode> findOrAddWater(osg::ref_ptr<osg::Node>& root, const std::string& file, bool* added = nullptr);

}
