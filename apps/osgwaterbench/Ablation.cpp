#include "node/WaterNodeImpl.h"
#include "Ablation.h"
#include "../common/FrameTimer.h"
#include <osg/Timer>
#include <cmath>
#include <limits>

namespace bench {

using osgWater::WaterNode;
using osgWater::WaterSettings;

std::vector<AblationConfig> ablationConfigs()
{
    auto none = [](WaterSettings&, WaterNode&) {};
    return {
        { "plain", "", none },
        { "everything on", "", none },
        { "caustics off", "caustics", [](WaterSettings& s, WaterNode&) { s.setCausticsEnabled(false); } },
        { "glow off", "glow", [](WaterSettings& s, WaterNode&) { s.setGlowEnabled(false); } },
        { "reflection off", "reflection", [](WaterSettings& s, WaterNode&) { s.setReflectionEnabled(false); } },
        { "refraction off", "refraction", [](WaterSettings& s, WaterNode&) { s.setRefractionEnabled(false); } },
        { "skips off", "skips", [](WaterSettings&, WaterNode& w) { w.setSkippingEnabled(false); } },
        { "caustics unfocused", "caustics", [](WaterSettings& s, WaterNode&) { s.setCausticsFocused(false); } },
        { "surface only", "", [](WaterSettings& s, WaterNode&) {
             s.setCausticsEnabled(false);
             s.setGlowEnabled(false);
             s.setReflectionEnabled(false);
             s.setRefractionEnabled(false);
         } },
        { "quality fast", "", [](WaterSettings& s, WaterNode&) { s.setQuality(WaterSettings::QUALITY_FAST); } },
        { "quality exact", "", [](WaterSettings& s, WaterNode&) { s.setQuality(WaterSettings::QUALITY_EXACT); } },
    };
}

double ablationRatio(const AblationView& v, const std::string& config)
{
    auto a = v.ms.find(config), p = v.ms.find("plain");
    if (a == v.ms.end() || p == v.ms.end() || !(p->second > 0.0)) return std::numeric_limits<double>::quiet_NaN();
    return a->second / p->second;
}

Ablation runAblation(osgViewer::Viewer& viewer, osg::Switch* scenes, WaterNode& water, const std::vector<View>& views,
                     const WaterSettings& base, int rounds, int frames)
{
    Ablation a;
    a.configs = ablationConfigs();
    a.rounds = rounds;
    a.frames = frames;
    // the automatic gather would time its candidates again whenever the caustics are remade: every
    // configuration uses the method it chose for the default
    const WaterSettings::CausticsGather gather = water.getActiveCausticsGather() == WaterSettings::GATHER_AUTO
                                                     ? base.getCausticsGather() : water.getActiveCausticsGather();
    a.gather = osgWater::causticsGatherLabel(gather);
    const bool timing = water.getPassTimingEnabled();
    water.setPassTimingEnabled(true);
    osg::Camera* camera = viewer.getCamera();
    for (const View& view : views) {
        AblationView av;
        av.view = view.name;
        camera->setViewMatrixAsLookAt(view.eye, view.center, view.up);
        av.eyeBelow = water.eyeHeightAboveSurface(view.eye, view.t) < 0.0; // the scene's water is not transformed
        std::map<std::string, std::vector<double>> roundMeans;
        std::map<int, std::vector<double>> passMs, passFragments;
        double t = view.t;
        for (int round = 0; round < rounds; ++round)
            for (const AblationConfig& c : a.configs) {
                osg::ref_ptr<WaterSettings> s = new WaterSettings(base, osg::CopyOp::DEEP_COPY_ALL);
                s->setCausticsGather(gather);
                water.setSkippingEnabled(true);
                c.apply(*s, water);
                water.setSettings(s.get());
                scenes->setSingleChildOn(c.name == "plain" ? 1 : 0);
                std::vector<double> ms;
                for (int i = 0; i < 2 + frames; ++i) {
                    const osg::Timer_t t0 = osg::Timer::instance()->tick();
                    viewer.frame(t);
                    t += 1.0 / 60.0;
                    if (i < 2) continue; // warm-up: targets remade, programs linked
                    ms.push_back(osg::Timer::instance()->delta_m(t0, osg::Timer::instance()->tick()));
                    if (c.name != "everything on") continue;
                    const osgWater::PassPlan plan = osgWater::internals(water).getPassPlan(camera);
                    av.waterInView = av.waterInView || plan.runs(osgWater::PASS_SURFACE);
                    av.effectRan["caustics"] = av.effectRan["caustics"] || plan.runs(osgWater::PASS_PHOTONS);
                    av.effectRan["glow"] = av.effectRan["glow"] || plan.runs(osgWater::PASS_GLOW_COMPOSITE);
                    av.effectRan["reflection"] = av.effectRan["reflection"] || plan.runs(osgWater::PASS_REFLECTION);
                    av.effectRan["refraction"] = av.effectRan["refraction"] || plan.runs(osgWater::PASS_REFRACTION);
                    const osgWater::ViewReport report = water.getViewReport(camera);
                    for (int pass = 0; pass < osgWater::PASS_COUNT; ++pass) {
                        if (!osgWater::gpuTimeLabel(osgWater::PassId(pass)) || !plan.runs(osgWater::PassId(pass))) continue;
                        if (report.milliseconds[pass] >= 0.0) passMs[pass].push_back(report.milliseconds[pass]);
                        if (report.fragments[pass] >= 0.0) passFragments[pass].push_back(report.fragments[pass]);
                    }
                }
                roundMeans[c.name].push_back(osgWaterApps::medianOfBlockMeans(ms, ms.size()));
            }
        av.effectRan["skips"] = av.waterInView;
        for (const auto& [name, means] : roundMeans) av.ms[name] = osgWaterApps::median(means);
        for (const auto& [pass, ms] : passMs) av.passMs[pass] = osgWaterApps::median(ms);
        for (const auto& [pass, counts] : passFragments) av.passFragments[pass] = osgWaterApps::median(counts);
        a.views.push_back(av);
        std::printf("ablation %-28s everything on x%.2f  caustics off x%.2f  glow off x%.2f  surface only x%.2f\n",
                    view.name.c_str(), ablationRatio(av, "everything on"), ablationRatio(av, "caustics off"),
                    ablationRatio(av, "glow off"), ablationRatio(av, "surface only"));
        std::fflush(stdout);
    }
    water.setSkippingEnabled(true);
    water.setPassTimingEnabled(timing);
    water.setSettings(new WaterSettings(base, osg::CopyOp::DEEP_COPY_ALL));
    scenes->setSingleChildOn(0);
    return a;
}

}
