// The pass table: which passes a view runs follows from the frame's facts and from what reads what;
// render orders, bins and texture units come from the table. No GPU.
#include "frame/PassTable.h"
#include <gtest/gtest.h>
#include <set>

using namespace osgWater;

namespace {

FrameFacts inView()
{
    FrameFacts f;
    f.waterInView = true;
    f.caustics = true;
    f.glowInView = true;
    f.environment = true;
    f.environmentStale = true;
    return f;
}

std::set<PassId> runs(const FrameFacts& f)
{
    std::set<PassId> s;
    const PassPlan plan = planPasses(f);
    for (int i = 0; i < PASS_COUNT; ++i)
        if (plan.runs(PassId(i))) s.insert(PassId(i));
    return s;
}

}

TEST(PassTable, RowsAreInDrawingOrderAndEveryReadIsWrittenByAnEarlierRow)
{
    unsigned written = RES_WAVES; // the one input from outside the frame's rows
    for (int i = 0; i < PASS_COUNT; ++i) {
        const PassRow& row = passTable()[i];
        EXPECT_EQ(row.id, PassId(i)) << row.name;
        EXPECT_EQ(&passRow(PassId(i)), &row);
        EXPECT_EQ(row.reads & ~written, 0u) << row.name << " reads what no earlier row writes";
        EXPECT_NE(row.writes, 0u) << row.name;
        written |= row.writes;
    }
    EXPECT_TRUE(written & RES_VIEW_IMAGE);
}

TEST(PassTable, RenderOrdersAndBinsFollowTheTable)
{
    int lastOrder = -1000, lastBin = 10; // overlays after OSG's transparent bin
    for (int i = 0; i < PASS_COUNT; ++i) {
        const PassRow& row = passTable()[i];
        if (row.stage == STAGE_PRE_RENDER) {
            EXPECT_GT(renderOrder(row.id), lastOrder) << row.name;
            lastOrder = renderOrder(row.id);
        } else if (row.stage == STAGE_OVERLAY) {
            EXPECT_GT(renderBin(row.id), lastBin) << row.name;
            lastBin = renderBin(row.id);
        } else if (row.stage == STAGE_UNDERLAY) {
            EXPECT_LT(renderBin(row.id), 0) << row.name << ": before the scene's opaque bin";
        }
    }
    // the units the scene and water programs sample at once never collide
    const std::set<int> units = { UNIT_BASE, UNIT_REFLECTION, UNIT_REFRACTION, UNIT_REFRACTION_DEPTH, UNIT_CAUSTICS,
                                  UNIT_SUN_DEPTH, UNIT_ENVIRONMENT, UNIT_REFLECTED_CAUSTICS, UNIT_REFLECTED_SUN_DEPTH,
                                  UNIT_REFLECTION_DEPTH };
    EXPECT_EQ(units.size(), 10u);
}

TEST(PassTable, EverythingRunsWithTheWaterInViewAndEveryEffectOn)
{
    const std::set<PassId> r = runs(inView());
    for (int i = 0; i < PASS_COUNT; ++i)
        if (PassId(i) != PASS_BACKDROP) EXPECT_TRUE(r.count(PassId(i))) << passRow(PassId(i)).name;
    EXPECT_FALSE(r.count(PASS_BACKDROP)) << "the backdrop is for an eye under water";
    FrameFacts below = inView();
    below.eyeBelow = true;
    EXPECT_TRUE(runs(below).count(PASS_BACKDROP));
}

TEST(PassTable, WithTheWaterOutOfViewOnlyTheSceneRuns)
{
    FrameFacts f = inView();
    f.waterInView = false;
    EXPECT_EQ(planPasses(f).describe(), "scene");
    EXPECT_FALSE(planPasses(f).usesViewPasses()) << "no view passes made for the scene alone";
    // nothing sees under the water: the caustics are read by no pass, so they do not run
    EXPECT_FALSE(planPasses(f).runs(PASS_PHOTONS));
    // under water the view sees the underwater scene even with the surface out of view
    f.eyeBelow = true;
    EXPECT_EQ(planPasses(f).describe(), "sun depth, photons, gather, scene, backdrop");
    EXPECT_TRUE(planPasses(f).usesViewPasses()); // the backdrop reads this view's water inputs
}

TEST(PassTable, APassNothingReadsDoesNotRun)
{
    FrameFacts f = inView();
    f.glowInView = false; // the composite is not wanted: neither are its blurs nor the highlight
    const std::set<PassId> r = runs(f);
    EXPECT_FALSE(r.count(PASS_GLOW_COMPOSITE));
    EXPECT_FALSE(r.count(PASS_GLOW_BLUR_H));
    EXPECT_FALSE(r.count(PASS_GLOW_BLUR_V));
    EXPECT_FALSE(r.count(PASS_GLOW_HIGHLIGHT));
    f.caustics = false; // no caustics: neither their three passes
    EXPECT_EQ(planPasses(f).describe(), "environment, reflection, refraction, surface, scene, near-plane cap");
}

TEST(PassTable, SharedCausticsRunOncePerFrameAndTheSunDepthOnlyWhenStale)
{
    FrameFacts f = inView();
    f.sunDepthStale = false;
    std::set<PassId> r = runs(f);
    EXPECT_TRUE(r.count(PASS_PHOTONS) && r.count(PASS_GATHER));
    EXPECT_FALSE(r.count(PASS_SUN_DEPTH));
    f.causticsDone = true; // another view rendered them this frame
    r = runs(f);
    EXPECT_FALSE(r.count(PASS_PHOTONS) || r.count(PASS_GATHER) || r.count(PASS_SUN_DEPTH));
    EXPECT_TRUE(r.count(PASS_SCENE) && r.count(PASS_REFRACTION));
}

TEST(PassTable, SwitchedOffPassesDoNotRun)
{
    FrameFacts f = inView();
    f.reflectionEnabled = false;
    EXPECT_FALSE(planPasses(f).runs(PASS_REFLECTION));
    EXPECT_TRUE(planPasses(f).runs(PASS_REFRACTION));
    f.refractionEnabled = false;
    EXPECT_FALSE(planPasses(f).runs(PASS_REFRACTION));
    EXPECT_TRUE(planPasses(f).runs(PASS_SURFACE));
}

TEST(PassTable, TheEnvironmentMapIsDrawnOnlyWhenStaleAndTheWaterIsSeen)
{
    FrameFacts f = inView();
    EXPECT_TRUE(planPasses(f).runs(PASS_ENVIRONMENT));
    f.environmentStale = false; // drawn on this context before, nothing changed since
    EXPECT_FALSE(planPasses(f).runs(PASS_ENVIRONMENT));
    f = inView();
    f.waterInView = false; // nothing reads it
    EXPECT_FALSE(planPasses(f).runs(PASS_ENVIRONMENT));
    f = inView();
    f.environment = false; // a map of the user's, or none
    EXPECT_FALSE(planPasses(f).runs(PASS_ENVIRONMENT));
}

TEST(PassTable, TheWavesAreReadOnlyWhereARunningPassDrawsOrReadsTheSurface)
{
    FrameFacts f = inView();
    EXPECT_TRUE(planPasses(f).reads(RES_WAVES));
    f.caustics = f.glowInView = false;
    f.reflectionEnabled = f.refractionEnabled = false;
    EXPECT_TRUE(planPasses(f).reads(RES_WAVES)) << "the surface itself";
    f = inView();
    f.waterInView = false; // the scene alone
    EXPECT_FALSE(planPasses(f).reads(RES_WAVES));
    f.reflectedCaustics = true; // the photons' grid is the surface seen from the sun
    EXPECT_TRUE(planPasses(f).reads(RES_WAVES));
    f.causticsDone = true;      // ... unless the caustics of an earlier frame still hold
    EXPECT_FALSE(planPasses(f).reads(RES_WAVES));
    f = inView();
    f.waterInView = false;
    f.eyeBelow = true;
    f.causticsInScene = true;   // the scene program makes the caustics from the waves
    EXPECT_EQ(planPasses(f).describe(), "sun depth, scene, backdrop");
    EXPECT_TRUE(planPasses(f).reads(RES_WAVES));
    f.caustics = false;
    EXPECT_FALSE(planPasses(f).reads(RES_WAVES));
}

TEST(PassTable, ReflectiveCausticsAreRenderedForAViewThatSeesOnlyTheSceneAboveTheWater)
{
    FrameFacts f;
    f.caustics = true; // the water out of view, the eye above it: the scene alone
    EXPECT_EQ(planPasses(f).describe(), "scene");
    f.reflectedCaustics = true; // the sun reflected off the water lights that scene
    EXPECT_EQ(planPasses(f).describe(), "sun depth, photons, gather, scene");
}
