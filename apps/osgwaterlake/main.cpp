// osgwaterlake: the thesis's lake demo (ch. 10) on OpenSceneGraph. Loads a scene (default
// data/lake.osgt: a WaterNode over the OBJ lake), shows it in a window with the frame rate, or
// renders it headless: N frames off-screen, a PNG screenshot and the median frame time, with and
// without the water, measured in one run.
#include "Hud.h"
#include "LakeOptions.h"
#include "WaterKeys.h"
#include "../common/Floaters.h"
#include "../common/Pond.h"
#include "../common/FrameTimer.h"
#include "../common/SceneWater.h"
#include <osgWater/Offscreen>
#include <osgDB/FileNameUtils>
#include <osgDB/ReadFile>
#include <osgDB/WriteFile>
#include <osgGA/KeySwitchMatrixManipulator>
#include <osgGA/StateSetManipulator>
#include <osgGA/TrackballManipulator>
#include <osgViewer/ViewerEventHandlers>
#include <osg/Switch>
#include <osg/Timer>
#include <algorithm>
#include <cstdio>
#include <functional>
#include <map>
#include <iostream>

namespace {

// OSG's WriteToFile adds the context number to the name; the screenshot goes where it was asked to
struct WriteExactly : public osgViewer::ScreenCaptureHandler::CaptureOperation {
    explicit WriteExactly(const std::string& f) : file(f) {}
    void operator()(const osg::Image& image, const unsigned int) override
    {
        if (!osgDB::writeImageFile(image, file)) std::cerr << "error: could not write the screenshot " << file << std::endl;
    }
    std::string file;
};

// One thing timed in the headless run: a name and how to switch the scene to it.
struct Configuration {
    std::string name;
    std::function<void()> select;
    std::vector<double> ms, causticsMs;
};

std::vector<Configuration> configurations(osg::Switch* scenes, osgWater::WaterNode* water, const LakeOptions& o)
{
    using osgWater::WaterSettings;
    WaterSettings* s = water->getSettings();
    const bool caustics = s->getCausticsEnabled();
    const WaterSettings::CausticsGather gather = s->getCausticsGather();
    std::vector<Configuration> c;
    c.push_back({ "water", [=] { scenes->setSingleChildOn(0); s->setCausticsEnabled(caustics); s->setCausticsGather(gather); }, {} });
    if (o.compareCaustics) {
        c[0].name = "water, caustics off";
        c[0].select = [=] { scenes->setSingleChildOn(0); s->setCausticsEnabled(false); };
        for (WaterSettings::CausticsGather g : { WaterSettings::GATHER_POINTS_COPY, WaterSettings::GATHER_POINTS_TEXTURE,
                                                 WaterSettings::GATHER_CPU })
            c.push_back({ std::string("water, caustics ") + osgWater::causticsGatherLabel(g),
                          [=] { scenes->setSingleChildOn(0); s->setCausticsEnabled(true); s->setCausticsGather(g); }, {} });
    }
    if (o.compareGlow) {
        c[0].name = "water, glow off";
        c[0].select = [=] { scenes->setSingleChildOn(0); s->setGlowEnabled(false); };
        c.push_back({ "water, glow on", [=] { scenes->setSingleChildOn(0); s->setGlowEnabled(true); }, {} });
    }
    if (o.compare) c.push_back({ "without water", [=] { scenes->setSingleChildOn(1); }, {} });
    return c;
}

int runHeadless(osgViewer::Viewer& viewer, osg::Switch* scenes, osgWater::WaterNode* water, osg::Node* hud, const LakeOptions& o)
{
    if (hud) hud->setNodeMask(0); // text costs the same with and without water: keep it out of the ratio
    viewer.getCamera()->setViewMatrixAsLookAt(o.eye, o.center, o.up);
    std::vector<Configuration> configs = configurations(scenes, water, o);
    std::map<int, std::vector<double>> passMs; // pass -> GPU times of the first configuration
    const osgWater::WaterSettings* s = water->getSettings();
    const bool caustics = s->getCausticsEnabled();
    const osgWater::WaterSettings::CausticsGather gather = s->getCausticsGather();
    const bool glow = s->getGlowEnabled();
    double t = o.time;
    const double dt = 1.0 / 60.0;
    // alternating blocks, so drifts in machine load hit every configuration alike
    // the frames asked for, in up to 5 alternating blocks (fewer when fewer frames are asked for)
    const int blocks = configs.size() > 1 ? std::min(5, o.frames) : 1, perBlock = std::max(o.frames / blocks, 1);
    for (int b = 0; b < blocks; ++b)
        for (size_t which = 0; which < configs.size(); ++which) {
            configs[which].select();
            for (int i = 0; i <= perBlock + 1; ++i) {
                const osg::Timer_t t0 = osg::Timer::instance()->tick();
                viewer.frame(t);
                t += dt;
                const double ms = osg::Timer::instance()->delta_m(t0, osg::Timer::instance()->tick());
                if (i < 2) continue; // the first frames after a switch warm up (GPU times lag a frame)
                configs[which].ms.push_back(ms);
                const double causticsMs = water->getPassMilliseconds(viewer.getCamera(), osgWater::PASS_PHOTONS);
                if (scenes->getValue(0) && s->getCausticsEnabled() && causticsMs >= 0)
                    configs[which].causticsMs.push_back(causticsMs);
                if (which != 0) continue;
                for (int pass = 0; pass < osgWater::PASS_COUNT; ++pass) {
                    const double gpu = water->getPassMilliseconds(viewer.getCamera(), osgWater::PassId(pass));
                    if (gpu >= 0.0 && osgWater::gpuTimeLabel(osgWater::PassId(pass))) passMs[pass].push_back(gpu);
                }
            }
        }
    scenes->setSingleChildOn(0); // the screenshot: the water as configured
    water->getSettings()->setCausticsEnabled(caustics);
    water->getSettings()->setCausticsGather(gather);
    water->getSettings()->setGlowEnabled(glow);
    if (hud) hud->setNodeMask(~0u);
    osg::ref_ptr<osg::Image> image = osgWater::renderOffscreenFrame(viewer, o.time); // the screenshot is at the start time
    if (!image.valid() || !osgDB::writeImageFile(*image, o.screenshot)) {
        std::cerr << "error: could not write the screenshot " << o.screenshot << std::endl;
        return 1;
    }
    std::cout << "screenshot: " << o.screenshot << std::endl;
    std::cout << "settings: " << describeSettings(*water->getSettings()) << ", " << describeSurface(*water->getSurface())
              << ", caustics " << describeCaustics(*water, water->getViewReport(viewer.getCamera())) << std::endl;
    auto frameMs = [&](const Configuration& c) { return osgWaterApps::medianOfBlockMeans(c.ms, size_t(perBlock)); };
    const double first = frameMs(configs[0]), last = frameMs(configs.back());
    std::printf("frame time, median over %d alternating blocks of the mean of %d frame%s:\n", blocks, perBlock,
                perBlock == 1 ? "" : "s");
    for (const Configuration& c : configs) {
        const double m = frameMs(c);
        std::printf("  %-32s %8.2f ms", c.name.c_str(), m);
        if (o.compareCaustics) std::printf("   x%.3f of caustics off", first > 0 ? m / first : 0.0);
        else if (o.compareGlow) std::printf("   x%.3f of glow off", first > 0 ? m / first : 0.0);
        else if (o.compare) std::printf("   x%.2f of without water", last > 0 ? m / last : 0.0);
        if (!c.causticsMs.empty()) std::printf("   caustics GPU %.2f ms", osgWaterApps::median(c.causticsMs));
        std::printf("\n");
    }
    std::printf("median pass GPU time (%s):", configs[0].name.c_str());
    for (const auto& [pass, ms] : passMs)
        std::printf("%s %s %.2f ms", pass == passMs.begin()->first ? "" : ",", osgWater::gpuTimeLabel(osgWater::PassId(pass)),
                    osgWaterApps::median(ms));
    std::printf("\n");
    return 0;
}

int runWindowed(osgViewer::Viewer& viewer, osgWater::WaterNode* water, osg::Switch* floaters, osg::Switch* pond,
                const LakeOptions& o)
{
    osg::ref_ptr<WalkManipulator> walker = new WalkManipulator;
    walker->setHomePosition(o.eye, o.center, o.up);
    osg::ref_ptr<osgGA::TrackballManipulator> trackball = new osgGA::TrackballManipulator;
    trackball->setHomePosition(o.eye, o.center, o.up);
    osg::ref_ptr<osgGA::KeySwitchMatrixManipulator> manipulators = new osgGA::KeySwitchMatrixManipulator;
    manipulators->addMatrixManipulator('1', "Walk", walker.get());
    manipulators->addMatrixManipulator('2', "Trackball", trackball.get());
    manipulators->setAutoComputeHomePosition(false); // start at --eye/--center, not at the bound's edge
    manipulators->setHomePosition(o.eye, o.center, o.up);
    viewer.setCameraManipulator(manipulators.get());
    // the water's pass GPU times beside OSG's own (press s twice): the WaterNode writes them into
    // the viewer's statistics
    osg::ref_ptr<osgViewer::StatsHandler> stats = new osgViewer::StatsHandler;
    for (int i = 0; i < osgWater::PASS_COUNT; ++i) {
        const char* label = osgWater::gpuTimeLabel(osgWater::PassId(i));
        if (!label) continue;
        stats->addUserStatsLine(label, osg::Vec4(0.4f, 0.8f, 1.0f, 1.0f),
                                osg::Vec4(0.4f, 0.8f, 1.0f, 0.5f), std::string("osgWater ") + label + " GPU ms", 1.0, true, false, "", "", 100.0);
    }
    viewer.addEventHandler(stats.get());
    viewer.addEventHandler(new osgViewer::HelpHandler(osg::ApplicationUsage::instance()));
    osg::ref_ptr<WaterKeys> keys = new WaterKeys(water);
    keys->addToggle('b', floaters, "the buoy and the boat");
    keys->addToggle('p', pond, "the pond above the lake");
    const osg::Vec3d aboveEye = o.underwater ? LakeOptions().eye : o.eye;
    const osg::Vec3d aboveCenter = o.underwater ? LakeOptions().center : o.center;
    keys->setViews(manipulators.get(), osg::Matrixd::inverse(osg::Matrixd::lookAt(aboveEye, aboveCenter, o.up)),
                   osg::Matrixd::inverse(osg::Matrixd::lookAt(o.underwaterEye, o.underwaterCenter, o.up)));
    viewer.addEventHandler(keys.get());
    osg::ref_ptr<osgViewer::ScreenCaptureHandler> capture = new osgViewer::ScreenCaptureHandler(new WriteExactly(o.screenshot));
    viewer.addEventHandler(capture.get());
    viewer.realize();
    std::vector<double> frameMs;
    while (!viewer.done()) {
        const osg::Timer_t t0 = osg::Timer::instance()->tick();
        viewer.frame(o.time + viewer.getFrameStamp()->getReferenceTime());
        frameMs.push_back(osg::Timer::instance()->delta_m(t0, osg::Timer::instance()->tick()));
        if (frameMs.size() == 60) {
            capture->captureNextFrame(viewer); // one screenshot once things have settled ('c' takes more)
            std::cout << "screenshot: " << o.screenshot << std::endl;
        }
    }
    std::printf("median frame time: %.2f ms (%zu frames)\n", osgWaterApps::median(frameMs), frameMs.size());
    return 0;
}

}

int main(int argc, char** argv)
{
    osg::ArgumentParser args(&argc, argv);
    LakeOptions::describe(*args.getApplicationUsage()); // the global usage, shown by the help handler too
    if (args.read("-h") || args.read("--help")) {
        args.getApplicationUsage()->write(std::cout);
        return 0;
    }
    LakeOptions o;
    if (!o.read(args)) return 1;

    const std::string file = findSceneFile(o.scene);
    if (file.empty()) {
        std::cerr << "error: scene file " << o.scene << " not found (build first: the lake's OBJ is generated into data/lake/)" << std::endl;
        return 1;
    }
    std::cout << "scene: " << file << std::endl;
    osg::ref_ptr<osg::Node> loaded = osgDB::readRefNodeFile(file);
    if (!loaded.valid()) {
        std::cerr << "error: could not read " << file << std::endl;
        return 1;
    }
    osg::ref_ptr<osgWater::WaterNode> water = osgWaterApps::findOrAddWater(loaded, file);
    o.apply(*water);
    water->setPassTimingEnabled(true);
    // a buoy and a boat in the default view's water, riding the waves (--floaters, key b)
    osg::ref_ptr<osg::Switch> floaters = osgWaterApps::addFloaters(water.get(), osgWaterApps::kLakeBuoy, osgWaterApps::kLakeBoat, o.floaters);
    // a second body of water on the north rim, above the lake's (--pond, key p)
    osg::ref_ptr<osg::Switch> pond = osgWaterApps::addPond(water.get(), osgWaterApps::kLakePond, o.pond);

    // the same scene without the water (the pond's either), for the frame-time baseline
    osg::ref_ptr<osg::Group> plain = new osg::Group;
    for (unsigned i = 0; i < water->getNumChildren(); ++i)
        if (water->getChild(i) != pond.get()) plain->addChild(water->getChild(i));
    osg::ref_ptr<osg::Switch> scenes = new osg::Switch;
    scenes->addChild(loaded.get(), true);
    scenes->addChild(plain.get(), false);
    osg::ref_ptr<osg::Group> root = new osg::Group;
    root->addChild(scenes.get());

    osgViewer::Viewer viewer(args);
    if (!osgWaterApps::setUpViewer(viewer, o.headless, o.width, o.height)) return 1;
    // headless timing must include the GPU work; a window leaves the final draw callback free for
    // the ScreenCaptureHandler (replacing it while the draw thread runs it would crash)
    if (o.headless) viewer.getCamera()->setFinalDrawCallback(new osgWaterApps::FinishFrame);
    viewer.getCamera()->setClearColor(osg::Vec4(0.55f, 0.7f, 0.9f, 1.0f));
    osg::ref_ptr<osg::Camera> hud = o.hud ? createHud(water.get(), viewer.getCamera(), o.width, o.height) : nullptr;
    if (hud.valid()) root->addChild(hud.get());
    viewer.setSceneData(root.get());
    return o.headless ? runHeadless(viewer, scenes.get(), water.get(), hud.get(), o) : runWindowed(viewer, water.get(), floaters.get(), pond.get(), o);
}
