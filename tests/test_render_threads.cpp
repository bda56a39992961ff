// Every OSG threading model: a CompositeViewer with views in two contexts (and, for a while, two
// views in one context, whose culls run in parallel under CullThreadPerCameraDrawThreadPerContext),
// views added and removed, 220 frames at fixed simulation times. Each view's image at the
// checkpoints must be the SingleThreaded run's, no GL error, no crash.
#include "node/WaterNodeImpl.h"
#include "GLHarness.h"
#include <osgWater/WaterNode>
#include <osgViewer/CompositeViewer>
#include <osgViewer/Renderer>
#include <osgUtil/RenderStage>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <map>

using namespace testing_gl;
using namespace osgWater;

namespace {

const int kW = 64, kH = 48, kFrames = 220;

struct ViewSlot {
    osg::ref_ptr<osgViewer::View> view;
    osg::ref_ptr<osg::Texture2D> target;
    osg::GraphicsContext* gc = nullptr;
};

osg::ref_ptr<WaterNode> makeWater()
{
    osg::ref_ptr<WaterNode> water = new WaterNode;
    water->getSurface()->setSize(40.0f);
    WaterSettings* s = water->getSettings();
    s->setSunDirection(osg::Vec3(0.2f, 0.9f, 0.39f)); // low ahead: the glow in view
    s->setReflectionTextureSize(64);
    s->setRefractionTextureSize(64);
    s->setCausticsResolution(32);
    s->setPhotonGridSize(32);
    s->setCausticsGather(WaterSettings::GATHER_POINTS_TEXTURE); // the automatic choice times the GPU
    water->addChild(checkerPlane(-2.0f, 40.0f, 1.0f));
    water->addChild(emissiveQuad(osg::Vec3(-1, 6, -2), osg::Vec3(1, 6, -2), osg::Vec3(1, 6, 2), osg::Vec3(-1, 6, 2),
                                 osg::Vec4(1, 0.5f, 0, 1)));
    return water;
}

ViewSlot makeView(osg::GraphicsContext* gc, osg::Node* scene, const osg::Vec3d& eye, const osg::Vec3d& centre)
{
    ViewSlot v;
    v.gc = gc;
    v.view = new osgViewer::View;
    osg::Camera* cam = v.view->getCamera();
    v.target = attachFloatTarget(cam, gc, kW, kH);
    cam->setClearColor(osg::Vec4(0.2f, 0.3f, 0.8f, 1.0f));
    cam->setComputeNearFarMode(osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR);
    cam->setViewMatrixAsLookAt(eye, centre, osg::Vec3d(0, 0, 1));
    cam->setProjectionMatrixAsPerspective(50.0, double(kW) / kH, 0.05, 500.0);
    v.view->setSceneData(scene);
    return v;
}

// every leaf of a render bin, its sub-bins and (for a stage) its pre- and post-render stages
void countLeaves(const osgUtil::RenderBin* bin, int& all, int& dynamic)
{
    for (const auto& b : bin->getRenderBinList()) countLeaves(b.second.get(), all, dynamic);
    for (const osgUtil::RenderLeaf* leaf : bin->getRenderLeafList()) {
        ++all;
        dynamic += leaf->_dynamic;
    }
    for (const osgUtil::StateGraph* sg : bin->getStateGraphList())
        for (const auto& leaf : sg->_leaves) {
            ++all;
            dynamic += leaf->_dynamic;
        }
    if (const osgUtil::RenderStage* stage = dynamic_cast<const osgUtil::RenderStage*>(bin)) {
        for (const auto& pre : stage->getPreRenderList()) countLeaves(pre.second.get(), all, dynamic);
        for (const auto& post : stage->getPostRenderList()) countLeaves(post.second.get(), all, dynamic);
    }
}

// (checkpoint frame, view name) -> image
typedef std::map<std::pair<int, std::string>, osg::ref_ptr<osg::Image>> Images;

// the run's images, or none with `why` when no context could be made
Images run(osgViewer::ViewerBase::ThreadingModel model, std::string& why)
{
    // fresh contexts: a viewer closes its contexts when it goes
    osg::ref_ptr<osg::GraphicsContext> gc1 = createPbuffer(kW, kH, why);
    osg::ref_ptr<osg::GraphicsContext> gc2 = gc1.valid() ? createPbuffer(kW, kH, why) : nullptr;
    if (!gc1.valid() || !gc2.valid()) return Images();
    osg::ref_ptr<WaterNode> water = makeWater();
    osg::ref_ptr<osgViewer::CompositeViewer> viewer = new osgViewer::CompositeViewer;
    viewer->setThreadingModel(model);
    viewer->setReleaseContextAtEndOfFrameHint(false);
    std::map<std::string, ViewSlot> views;
    auto add = [&](const std::string& name, osg::GraphicsContext* gc, const osg::Vec3d& eye, const osg::Vec3d& c) {
        views[name] = makeView(gc, water.get(), eye, c);
        viewer->addView(views[name].view.get());
    };
    auto remove = [&](const std::string& name) {
        // the view and its camera go while no thread runs (a camera destroyed while a draw
        // thread starts its context's operations leaves that thread a dangling camera)
        viewer->stopThreading();
        viewer->removeView(views[name].view.get());
        views.erase(name);
        viewer->startThreading();
    };
    add("above", gc1.get(), osg::Vec3d(0, -10, 3), osg::Vec3d(0, 5, -1));
    add("below", gc2.get(), osg::Vec3d(1, -6, -1), osg::Vec3d(0, 6, 0.5));
    Images images;
    for (int i = 0; i < kFrames; ++i) {
        if (i == 60) remove("below");
        if (i == 100) add("below again", gc2.get(), osg::Vec3d(-2, -8, 1.5), osg::Vec3d(2, 4, -1));
        if (i == 140) add("second in context 1", gc1.get(), osg::Vec3d(3, -9, 0.4), osg::Vec3d(-2, 6, 0));
        if (i == 180) remove("second in context 1");
        if (std::getenv("OSGWATER_TEST_VERBOSE")) std::cout << "frame " << i << std::endl;
        viewer->frame(i / 30.0);
        if (i == 59 || i == 99 || i == 139 || i == 179 || i == kFrames - 1) {
            // the draw threads finish and let go of their contexts; this thread reads the targets
            viewer->stopThreading();
            for (auto& v : views) images[{ i, v.first }] = readTexture(v.second.gc, v.second.target.get());
            gc1->releaseContext();
            gc2->releaseContext();
            viewer->startThreading();
        }
    }
    viewer->stopThreading();
    return images;
}

}

TEST(RenderThreads, EveryThreadingModelRendersTheSingleThreadedImages)
{
    std::string why;
    const Images reference = run(osgViewer::ViewerBase::SingleThreaded, why);
    ContextProbe probe{ !reference.empty(), why };
    REQUIRE_GL(probe);
    ASSERT_EQ(reference.size(), 10u); // the views present at frames 59, 99, 139, 179, 219
    for (const auto& r : reference) {
        ASSERT_TRUE(r.second.valid()) << r.first.second << " at frame " << r.first.first;
        EXPECT_TRUE(allFinite(r.second.get()));
    }
    const std::pair<osgViewer::ViewerBase::ThreadingModel, const char*> models[] = {
        { osgViewer::ViewerBase::CullDrawThreadPerContext, "CullDrawThreadPerContext" },
        { osgViewer::ViewerBase::DrawThreadPerContext, "DrawThreadPerContext" },
        { osgViewer::ViewerBase::CullThreadPerCameraDrawThreadPerContext, "CullThreadPerCameraDrawThreadPerContext" },
    };
    for (const auto& m : models) {
        const Images images = run(m.first, why);
        ASSERT_EQ(images.size(), reference.size()) << m.second;
        float worst = 0.0f;
        for (const auto& r : reference) {
            const osg::Image* a = r.second.get();
            const osg::Image* b = images.at(r.first).get();
            ASSERT_TRUE(b) << m.second << ": " << r.first.second << " at frame " << r.first.first;
            float d = 0.0f;
            for (int y = 0; y < a->t(); ++y)
                for (int x = 0; x < a->s(); ++x)
                    for (int k = 0; k < 4; ++k) d = std::max(d, std::fabs(pixel(a, x, y)[k] - pixel(b, x, y)[k]));
            EXPECT_LE(d, 1.0f / 255.0f) << m.second << ": " << r.first.second << " at frame " << r.first.first;
            worst = std::max(worst, d);
        }
        std::cout << m.second << ": largest difference from SingleThreaded " << worst << std::endl;
    }
}

TEST(RenderThreads, EveryLeafDrawnUnderTheKitsStateIsDynamic)
{
    // DrawThreadPerContext starts the next frame's update and cull once the DYNAMIC leaves are
    // drawn: every state set the kit writes per frame (lighting, pass uniforms, the settings' state
    // in the update traversal) must be DYNAMIC, so every leaf drawn under one is. Checked in the
    // render stages of the last frame, with the water out of view, in view (every pass, glow
    // included) and from under water.
    Harness h(64, 48);
    REQUIRE_GL(h);
    osg::ref_ptr<WaterNode> water = makeWater();
    water->addChild(litQuad(osg::Vec3(-3, 10, 8), osg::Vec3(3, 10, 8), osg::Vec3(3, 10, 14), osg::Vec3(-3, 10, 14)));
    h.setScene(water.get());
    struct Case { const char* name; osg::Vec3d eye, centre; };
    const Case cases[] = { { "out of view", osg::Vec3d(0, -10, 3), osg::Vec3d(0, 10, 15) },
                           { "in view", osg::Vec3d(0, -10, 3), osg::Vec3d(0, 5, -1) },
                           { "under water", osg::Vec3d(1, -6, -1), osg::Vec3d(0, 6, 0.5) } };
    osgViewer::Renderer* renderer = dynamic_cast<osgViewer::Renderer*>(h.camera()->getRenderer());
    ASSERT_TRUE(renderer);
    for (const Case& c : cases) {
        h.lookAt(c.eye, c.centre);
        h.frame(1.0);
        h.frame(1.1);
        int all = 0, dynamic = 0;
        for (unsigned int i = 0; i < 2; ++i)
            if (osgUtil::SceneView* sv = renderer->getSceneView(i))
                if (sv->getRenderStage()) countLeaves(sv->getRenderStage(), all, dynamic);
        EXPECT_GT(all, 0) << c.name;
        EXPECT_EQ(dynamic, all) << c.name << ": leaves OSG would not wait for";
    }
    ASSERT_TRUE(osgWater::internals(*water).getViewPasses(h.camera()) && osgWater::internals(*water).getViewPasses(h.camera())->getGlow());
}
