// Leaks: WaterNodes made and dropped, views added and removed, and thousands of frames leave the
// number of GL textures, framebuffers, renderbuffers, buffers, programs and queries where it was. (Memory leaks are
// LeakSanitizer's part: this suite runs under scripts/sanitize.sh like every other.)
#include "GLHarness.h"
#include <osgWater/WaterNode>
#include <osgViewer/CompositeViewer>
#include <osg/GLExtensions>
#include <osg/GLObjects>
#include <cmath>
#include <cstdlib>
#include <iostream>

using namespace testing_gl;
using namespace osgWater;

namespace {

osgViewer::View* makeView(osg::GraphicsContext* gc, osg::Node* scene, osg::ref_ptr<osg::Texture2D>& target, double yaw)
{
    osgViewer::View* view = new osgViewer::View;
    osg::Camera* cam = view->getCamera();
    target = attachFloatTarget(cam, gc, 32, 32);
    cam->setComputeNearFarMode(osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR);
    const osg::Vec3d eye(0.0, 0.0, 3.0);
    cam->setViewMatrixAsLookAt(eye, eye + osg::Vec3d(std::sin(yaw), std::cos(yaw), -0.4), osg::Vec3d(0, 0, 1));
    cam->setProjectionMatrixAsPerspective(50.0, 1.0, 0.05, 500.0);
    view->setSceneData(scene);
    return view;
}

// a lake with every pass on, its targets small so thousands of frames stay quick
osg::ref_ptr<WaterNode> makeWater(osg::Node* bed)
{
    osg::ref_ptr<WaterNode> water = new WaterNode;
    water->getSurface()->setSize(60.0f);
    WaterSettings* s = water->getSettings();
    s->setReflectionTextureSize(32);
    s->setRefractionTextureSize(32);
    s->setCausticsResolution(32);
    s->setPhotonGridSize(16);
    s->setCausticsEnabled(true);
    s->setGlowEnabled(true);
    water->addChild(bed);
    return water;
}

int envCount(const char* name, int fallback)
{
    const char* v = std::getenv(name);
    return v ? std::max(1, std::atoi(v)) : fallback;
}

}

TEST(RenderLeaks, WaterNodesViewsAndFramesLeaveTheGLObjectCountConstant)
{
    // OSGWATER_LEAK_NODES / _VIEWS / _FRAMES shorten the run while developing
    const int nodes = envCount("OSGWATER_LEAK_NODES", 1000), views = envCount("OSGWATER_LEAK_VIEWS", 100),
              frames = envCount("OSGWATER_LEAK_FRAMES", 10000);
    std::string why;
    osg::ref_ptr<osg::GraphicsContext> gc = createPbuffer(32, 32, why);
    ContextProbe probe{ gc.valid(), why };
    REQUIRE_GL(probe);

    osg::ref_ptr<osg::Node> bed = checkerPlane(-2.0f, 60.0f, 1.0f);
    osg::ref_ptr<WaterNode> water = makeWater(bed.get());
    osg::ref_ptr<osgViewer::CompositeViewer> viewer = new osgViewer::CompositeViewer;
    viewer->setThreadingModel(osgViewer::ViewerBase::SingleThreaded);
    viewer->setReleaseContextAtEndOfFrameHint(false);
    osg::ref_ptr<osg::Texture2D> mainTarget, extraTarget;
    osgViewer::View* main = makeView(gc.get(), water.get(), mainTarget, 0.0);
    viewer->addView(main);
    double t = 0.0;
    auto run = [&](int n) {
        for (int i = 0; i < n; ++i) viewer->frame(t += 1.0 / 60.0);
    };
    // OSG deletes released GL objects at the end of later frames, within a time budget: a few
    // frames with nothing new let it catch up before counting
    const int settle = 10;
    GLuint highest = 0;
    // warm-up: the automatic caustics gather times each path over its first frames, then keeps one
    run(200);
    const GLCounts baseline = countGLObjects(gc.get(), highest);
    std::cout << "baseline: " << baseline << std::endl;
    EXPECT_GT(baseline.textures, 4) << "the passes' targets should be counted";
    EXPECT_GT(baseline.framebuffers, 2);

    // 1. WaterNodes made, drawn once and dropped
    for (int i = 0; i < nodes; ++i) {
        osg::ref_ptr<WaterNode> w = makeWater(bed.get());
        main->setSceneData(w.get());
        run(1);
    }
    main->setSceneData(water.get());
    run(settle);
    const GLCounts afterNodes = countGLObjects(gc.get(), highest);
    std::cout << "after " << nodes << " WaterNodes: " << afterNodes << std::endl;
    EXPECT_EQ(afterNodes, baseline) << "WaterNodes left GL objects behind";

    // the image at one time, to compare after the views come and go (a pass drawn once and
    // released with a removed view must come back)
    auto imageAt = [&](double when) {
        viewer->frame(when);
        return readTexture(gc.get(), mainTarget.get());
    };
    osg::ref_ptr<osg::Image> before = imageAt(100.0);

    // 2. a second view added, drawn and removed
    for (int i = 0; i < views; ++i) {
        viewer->addView(makeView(gc.get(), water.get(), extraTarget, 0.1 * i));
        run(2);
        EXPECT_EQ(water->getNumViews(), 2u);
        viewer->removeView(viewer->getView(1));
        extraTarget = nullptr;
        run(1);
        EXPECT_EQ(water->getNumViews(), 1u);
    }
    run(settle);
    const GLCounts afterViews = countGLObjects(gc.get(), highest);
    std::cout << "after " << views << " views: " << afterViews << std::endl;
    osg::ref_ptr<osg::Image> after = imageAt(100.0);
    float worst = 0.0f;
    for (int y = 0; y < after->t(); ++y)
        for (int x = 0; x < after->s(); ++x)
            for (int k = 0; k < 3; ++k) worst = std::max(worst, std::fabs(pixel(after.get(), x, y)[k] - pixel(before.get(), x, y)[k]));
    EXPECT_LE(worst, 1e-5f) << "the main view's image changed after views came and went";
    EXPECT_EQ(afterViews, baseline) << "removed views left GL objects behind";

    // 3. frames: the count never moves
    run(frames);
    run(settle);
    const GLCounts afterFrames = countGLObjects(gc.get(), highest);
    std::cout << "after " << frames << " frames: " << afterFrames << std::endl;
    EXPECT_EQ(afterFrames, baseline) << "frames left GL objects behind";
    EXPECT_LT(highest, kNames - 1024) << "names reached the counted range's end: raise kNames";
}
