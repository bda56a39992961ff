// Per-view passes: two views in one CompositeViewer each render their own, correct reflection;
// passes cull (not just clip) subgraphs wholly on the wrong side of the water plane.
#include "node/WaterNodeImpl.h"
#include "GLHarness.h"
#include <osgWater/WaterNode>
#include <osgViewer/CompositeViewer>
#include <osgUtil/CullVisitor>
#include <map>

using namespace testing_gl;
using namespace osgWater;

namespace {

osg::Vec2i mirrorPixel(osg::Camera* cam, const osg::Vec3d& p, int w, int h)
{
    const osg::Vec4d c = osg::Vec4d(p.x(), p.y(), -p.z(), 1.0) * cam->getViewMatrix() * cam->getProjectionMatrix();
    return osg::Vec2i(int((c.x() / c.w() * 0.5 + 0.5) * w), int((c.y() / c.w() * 0.5 + 0.5) * h));
}

// counts, per camera name, how often cull reaches a node
struct CullCounter : public osg::NodeCallback {
    std::map<std::string, int> visits;
    void operator()(osg::Node* node, osg::NodeVisitor* nv) override
    {
        if (osgUtil::CullVisitor* cv = nv->asCullVisitor()) ++visits[cv->getCurrentCamera()->getName()];
        traverse(node, nv);
    }
};

}

TEST(RenderViews, TwoViewsEachGetTheirOwnReflection)
{
    std::string why;
    osg::ref_ptr<osg::GraphicsContext> gc = createPbuffer(64, 64, why);
    ContextProbe probe{ gc.valid(), why };
    REQUIRE_GL(probe);

    osg::ref_ptr<WaterNode> water = new WaterNode;
    water->getSurface()->setWaves({});
    water->getSurface()->setSize(400.0f);
    water->getSettings()->setRefractionEnabled(false);
    water->getSettings()->setReflectionTextureSize(256);
    // red quad north (+y), green quad south (-y)
    water->addChild(emissiveQuad(osg::Vec3(-2, 12, 1), osg::Vec3(2, 12, 1), osg::Vec3(2, 12, 4), osg::Vec3(-2, 12, 4),
                                 osg::Vec4(1, 0, 0, 1)));
    water->addChild(emissiveQuad(osg::Vec3(2, -12, 1), osg::Vec3(-2, -12, 1), osg::Vec3(-2, -12, 4), osg::Vec3(2, -12, 4),
                                 osg::Vec4(0, 1, 0, 1)));

    const int W = 128, H = 96;
    osg::ref_ptr<osgViewer::CompositeViewer> viewer = new osgViewer::CompositeViewer;
    viewer->setThreadingModel(osgViewer::ViewerBase::SingleThreaded);
    viewer->setReleaseContextAtEndOfFrameHint(false);
    osg::ref_ptr<osg::Texture2D> targets[2];
    const osg::Vec3d eyes[2] = { osg::Vec3d(0, 0, 2), osg::Vec3d(0, 0, 2) };
    const osg::Vec3d centers[2] = { osg::Vec3d(0, 12, 0), osg::Vec3d(0, -12, 0) };
    for (int i = 0; i < 2; ++i) {
        osg::ref_ptr<osgViewer::View> view = new osgViewer::View;
        osg::Camera* cam = view->getCamera();
        targets[i] = attachFloatTarget(cam, gc.get(), W, H);
        cam->setClearColor(osg::Vec4(0.2f, 0.3f, 0.8f, 1.0f));
        cam->setComputeNearFarMode(osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR);
        cam->setViewMatrixAsLookAt(eyes[i], centers[i], osg::Vec3d(0, 0, 1));
        cam->setProjectionMatrixAsPerspective(45.0, double(W) / H, 0.1, 500.0);
        view->setSceneData(water.get());
        viewer->addView(view.get());
    }
    viewer->frame(0.0);
    EXPECT_EQ(water->getNumViews(), 2u);

    const osg::Vec4 expected[2] = { osg::Vec4(1, 0, 0, 1), osg::Vec4(0, 1, 0, 1) };
    const osg::Vec3d quadCentre[2] = { osg::Vec3d(0, 12, 2.5), osg::Vec3d(0, -12, 2.5) };
    osg::Texture2D* reflTex[2];
    for (int i = 0; i < 2; ++i) {
        osg::Camera* cam = viewer->getView(i)->getCamera();
        ViewPasses* p = osgWater::internals(*water).getViewPasses(cam);
        ASSERT_TRUE(p);
        reflTex[i] = p->getReflectionCamera()->getColorTexture();
        // the final image shows this view's quad mirrored, in its own colour
        osg::ref_ptr<osg::Image> img = readTexture(gc.get(), targets[i].get());
        ASSERT_TRUE(allFinite(img.get()));
        const osg::Vec2i px = mirrorPixel(cam, quadCentre[i], W, H);
        const float* c = pixel(img.get(), px.x(), px.y());
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(c[k], expected[i][k], 0.02f) << "view " << i << " channel " << k;
        // and its reflection texture holds its own quad only
        osg::ref_ptr<osg::Image> refl = readTexture(gc.get(), reflTex[i]);
        int red = 0, green = 0;
        for (int y = 0; y < refl->t(); ++y)
            for (int x = 0; x < refl->s(); ++x) {
                const float* q = pixel(refl.get(), x, y);
                red += q[0] > 0.9f && q[1] < 0.1f;
                green += q[1] > 0.9f && q[0] < 0.1f;
            }
        EXPECT_GT(i == 0 ? red : green, 50) << "view " << i;
        EXPECT_EQ(i == 0 ? green : red, 0) << "view " << i;
    }
    EXPECT_NE(reflTex[0], reflTex[1]);

    // a view that goes away takes its passes with it
    osg::observer_ptr<osg::Camera> gone = viewer->getView(1)->getCamera();
    viewer->removeView(viewer->getView(1));
    ASSERT_FALSE(gone.valid()) << "the removed view's camera should be deleted";
    viewer->frame(1.0);
    EXPECT_EQ(water->getNumViews(), 1u);
}

TEST(RenderViews, PassesCullSubgraphsWhollyOnTheWrongSide)
{
    Harness h(64, 64);
    REQUIRE_GL(h);
    osg::ref_ptr<WaterNode> water = new WaterNode;
    osg::ref_ptr<osg::Geode> above = emissiveQuad(osg::Vec3(-1, 8, 2), osg::Vec3(1, 8, 2), osg::Vec3(1, 8, 3),
                                                  osg::Vec3(-1, 8, 3), osg::Vec4(1, 0, 0, 1));
    osg::ref_ptr<osg::Geode> below = emissiveQuad(osg::Vec3(-1, 8, -3), osg::Vec3(1, 8, -3), osg::Vec3(1, 8, -2),
                                                  osg::Vec3(-1, 8, -2), osg::Vec4(0, 1, 0, 1));
    osg::ref_ptr<osg::Geode> crossing = emissiveQuad(osg::Vec3(-1, 9, -1), osg::Vec3(1, 9, -1), osg::Vec3(1, 9, 1),
                                                     osg::Vec3(-1, 9, 1), osg::Vec4(0, 0, 1, 1));
    osg::ref_ptr<CullCounter> ca = new CullCounter, cb = new CullCounter, cc = new CullCounter;
    above->setCullCallback(ca.get());
    below->setCullCallback(cb.get());
    crossing->setCullCallback(cc.get());
    water->addChild(above.get());
    water->addChild(below.get());
    water->addChild(crossing.get());
    h.camera()->setName("main");
    h.setScene(water.get());
    h.lookAt(osg::Vec3d(0, 0, 1.5), osg::Vec3d(0, 8, 0));
    h.frame(0.0);
    EXPECT_EQ(ca->visits["main"], 1);
    EXPECT_EQ(ca->visits["osgWater.ReflectionCamera"], 1);
    EXPECT_EQ(ca->visits["osgWater.RefractionCamera"], 0);
    EXPECT_EQ(cb->visits["main"], 1);
    EXPECT_EQ(cb->visits["osgWater.ReflectionCamera"], 0);
    EXPECT_EQ(cb->visits["osgWater.RefractionCamera"], 1);
    EXPECT_EQ(cc->visits["osgWater.ReflectionCamera"], 1); // crossing the plane: drawn and clipped by both
    EXPECT_EQ(cc->visits["osgWater.RefractionCamera"], 1);
}

TEST(RenderViews, NoPassesWhenTheWaterIsOutOfView)
{
    Harness h(64, 64);
    REQUIRE_GL(h);
    osg::ref_ptr<WaterNode> water = new WaterNode;
    water->getSurface()->setSize(10.0f);
    osg::ref_ptr<osg::Geode> sky = emissiveQuad(osg::Vec3(-1, 8, 20), osg::Vec3(1, 8, 20), osg::Vec3(1, 8, 22),
                                                osg::Vec3(-1, 8, 22), osg::Vec4(1, 0, 0, 1));
    osg::ref_ptr<CullCounter> counter = new CullCounter;
    sky->setCullCallback(counter.get());
    water->addChild(sky.get());
    h.camera()->setName("main");
    h.setScene(water.get());
    h.lookAt(osg::Vec3d(0, 0, 21), osg::Vec3d(0, 8, 21), 30.0); // looking at the horizon, water below the view
    h.frame(0.0);
    EXPECT_EQ(counter->visits["main"], 1);
    EXPECT_EQ(counter->visits["osgWater.ReflectionCamera"], 0);
    EXPECT_EQ(osgWater::internals(*water).getViewPasses(h.camera()), nullptr);
    EXPECT_EQ(osgWater::internals(*water).getPassPlan(h.camera()).describe(), "scene") << "nothing but the scene under its lighting";
    // and in view again, the plan says so
    h.lookAt(osg::Vec3d(0, 0, 21), osg::Vec3d(0, 8, 0), 30.0);
    h.frame(0.0);
    EXPECT_TRUE(osgWater::internals(*water).getPassPlan(h.camera()).runs(PASS_SURFACE));
}

TEST(RenderViews, PassTargetsScaledToTheViewShadeFlatWaterAsTheOpticsMirrorDoes)
{
    // a wide view and targets of its own size: rectangular targets, the view's aspect, read through
    // the same matrices; the shading still eq. 9 of eq. 5 of the bed and the sky. Tolerance 0.02:
    // 8-bit targets, and the search's nearest depth texel (100 rows here, against 512 for the fixed
    // squares, where 0.01 holds) moves the bottom, so the path under water, by up to a texel
    Harness h(200, 100);
    REQUIRE_GL(h);
    osg::ref_ptr<WaterNode> water = flatWaterOverBed(1.5f);
    water->getSettings()->setAttenuation(0.3f);
    water->getSettings()->setPassTargetScale(1.0f);
    h.setScene(water.get());
    h.lookAt(osg::Vec3d(0, -3, 2.5), osg::Vec3d(0, 8, -1.5));
    h.frame(0.0);
    ViewPasses* p = osgWater::internals(*water).getViewPasses(h.camera());
    ASSERT_NE(p, nullptr);
    for (const PassCamera* c : { static_cast<PassCamera*>(p->getReflectionCamera()), static_cast<PassCamera*>(p->getRefractionCamera()) }) {
        EXPECT_EQ(c->getTargetWidth(), 200);
        EXPECT_EQ(c->getTargetHeight(), 100);
        EXPECT_EQ(c->getColorTexture()->getTextureWidth(), 200);
        EXPECT_EQ(c->getColorTexture()->getTextureHeight(), 100);
    }
    osg::ref_ptr<osg::Image> img = h.readColor();
    const MirrorComparison m = compareFlatWaterWithOptics(h, img.get(), *water->getSettings(), osg::Matrixd::identity(),
                                                          0.0, -1.5, kBedGrey, 5);
    EXPECT_FALSE(m.bedMissed);
    EXPECT_GT(m.checked, 100);
    EXPECT_LT(m.worst, 0.02);

    // half the view per axis
    water->getSettings()->setPassTargetScale(0.5f);
    h.frame(0.0);
    EXPECT_EQ(osgWater::internals(*water).getViewPasses(h.camera())->getReflectionCamera()->getTargetWidth(), 100);
    EXPECT_EQ(osgWater::internals(*water).getViewPasses(h.camera())->getReflectionCamera()->getTargetHeight(), 50);

    // 0: the fixed squares again
    water->getSettings()->setPassTargetScale(0.0f);
    h.frame(0.0);
    EXPECT_EQ(osgWater::internals(*water).getViewPasses(h.camera())->getRefractionCamera()->getTargetWidth(), 512);
    EXPECT_EQ(osgWater::internals(*water).getViewPasses(h.camera())->getRefractionCamera()->getTargetHeight(), 512);
}
