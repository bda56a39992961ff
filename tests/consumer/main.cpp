// A program built against the installed kit alone: only the public headers are on its include path.
#include <osgWater/FloatingTransform>
#include <osgWater/Statistics>
#include <osgWater/Version>
#include <osgWater/WaterNode>
#include <osgWater/WaterTypes>
#include <cstring>
#include <iostream>
#include <string>
int main()
{
    osg::ref_ptr<osgWater::WaterNode> water = new osgWater::WaterNode;
    std::cout << water->className() << " k=" << water->getSettings()->getAttenuation() << " version "
              << osgWater::getVersion() << std::endl;
    bool ok = std::string(water->className()) == "WaterNode" && water->getSurface()->getResolution() == 49;
    // the diagnostics: a camera the water never saw has no report, and every pass has a name
    osg::ref_ptr<osg::Camera> camera = new osg::Camera;
    const osgWater::ViewReport report = water->getViewReport(camera.get());
    ok = ok && !report.valid && report.milliseconds[osgWater::PASS_REFLECTION] < 0.0;
    ok = ok && std::strcmp(osgWater::passName(osgWater::PASS_REFRACTION), "refraction") == 0;
    // the version the library was built as is the one its header says
    const std::string header = std::to_string(OSGWATER_VERSION_MAJOR) + "." + std::to_string(OSGWATER_VERSION_MINOR) +
                               "." + std::to_string(OSGWATER_VERSION_PATCH);
    ok = ok && header == osgWater::getVersion();
    return ok ? 0 : 1;
}
