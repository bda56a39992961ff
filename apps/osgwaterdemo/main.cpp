// osgwaterdemo: a small lake with osgWater, windowed or headless. Prints the median frame time
// with and without the water, measured in one run (alternating blocks), and writes a screenshot.
#include "DemoScene.h"
#include "../common/FrameTimer.h"
#include <osgWater/WaterNode>
#include <osgDB/WriteFile>
#include <osgDB/FileNameUtils>
#include <osgGA/TrackballManipulator>
#include <osgViewer/ViewerEventHandlers>
#include <osg/ArgumentParser>
#include <osg/Switch>
#include <osg/Timer>
#include <cstdio>
#include <iostream>

int main(int argc, char** argv)
{
    osg::ArgumentParser args(&argc, argv);
    args.getApplicationUsage()->setDescription("osgWater demo: a small procedural lake");
    args.getApplicationUsage()->addCommandLineOption("--headless", "Render off-screen (pbuffer) and exit");
    args.getApplicationUsage()->addCommandLineOption("--frames <n>", "Frames per scene in headless mode (default 60)");
    args.getApplicationUsage()->addCommandLineOption("--size <w> <h>", "Window or image size (default 800 600)");
    args.getApplicationUsage()->addCommandLineOption("--screenshot <file>", "Screenshot file (default osgwaterdemo.png)");
    args.getApplicationUsage()->addCommandLineOption("--dump-passes <prefix>", "Headless: also write the pass textures");
    args.getApplicationUsage()->addCommandLineOption("--eye <x> <y> <z>", "Eye position");
    args.getApplicationUsage()->addCommandLineOption("--center <x> <y> <z>", "Point looked at");
    if (args.read("-h") || args.read("--help")) {
        args.getApplicationUsage()->write(std::cout);
        return 0;
    }
    const bool headless = args.read("--headless");
    int frames = 60, width = 800, height = 600;
    std::string shot = "osgwaterdemo.png";
    osg::Vec3d eye(-30, -30, 6), center(0, 0, -1);
    args.read("--frames", frames);
    args.read("--size", width, height);
    args.read("--screenshot", shot);
    std::string dumpPasses;
    args.read("--dump-passes", dumpPasses);
    args.read("--eye", eye.x(), eye.y(), eye.z());
    args.read("--center", center.x(), center.y(), center.z());
    args.reportRemainingOptionsAsUnrecognized();
    if (args.errors()) {
        args.writeErrorMessages(std::cerr);
        return 1;
    }
    frames = std::max(frames, 2);

    osg::ref_ptr<osg::Group> scene = createDemoScene();
    osg::ref_ptr<osgWater::WaterNode> water = new osgWater::WaterNode;
    water->getSurface()->setSize(90.0f);
    water->addChild(scene.get());
    osg::ref_ptr<osg::Group> plain = new osg::Group;   // same scene, no water: the baseline
    plain->addChild(scene.get());
    osg::ref_ptr<osg::Switch> root = new osg::Switch;
    root->addChild(water.get(), true);
    root->addChild(plain.get(), false);

    osgViewer::Viewer viewer;
    if (!osgWaterApps::setUpViewer(viewer, headless, width, height)) return 1;
    viewer.getCamera()->setFinalDrawCallback(new osgWaterApps::FinishFrame);
    viewer.getCamera()->setClearColor(osg::Vec4(0.55f, 0.7f, 0.9f, 1.0f));
    viewer.setSceneData(root.get());

    std::vector<double> waterMs, plainMs;
    osg::ref_ptr<osg::Image> image;
    if (headless) {
        viewer.getCamera()->setViewMatrixAsLookAt(eye, center, osg::Vec3d(0, 0, 1));
        // alternate blocks of water / plain frames so drifts in machine load hit both alike
        const int blocks = 5, perBlock = std::max(frames / blocks, 1);
        double t = 0.0;
        for (int b = 0; b < blocks; ++b)
            for (int which = 0; which < 2; ++which) {
                root->setSingleChildOn(which);
                for (int i = 0; i < perBlock + 1; ++i) {
                    const osg::Timer_t t0 = osg::Timer::instance()->tick();
                    viewer.frame(t += 1.0 / 60.0);
                    const double ms = osg::Timer::instance()->delta_m(t0, osg::Timer::instance()->tick());
                    if (i > 0) (which == 0 ? waterMs : plainMs).push_back(ms); // first frame after a switch warms up
                }
            }
        root->setSingleChildOn(0);
        image = osgWaterApps::captureFrame(viewer, t + 1.0 / 60.0);
        if (!dumpPasses.empty()) {
            // the pass textures of this view, for looking at what the water shader reads
            osgWater::ViewPasses* p = water->getViewPasses(viewer.getCamera());
            osg::GraphicsContext* gc = viewer.getCamera()->getGraphicsContext();
            if (p) {
                osgDB::writeImageFile(*osgWaterApps::readTexture(gc, p->getReflectionCamera()->getColorTexture()), dumpPasses + "reflection.png");
                osgDB::writeImageFile(*osgWaterApps::readTexture(gc, p->getRefractionCamera()->getColorTexture()), dumpPasses + "refraction.png");
                osgDB::writeImageFile(*osgWaterApps::readTexture(gc, p->getRefractionCamera()->getDepthTexture()), dumpPasses + "depth.png");
            }
        }
    } else {
        osgGA::TrackballManipulator* manip = new osgGA::TrackballManipulator;
        manip->setHomePosition(eye, center, osg::Vec3d(0, 0, 1));
        viewer.setCameraManipulator(manip);
        viewer.addEventHandler(new osgViewer::StatsHandler);
        // screenshot of the 60th frame (and on 'c'), through OSG's own capture handler
        osg::ref_ptr<osgViewer::ScreenCaptureHandler::WriteToFile> writer = new osgViewer::ScreenCaptureHandler::WriteToFile(
            osgDB::getNameLessExtension(shot), osgDB::getFileExtension(shot), osgViewer::ScreenCaptureHandler::WriteToFile::OVERWRITE);
        osg::ref_ptr<osgViewer::ScreenCaptureHandler> capture = new osgViewer::ScreenCaptureHandler(writer.get());
        viewer.addEventHandler(capture.get());
        viewer.realize();
        while (!viewer.done()) {
            const osg::Timer_t t0 = osg::Timer::instance()->tick();
            viewer.frame();
            waterMs.push_back(osg::Timer::instance()->delta_m(t0, osg::Timer::instance()->tick()));
            if (waterMs.size() == 60) {
                capture->captureNextFrame(viewer);
                std::cout << "screenshot: " << shot << std::endl;
            }
        }
    }

    if (image.valid() && osgDB::writeImageFile(*image, shot)) std::cout << "screenshot: " << shot << std::endl;
    const double w = osgWaterApps::median(waterMs), p = osgWaterApps::median(plainMs);
    std::printf("median frame time: water %.2f ms (%zu frames)", w, waterMs.size());
    if (!plainMs.empty()) std::printf(", plain scene %.2f ms (%zu frames), ratio %.2f", p, plainMs.size(), p > 0 ? w / p : 0.0);
    std::printf("\n");
    return 0;
}
