#include "SceneWater.h"
#include <osg/NodeVisitor>
#include <iostream>

namespace osgWaterApps {

namespace {
class FindWater : public osg::NodeVisitor
{
public:
    FindWater() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}
    void apply(osg::Group& g) override
    {
        if (!found) found = dynamic_cast<osgWater::WaterNode*>(&g);
        if (!found) traverse(g);
    }
    osgWater::WaterNode* found = nullptr;
};
}

osg::ref_ptr<osgWater::WaterNode> findOrAddWater(osg::ref_ptr<osg::Node>& root, const std::string& file, bool* added)
{
    FindWater find;
    root->accept(find);
    osg::ref_ptr<osgWater::WaterNode> water = find.found;
    if (added) *added = !water.valid();
    if (!water.valid()) { // any model: put water under it
        std::cout << file << " has no osgWater::WaterNode: adding water at z = 0" << std::endl;
        water = new osgWater::WaterNode;
        water->addChild(root.get());
        root = water;
    }
    return water;
}

}
