// The benchmark's outputs: results.json (a list of records), results.csv, and the generated
// docs (BENCHMARKS.md with the targets, per-technique and per-view tables, and a gnuplot PNG).
#pragma once
#include "Ablation.h"
#include "ImageCompare.h"
#include "Metrics.h"
#include <string>
#include <vector>

namespace bench {

struct Record {
    std::string technique, view, lookup, fresnel, caustics;
    int steps = 0, textureSize = 0;
    bool rotation = true, apparentEye = true, glow = true, eyeBelow = false;
    bool heldOut = false; //!< a held-out view (--held-out): in no median, no summary, no ablation
    double t = 0.0;
    double frameMs = 0.0, plainMs = 0.0, ratio = 0.0;
    size_t waterPixels = 0, misses = 0, tirMismatch = 0, coverageMismatch = 0, nanPixels = 0;
    size_t reflectionNotShown = 0; //!< measured pixels whose mirror hit the reflection pass cannot show
    Quantiles refractionPx, refractionM, reflectionTexels, reflectionShownTexels, fresnelError;
    Quantiles reflectionFanTexels, reflectionBeyondFanTexels; //!< the shown pixels' (ViewErrors)
    Quantiles refractionFanPx, refractionBeyondFanPx;         //!< the refraction's pixels' (ViewErrors)
    Quantiles refractionOwnPx, reflectionOwnShownTexels;      //!< along the render's own rays (ViewErrors)
    size_t reflectionOwnNotShown = 0, reflectionOwnSentUnder = 0;
    size_t refractionOwnCauses[CAUSE_COUNT] = {};
    Quantiles drawnSurfacePx; //!< the drawn mesh against the analytic surface, screen pixels
    Quantiles shadedPointCm;  //!< the point each pixel shades against its ray's exact crossing, cm (over2: > 2 cm)
    size_t refractionCauses[CAUSE_COUNT] = {}; //!< the refraction's pixels over 2 px, by cause
    CausticsErrors causticsErrors;
    ImageErrors image; //!< the view as shown against the reference image
    WorkCounts work;   //!< the per-pixel loops' work over the render's water
};

//! Pooled over every view of one technique.
struct Summary {
    std::string technique;
    double ratioInView = 0.0;   //!< median over views with water in view and the eye above it
    double frameMs = 0.0;       //!< median over the same views
    Quantiles refractionPx, refractionM, reflectionTexels, fresnel; //!< every pixel of every view
    Quantiles reflectionShownTexels;   //!< the pixels whose mirror hit the reflection pass shows
    Quantiles reflectionFanTexels, reflectionBeyondFanTexels; //!< the shown pixels' (ViewErrors)
    Quantiles refractionFanPx, refractionBeyondFanPx;         //!< the refraction's pixels' (ViewErrors)
    Quantiles refractionOwnPx, reflectionOwnShownTexels;      //!< along the render's own rays (ViewErrors)
    double reflectionOwnNotShownShare = std::numeric_limits<double>::quiet_NaN();
    Quantiles drawnSurfacePx;          //!< the drawn mesh against the analytic surface, every pixel of every view
    Quantiles shadedPointCm;           //!< the shaded point against the exact crossing, every pixel of every view
    double worstCoverageShare = std::numeric_limits<double>::quiet_NaN(); //!< the worst view's coverage mismatch
    std::string worstCoverageView;
    double reflectionNotShownShare = std::numeric_limits<double>::quiet_NaN(); //!< of the reflection's measured pixels
    double coverageMismatchShare = std::numeric_limits<double>::quiet_NaN();   //!< of the reference's water pixels
    double causticsRmse = std::numeric_limits<double>::quiet_NaN(), causticsNoise = causticsRmse;
    double worstCausticsRmse = causticsRmse, worstCausticsNoise = causticsRmse; //!< the worst view's, and its reference's noise
    std::string worstCausticsView;
    //! the image against the reference: the mean over the views of each view's water SSIM and mean
    //! CIEDE2000, and the worst view's
    double imageSsim = std::numeric_limits<double>::quiet_NaN(), imageDeltaE = imageSsim;
    double worstImageSsim = imageSsim, worstImageDeltaE = imageSsim;
    std::string worstImageView;
    size_t nanPixels = 0;
    WorkCounts work; //!< every water pixel of every view
};

struct RunInfo {
    std::string command, scene, viewsFile, renderer, date;
    int width = 0, height = 0, frames = 0;
    size_t photons = 0;
    int referenceSamples = 1; //!< the reference image's rays a pixel, each way
    int referenceRefine = 0;  //!< ... and more, each way, where a pixel's halves disagree
    unsigned int cpus = 0;
    bool quick = false;
    double heightQueriesPerSecond = 0.0; //!< WaterNode::getSurfaceHeightAt with the normal, one thread
};

bool writeJson(const std::string& file, const std::vector<Record>& records, std::string& error);
bool writeCsv(const std::string& file, const std::vector<Record>& records, std::string& error);
//! BENCHMARKS.md and its plot (PNG via gnuplot; without gnuplot the page says the plot is missing).
bool writeDocs(const std::string& dir, const RunInfo& info, const std::vector<Record>& records,
               const std::vector<Summary>& summaries, const Ablation* ablation, std::string& error);

//! What the ablation table says, summed up over the views (see Report.cpp for each figure's rule).
struct AblationSummary {
    struct Row {
        std::string config, effect;
        double ratio = 0.0;   //!< median over views with water in view and the eye above it
        double frameMs = 0.0; //!< the same views' median frame time
        double cost = 0.0;    //!< an effect's cost: everything on / this - 1, median over the views where it ran
        int views = 0;        //!< views the cost is the median of
    };
    std::vector<Row> rows;
    double outOfView = 0.0; //!< everything on / plain with the water out of view (median over such views)
    std::map<int, double> passMs;        //!< PassId -> median GPU ms over the views where it ran
    std::map<int, double> passFragments; //!< PassId -> median fragments a frame, the same
};
AblationSummary summarizeAblation(const Ablation& a);
bool writeAblationCsv(const std::string& file, const Ablation& a, std::string& error);
void printAblation(const Ablation& a);

}
