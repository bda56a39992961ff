// An update traversal at a given simulation time and frame, as a viewer's frame runs it (no GPU).
#pragma once
#include <osg/FrameStamp>
#include <osg/Node>
#include <osgUtil/UpdateVisitor>

namespace testing_update {

inline void update(osg::Node* node, double simulationTime, unsigned int frame)
{
    osg::ref_ptr<osg::FrameStamp> fs = new osg::FrameStamp;
    fs->setSimulationTime(simulationTime);
    fs->setFrameNumber(frame);
    osgUtil::UpdateVisitor uv;
    uv.setFrameStamp(fs.get());
    node->accept(uv);
}

}
