// The ablation: for every view, the frame with everything on, then each effect off in turn, the
// skips off, the surface alone and the quality presets, all timed in one run in alternating rounds
// (so drifts in machine load hit every configuration alike), with each pass's own GPU time and
// its fragment shader invocations (the work, which the machine's load does not change).
// Timing only: the errors of the same configurations are the techniques' table's.
#pragma once
#include "Views.h"
#include <osgViewer/Viewer>
#include <osg/Switch>
#include <osgWater/WaterNode>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace bench {

struct AblationConfig {
    std::string name;
    std::string effect; //!< for an effect switched off: the effect ("caustics", ...); else empty
    std::function<void(osgWater::WaterSettings&, osgWater::WaterNode&)> apply;
};

//! The configurations, in the table's order; "plain" (water removed) and "everything on" first.
std::vector<AblationConfig> ablationConfigs();

struct AblationView {
    std::string view;
    bool waterInView = false, eyeBelow = false;
    std::map<std::string, double> ms;      //!< configuration -> frame time (median over rounds of the round's mean)
    std::map<std::string, bool> effectRan; //!< effect -> its passes ran with everything on
    std::map<int, double> passMs;          //!< PassId -> median GPU time with everything on (passes that ran)
    std::map<int, double> passFragments;   //!< PassId -> median fragment shader invocations a frame, the same
};

struct Ablation {
    std::vector<AblationConfig> configs;
    std::vector<AblationView> views;
    int rounds = 0, frames = 0;
    std::string gather; //!< the caustics gather every configuration uses (the one the default chose)
};

//! `scenes`: child 0 the scene with the water, child 1 the plain scene. Every configuration starts
//! from `base`; the water's settings are restored to a copy of it afterwards.
Ablation runAblation(osgViewer::Viewer& viewer, osg::Switch* scenes, osgWater::WaterNode& water,
                     const std::vector<View>& views, const osgWater::WaterSettings& base, int rounds, int frames);

//! Frame time of a configuration over the plain scene's in one view (NaN when either is missing).
double ablationRatio(const AblationView& v, const std::string& config);

}
