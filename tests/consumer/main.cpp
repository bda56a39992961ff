#include <osgWater/WaterNode>
#include <iostream>
#include <string>
int main()
{
    osg::ref_ptr<osgWater::WaterNode> water = new osgWater::WaterNode;
    std::cout << water->className() << " k=" << water->getSettings()->getAttenuation() << std::endl;
    const bool ok = std::string(water->className()) == "WaterNode" && water->getSurface()->getResolution() == 49;
    return ok ? 0 : 1;
}
