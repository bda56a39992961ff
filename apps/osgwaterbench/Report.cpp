#include "Report.h"
#include "Gnuplot.h"
#include <nlohmann/json.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>

namespace bench {

namespace {

nlohmann::json number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

void addQuantiles(nlohmann::json& j, const std::string& prefix, const Quantiles& q)
{
    j[prefix + "_median"] = number(q.median);
    j[prefix + "_p95"] = number(q.p95);
    j[prefix + "_p99"] = number(q.p99);
    j[prefix + "_max"] = number(q.max);
    j[prefix + "_n"] = q.n;
}

nlohmann::json toJson(const Record& r)
{
    nlohmann::json j;
    j["technique"] = r.technique;
    j["view"] = r.view;
    j["time_s"] = r.t;
    j["eye_below"] = r.eyeBelow;
    j["held_out"] = r.heldOut;
    j["lookup"] = r.lookup;
    j["steps"] = r.steps;
    j["texture_size"] = r.textureSize;
    j["rotation"] = r.rotation;
    j["apparent_eye"] = r.apparentEye;
    j["fresnel"] = r.fresnel;
    j["caustics"] = r.caustics;
    j["glow"] = r.glow;
    j["frame_ms"] = number(r.frameMs);
    j["plain_ms"] = number(r.plainMs);
    j["ratio"] = number(r.ratio);
    j["water_pixels"] = r.waterPixels;
    addQuantiles(j, "refraction_px", r.refractionPx);
    j["refraction_px_over2_share"] = number(r.refractionPx.over2);
    addQuantiles(j, "refraction_m", r.refractionM);
    addQuantiles(j, "refraction_fan_px", r.refractionFanPx);
    addQuantiles(j, "refraction_beyond_fan_px", r.refractionBeyondFanPx);
    j["refraction_beyond_fan_over2_share"] = number(r.refractionBeyondFanPx.over2);
    addQuantiles(j, "refraction_own_px", r.refractionOwnPx);
    j["refraction_own_over2_share"] = number(r.refractionOwnPx.over2);
    addQuantiles(j, "reflection_own_shown_texels", r.reflectionOwnShownTexels);
    j["reflection_own_not_shown"] = r.reflectionOwnNotShown;
    j["reflection_own_sent_under"] = r.reflectionOwnSentUnder;
    addQuantiles(j, "reflection_texels", r.reflectionTexels);
    addQuantiles(j, "reflection_shown_texels", r.reflectionShownTexels);
    j["reflection_not_shown"] = r.reflectionNotShown;
    addQuantiles(j, "reflection_fan_texels", r.reflectionFanTexels);
    addQuantiles(j, "reflection_beyond_fan_texels", r.reflectionBeyondFanTexels);
    addQuantiles(j, "fresnel_error", r.fresnelError);
    addQuantiles(j, "drawn_surface_px", r.drawnSurfacePx);
    addQuantiles(j, "shaded_point_cm", r.shadedPointCm);
    j["shaded_point_over_2cm_share"] = number(r.shadedPointCm.over2);
    const char* causes[CAUSE_COUNT] = { "within_fan", "shaded_point", "hidden", "in_front", "behind" };
    for (int c = 0; c < CAUSE_COUNT; ++c) j[std::string("refraction_over2_") + causes[c]] = r.refractionCauses[c];
    for (int c = CAUSE_HIDDEN; c < CAUSE_COUNT; ++c) j[std::string("refraction_own_over2_") + causes[c]] = r.refractionOwnCauses[c];
    j["refraction_misses"] = r.misses;
    j["tir_mismatch"] = r.tirMismatch;
    j["coverage_mismatch"] = r.coverageMismatch;
    j["caustics_rel_rmse"] = number(r.causticsErrors.relativeRmse);
    j["caustics_reference_noise"] = number(r.causticsErrors.referenceNoise);
    // the blocks' means: a bias shows as a difference, noise and blur only in the RMSE
    j["caustics_mean_reference"] = number(r.causticsErrors.meanReference);
    j["caustics_mean_rendered"] = number(r.causticsErrors.meanRendered);
    j["image_ssim"] = number(r.image.ssimWater);
    j["image_delta_e_mean"] = number(r.image.deltaEMeanWater);
    j["image_delta_e_p95"] = number(r.image.deltaEP95Water);
    j["image_ssim_frame"] = number(r.image.ssimFrame);
    j["image_delta_e_mean_frame"] = number(r.image.deltaEMeanFrame);
    j["image_delta_e_p95_frame"] = number(r.image.deltaEP95Frame);
    j["image_reference_noise_delta_e"] = number(r.image.referenceNoiseWater);
    j["nan_pixels"] = r.nanPixels;
    j["work_refraction_reads"] = number(r.work.refractionReads);
    j["work_reflection_reads"] = number(r.work.reflectionReads);
    j["work_march_heights"] = number(r.work.marchHeights);
    return j;
}

std::string fmt(double v, int digits = 2, const char* suffix = "")
{
    if (!std::isfinite(v)) return "–";
    std::ostringstream o;
    o << std::fixed << std::setprecision(digits) << v << suffix;
    return o.str();
}

std::string pct(double v) { return std::isfinite(v) ? fmt(100.0 * v, 1, "%") : "–"; }

double median(std::vector<double> v)
{
    v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return !std::isfinite(x); }), v.end());
    if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

const Summary* find(const std::vector<Summary>& s, const std::string& name)
{
    for (const Summary& x : s)
        if (x.technique == name) return &x;
    return nullptr;
}

bool plot(const std::string& dir, const std::vector<Summary>& summaries, std::string& png)
{
    std::ostringstream d;
    for (const Summary& s : summaries)
        if (std::isfinite(s.ratioInView) && std::isfinite(s.refractionPx.median))
            d << '"' << s.technique << "\" " << s.ratioInView << ' ' << std::max(s.refractionPx.median, 1e-3) << ' '
              << std::max(s.refractionPx.p99, 1e-3) << ' ' << (std::isfinite(s.imageDeltaE) ? s.imageDeltaE : -1.0)
              << '\n';
    png = "benchmark-speed-error.png";
    return runGnuplot(dir, "benchmark-speed-error", d.str(),
                      "set terminal pngcairo size 1100,1200 font 'sans,10'\n"
                      "set output OUTPUT\n"
                      "set multiplot layout 2,1 title 'osgWater: frame time against error (generated by osgwaterbench)'\n"
                      "set xlabel 'frame time / plain scene (median over views with water in view)'\n"
                      "set grid\nset key top right\nset offsets graph 0.08, graph 0.2, graph 0.1, graph 0.1\n"
                      "set title 'the image: mean CIEDE2000 over the water against the reference image (mean over views)'\n"
                      "set ylabel 'CIEDE2000 (1: just noticeable)'\n"
                      "plot DATA using 2:($5 < 0 ? NaN : $5) with points pt 7 ps 1.5 lc rgb '#228833' notitle, \\\n"
                      "     '' using 2:($5 < 0 ? NaN : $5):1 with labels offset 1,0.6 left font 'sans,8' notitle\n"
                      "set title 'the refraction lookup'\n"
                      "set ylabel 'refraction apparent-position error, screen pixels (log)'\n"
                      "set logscale y\n"
                      "plot DATA using 2:4 with points pt 6 ps 1.5 lc rgb '#cc4444' title 'p99', \\\n"
                      "     '' using 2:3 with points pt 7 ps 1.5 lc rgb '#2255aa' title 'median', \\\n"
                      "     '' using 2:3:1 with labels offset 1,0.6 left font 'sans,8' notitle\n"
                      "unset multiplot\n");
}

}

AblationSummary summarizeAblation(const Ablation& a)
{
    AblationSummary s;
    std::vector<double> outOfView;
    for (const AblationView& v : a.views)
        if (!v.waterInView && !v.eyeBelow) outOfView.push_back(ablationRatio(v, "everything on"));
    s.outOfView = median(outOfView);
    for (const AblationConfig& c : a.configs) {
        AblationSummary::Row row;
        row.config = c.name;
        row.effect = c.effect;
        std::vector<double> ratios, ms, costs;
        for (const AblationView& v : a.views) {
            if (v.waterInView && !v.eyeBelow) {
                ratios.push_back(ablationRatio(v, c.name));
                auto it = v.ms.find(c.name);
                if (it != v.ms.end()) ms.push_back(it->second);
            }
            // an effect costs what switching it off saves, where it ran
            auto ran = v.effectRan.find(c.effect);
            if (!c.effect.empty() && ran != v.effectRan.end() && ran->second && !v.eyeBelow)
                costs.push_back(ablationRatio(v, "everything on") / ablationRatio(v, c.name) - 1.0);
        }
        row.ratio = median(ratios);
        row.frameMs = median(ms);
        row.cost = median(costs);
        row.views = int(costs.size());
        s.rows.push_back(row);
    }
    std::map<int, std::vector<double>> passes, fragments;
    for (const AblationView& v : a.views) {
        for (const auto& [pass, ms] : v.passMs) passes[pass].push_back(ms);
        for (const auto& [pass, n] : v.passFragments) fragments[pass].push_back(n);
    }
    for (const auto& [pass, ms] : passes) s.passMs[pass] = median(ms);
    for (const auto& [pass, n] : fragments) s.passFragments[pass] = median(n);
    return s;
}

bool writeAblationCsv(const std::string& file, const Ablation& a, std::string& error)
{
    std::ofstream out(file);
    out << "view,water_in_view,eye_below";
    for (const AblationConfig& c : a.configs) out << ",\"" << c.name << " ms\"";
    for (int p = 0; p < osgWater::PASS_COUNT; ++p)
        if (const char* label = osgWater::gpuTimeLabel(osgWater::PassId(p))) out << ",\"" << label << " GPU ms\"";
    for (int p = 0; p < osgWater::PASS_COUNT; ++p)
        if (const char* label = osgWater::gpuTimeLabel(osgWater::PassId(p))) out << ",\"" << label << " fragments\"";
    out << '\n';
    for (const AblationView& v : a.views) {
        out << '"' << v.view << "\"," << v.waterInView << ',' << v.eyeBelow;
        for (const AblationConfig& c : a.configs) {
            auto it = v.ms.find(c.name);
            out << ',' << (it != v.ms.end() ? fmt(it->second, 3) : "");
        }
        for (const std::map<int, double>* measure : { &v.passMs, &v.passFragments })
            for (int p = 0; p < osgWater::PASS_COUNT; ++p) {
                if (!osgWater::gpuTimeLabel(osgWater::PassId(p))) continue;
                auto it = measure->find(p);
                out << ',' << (it != measure->end() ? fmt(it->second, measure == &v.passMs ? 3 : 0) : "");
            }
        out << '\n';
    }
    if (!out) error = "cannot write " + file;
    return bool(out);
}

void printAblation(const Ablation& a)
{
    const AblationSummary s = summarizeAblation(a);
    std::printf("ablation (median over views with water in view, eye above; %d rounds of %d frames):\n", a.rounds, a.frames);
    for (const AblationSummary::Row& r : s.rows)
        std::printf("  %-16s x%.2f  %7.1f ms%s\n", r.config.c_str(), r.ratio, r.frameMs,
                    r.effect.empty() ? "" : ("  costs " + fmt(100.0 * r.cost, 1, "%") + " over " + std::to_string(r.views) + " views").c_str());
    std::printf("  water out of view x%.3f\n", s.outOfView);
    for (const auto& [pass, ms] : s.passMs) {
        auto n = s.passFragments.find(pass);
        std::printf("  %-18s %6.2f ms GPU  %s\n", osgWater::gpuTimeLabel(osgWater::PassId(pass)), ms,
                    n != s.passFragments.end() ? (fmt(n->second * 1e-6, 3) + " M fragments").c_str() : "fragments not counted");
    }
}

bool writeJson(const std::string& file, const std::vector<Record>& records, std::string& error)
{
    nlohmann::json all = nlohmann::json::array();
    for (const Record& r : records) all.push_back(toJson(r));
    std::ofstream out(file);
    out << all.dump(1) << '\n';
    if (!out) error = "cannot write " + file;
    return bool(out);
}

bool writeCsv(const std::string& file, const std::vector<Record>& records, std::string& error)
{
    std::ofstream out(file);
    if (records.empty()) return bool(out);
    const nlohmann::json first = toJson(records.front());
    bool comma = false;
    for (auto it = first.begin(); it != first.end(); ++it) { out << (comma ? "," : "") << it.key(); comma = true; }
    out << '\n';
    for (const Record& r : records) {
        const nlohmann::json j = toJson(r);
        comma = false;
        for (auto it = first.begin(); it != first.end(); ++it) {
            const nlohmann::json& v = j[it.key()];
            out << (comma ? "," : "") << (v.is_null() ? "" : v.is_string() ? '"' + v.get<std::string>() + '"' : v.dump());
            comma = true;
        }
        out << '\n';
    }
    if (!out) error = "cannot write " + file;
    return bool(out);
}

namespace {

// of the render's own mirror rays that rise from the level, the share its reflection pass cannot show
double ownNotShownShare(const Record& r)
{
    const double n = double(r.reflectionOwnShownTexels.n + r.reflectionOwnNotShown);
    return n > 0.0 ? double(r.reflectionOwnNotShown) / n : std::numeric_limits<double>::quiet_NaN();
}

// of all the render's own mirror rays, the share the waves send back under the level
double sentUnderShare(const Record& r)
{
    const double n = double(r.reflectionOwnShownTexels.n + r.reflectionOwnNotShown + r.reflectionOwnSentUnder);
    return n > 0.0 ? double(r.reflectionOwnSentUnder) / n : std::numeric_limits<double>::quiet_NaN();
}

// A view's tails against their targets, along the render's own rays (the lookups' errors alone,
// whatever the pixel's filtering chose): the refraction's p99 <= 2 px with at most 1% of pixels over
// 2 px, the reflection's where its pass shows the hit p99 <= 4 texels with <= 2% of the pixels it
// cannot show; what the view has none of counts as met, and "not measured" where it has neither
std::string tailsStatus(const Record& r)
{
    const bool refraction = r.refractionOwnPx.n > 0, reflection = r.reflectionOwnShownTexels.n + r.reflectionOwnNotShown > 0;
    if (!refraction && !reflection) return "not measured";
    const bool refractionMet = !refraction || (r.refractionOwnPx.p99 <= 2.0 && r.refractionOwnPx.over2 <= 0.01);
    const bool reflectionMet = !reflection || (r.reflectionOwnShownTexels.n > 0 && r.reflectionOwnShownTexels.p99 <= 4.0 &&
                                               ownNotShownShare(r) <= 0.02);
    if (refractionMet && reflectionMet) return "met";
    return std::string("**missed**") + (refractionMet ? " (reflection)" : reflectionMet ? " (refraction)" : "");
}

}

bool writeDocs(const std::string& dir, const RunInfo& info, const std::vector<Record>& records,
               const std::vector<Summary>& summaries, const Ablation* ablation, std::string& error)
{
    std::string png;
    const bool plotted = plot(dir, summaries, png);
    std::ofstream md(dir + "/BENCHMARKS.md");
    md << "# Benchmarks: speed against error\n\n"
       << "Generated by `osgwaterbench` — do not edit by hand; regenerate with `bash scripts/bench.sh`.\n\n"
       << "- Command: `" << info.command << "`\n"
       << "- Date: " << info.date << "; renderer: " << info.renderer << "; " << info.cpus << " CPU threads\n"
       << "- Scene `" << info.scene << "`, views `" << info.viewsFile << "`, " << info.width << "×" << info.height
       << ", frame time = median over blocks of 5 of the block's mean, " << info.frames << " frames after warm-up (work "
       << "done every few frames counts at its average), plain scene (water removed) timed "
       << "in the same run just before and after each technique (ratio = frame / plain)\n"
       << "- Reference: the eye rays against the analytic waves at the view's time (double precision), then Embree "
       << "ray casting over the scene's triangles; caustics by "
       << info.photons << " photons traced from the sun; the reference image by Whitted ray tracing on the same "
       << "machinery (the facets under the wind's roughness drawn per ray), " << info.referenceSamples << " × " << info.referenceSamples << " rays a pixel"
       << (info.referenceRefine > 0 ? " and " + std::to_string(info.referenceRefine) + " × " + std::to_string(info.referenceRefine) +
                                          " more where its two halves disagree by over 1%"
                                    : std::string())
       << " (exact Fresnel, "
       << "up to 8 water hits a path, the scene program's colours, caustics and underwater shadows from the traced photons), shown as the technique shows its light (exposure, tone curve, sRGB); "
       << "`triplets/` beside the run's output has each view's render | reference | CIEDE2000 (black 0, white ≥ 10) "
       << "for the default, and `benchmark-reference.png` the first view's\n"
       << "- Height queries (`WaterNode::getSurfaceHeightAt` with the normal, the scene's waves, one thread): "
       << fmt(info.heightQueriesPerSecond / 1.0e6, 2, " million") << " per second\n\n";

    // targets: the speed ones from the ablation (every configuration in one run, alternating rounds)
    const Summary* def = find(summaries, "default");
    const AblationSummary abl = ablation ? summarizeAblation(*ablation) : AblationSummary();
    auto row = [&](const std::string& config) -> const AblationSummary::Row* {
        for (const AblationSummary::Row& r : abl.rows)
            if (r.config == config) return &r;
        return nullptr;
    };
    auto status = [](double v, bool met) { return !std::isfinite(v) ? "not measured" : met ? "met" : "**missed**"; };
    auto signedPct = [](double v) { return std::isfinite(v) ? (v >= 0 ? "+" : "") + fmt(100 * v, 1, "%") : std::string("–"); };
    const AblationSummary::Row* all = row("everything on");
    const AblationSummary::Row* caustics = row("caustics off");
    const AblationSummary::Row* glow = row("glow off");
    const double allRatio = all ? all->ratio : std::numeric_limits<double>::quiet_NaN();
    const double causticsCost = caustics ? caustics->cost : std::numeric_limits<double>::quiet_NaN();
    const double glowCost = glow ? glow->cost : std::numeric_limits<double>::quiet_NaN();
    md << "## Targets (lake at 1280×720 on a 2-core software-rendered machine)\n\n"
       << "Speed from the ablation below (one run); errors from the techniques' table.\n\n"
       << "| target | measured | status |\n|---|---|---|\n"
       << "| every effect on (default) ≤ 3.0× the plain scene | " << fmt(allRatio, 2, "×") << " | "
       << status(allRatio, allRatio <= 3.0) << " |\n"
       << "| every effect on: goal 2.0× | " << fmt(allRatio, 2, "×") << " | " << status(allRatio, allRatio <= 2.0) << " |\n"
       << "| water out of view ≤ 1.03× | " << fmt(abl.outOfView, 3, "×") << " | "
       << status(ablation ? abl.outOfView : std::numeric_limits<double>::quiet_NaN(), abl.outOfView <= 1.03) << " |\n"
       << "| caustics ≤ +10% of the frame | " << signedPct(causticsCost) << " | " << status(causticsCost, causticsCost <= 0.10) << " |\n"
       << "| glow ≤ +5% of the frame | " << signedPct(glowCost) << " | " << status(glowCost, glowCost <= 0.05) << " |\n";
    if (def) {
        md << "| default refraction median ≤ 0.25 px | " << fmt(def->refractionPx.median, 3, " px") << " | "
           << status(def->refractionPx.median, def->refractionPx.median <= 0.25) << " |\n";
        md << "| default refraction p99 ≤ 2 px | " << fmt(def->refractionPx.p99, 2, " px") << " | "
           << status(def->refractionPx.p99, def->refractionPx.p99 <= 2.0) << " |\n";
        md << "| the same beyond the fan of each pixel's own refracted rays (median fan "
           << fmt(def->refractionFanPx.median, 2, " px") << ") | " << fmt(def->refractionBeyondFanPx.p99, 2, " px") << " | "
           << status(def->refractionBeyondFanPx.p99, def->refractionBeyondFanPx.p99 <= 2.0) << " |\n";
        md << "| default refraction: ≤ 1% of pixels over 2 px beyond their fan | " << pct(def->refractionBeyondFanPx.over2)
           << " | " << status(def->refractionBeyondFanPx.over2, def->refractionBeyondFanPx.over2 <= 0.01) << " |\n";
        md << "| default refraction along the render's own rays: p99 ≤ 2 px | " << fmt(def->refractionOwnPx.p99, 2, " px")
           << " | " << status(def->refractionOwnPx.p99, def->refractionOwnPx.p99 <= 2.0) << " |\n";
        md << "| the same: ≤ 1% of pixels over 2 px | " << pct(def->refractionOwnPx.over2) << " | "
           << status(def->refractionOwnPx.over2, def->refractionOwnPx.over2 <= 0.01) << " |\n";
        md << "| default reflection along the render's own rays, where its pass shows the hit: p99 ≤ 4 texels | "
           << fmt(def->reflectionOwnShownTexels.p99, 1, " texels") << " | "
           << status(def->reflectionOwnShownTexels.p99, def->reflectionOwnShownTexels.p99 <= 4.0) << " |\n";
        md << "| the same: the hits its pass cannot show ≤ 2% | " << pct(def->reflectionOwnNotShownShare) << " | "
           << status(def->reflectionOwnNotShownShare, def->reflectionOwnNotShownShare <= 0.02) << " |\n";
        md << "| default reflection median ≤ 0.5 texel | " << fmt(def->reflectionTexels.median, 3, " texels") << " | "
           << status(def->reflectionTexels.median, def->reflectionTexels.median <= 0.5) << " |\n";
        md << "| default reflection p99 ≤ 4 texels | " << fmt(def->reflectionTexels.p99, 1, " texels") << " | "
           << status(def->reflectionTexels.p99, def->reflectionTexels.p99 <= 4.0) << " |\n";
        md << "| the same where the reflection pass shows the hit (" << pct(1.0 - def->reflectionNotShownShare)
           << " of the pixels) | " << fmt(def->reflectionShownTexels.p99, 1, " texels") << " | "
           << status(def->reflectionShownTexels.p99, def->reflectionShownTexels.p99 <= 4.0) << " |\n";
        md << "| the same beyond the fan of each pixel's own mirror rays (median fan "
           << fmt(def->reflectionFanTexels.median, 1, " texels") << ") | " << fmt(def->reflectionBeyondFanTexels.p99, 1, " texels")
           << " | " << status(def->reflectionBeyondFanTexels.p99, def->reflectionBeyondFanTexels.p99 <= 4.0) << " |\n";
        md << "| default coverage mismatch ≤ 0.5% on every view (worst: " << def->worstCoverageView << ") | "
           << pct(def->worstCoverageShare) << " | " << status(def->worstCoverageShare, def->worstCoverageShare <= 0.005)
           << " |\n";
        md << "| default caustics RMSE ≤ 10% on every view (worst: " << def->worstCausticsView << ", the reference's noise "
           << pct(def->worstCausticsNoise) << ") | " << pct(def->worstCausticsRmse) << " | "
           << status(def->worstCausticsRmse, def->worstCausticsRmse <= 0.10) << " |\n";
        md << "| default image over the water: SSIM ≥ 0.95 on every view | " << fmt(def->worstImageSsim, 3) << " | "
           << status(def->worstImageSsim, def->worstImageSsim >= 0.95) << " |\n";
        md << "| default image over the water: mean CIEDE2000 ≤ 2 on every view (worst: " << def->worstImageView << ") | "
           << fmt(def->worstImageDeltaE, 2) << " | " << status(def->worstImageDeltaE, def->worstImageDeltaE <= 2.0) << " |\n";
    }

    // the presets: speed from the ablation, errors from the techniques
    md << "\n## Quality presets\n\n"
       << "`WaterSettings::setQuality()`: bundles of the speed settings (see `osgWater/settings/QualityPresets.cpp`). "
       << "Ratio from the ablation, errors from the techniques' table (every water pixel of every view).\n\n"
       << "| preset | ratio | refr. px median | p99 | refl. texels median | caustics RMSE |\n|---|---|---|---|---|---|\n";
    const std::pair<const char*, const char*> presets[] = { { "fast", "quality-fast" }, { "balanced (default)", "default" },
                                                            { "exact", "quality-exact" } };
    for (const auto& [name, technique] : presets) {
        const AblationSummary::Row* r = row(std::string(technique) == "default" ? "everything on" : "quality " + std::string(name));
        const Summary* t = find(summaries, technique);
        md << "| " << name << " | " << (r ? fmt(r->ratio, 2, "×") : "–") << " | "
           << (t ? fmt(t->refractionPx.median, 3) : "–") << " | " << (t ? fmt(t->refractionPx.p99, 2) : "–") << " | "
           << (t ? fmt(t->reflectionTexels.median, 2) : "–") << " | " << (t ? pct(t->causticsRmse) : "–") << " |\n";
    }

    // the ablation itself
    if (ablation) {
        md << "\n## Ablation\n\n"
           << "Every configuration timed in one run for every view, in " << ablation->rounds
           << " alternating rounds of " << ablation->frames << " frames (after 2 warm-up frames): a view's figure is "
           << "the median over rounds of the round's mean frame time. Ratio: over the plain scene, median over the "
           << "views with water in view and the eye above it. An effect's cost: everything on over the effect off, "
           << "less 1, median over the views where the effect's passes ran (caustics: the views whose frames rendered "
           << "them; glow: those with the highlight in view); for the skips and the caustics' focus (caustics unfocused), negative: what they save. Caustics gather: " << ablation->gather << " in every "
           << "configuration (the automatic choice for the default). Errors of the same settings: the techniques' table "
           << "(caustics-off, caustics-unfocused, glow-off, quality-fast, quality-exact).\n\n"
           << "| configuration | ratio | frame ms | everything on ÷ this − 1 | over views |\n|---|---|---|---|---|\n";
        for (const AblationSummary::Row& r : abl.rows)
            md << "| " << r.config << " | " << fmt(r.ratio, 2, "×") << " | " << fmt(r.frameMs, 1) << " | "
               << (r.effect.empty() ? "–" : signedPct(r.cost)) << " | " << (r.effect.empty() ? "–" : std::to_string(r.views))
               << " |\n";
        md << "| water out of view (everything on) | " << fmt(abl.outOfView, 3, "×") << " | – | – | – |\n";
        md << "\nEach pass's own GPU time with everything on (GL timestamp queries; median over the views where it ran). "
           << "On a software rasteriser a pass drawn in the view itself (surface, cap, composite) is timed only up to "
           << "the driver's deferred rasterisation, so its figure is low; the render-to-texture passes are timed whole. "
           << "Its work: fragment shader invocations a frame (GL_ARB_pipeline_statistics_query), which this machine's "
           << "load does not change; this driver shades 4x4 blocks, so a block a triangle's edge crosses counts whole "
           << "for each triangle (a GPU counts pixels).\n\n"
           << "| pass | GPU ms | fragments a frame (millions) |\n|---|---|---|\n";
        for (const auto& [pass, ms] : abl.passMs) {
            auto n = abl.passFragments.find(pass);
            md << "| " << osgWater::gpuTimeLabel(osgWater::PassId(pass)) << " | " << fmt(ms, 2) << " | "
               << (n != abl.passFragments.end() ? fmt(n->second * 1e-6, 3) : "–") << " |\n";
        }
        md << "\nThe work per view, everything on: each pass's fragments a frame over the view's " << info.width << "×"
           << info.height << " pixels (the scene itself, drawn in the view's bins, is not counted).\n\n| view";
        std::vector<int> counted;
        for (int p = 0; p < osgWater::PASS_COUNT; ++p)
            if (const char* label = osgWater::gpuTimeLabel(osgWater::PassId(p)))
                for (const AblationView& v : ablation->views)
                    if (v.passFragments.count(p)) {
                        counted.push_back(p);
                        md << " | " << label;
                        break;
                    }
        md << " | all |\n|---";
        for (size_t i = 0; i <= counted.size(); ++i) md << "|---";
        md << "|\n";
        const double pixels = double(info.width) * info.height;
        for (const AblationView& v : ablation->views) {
            md << "| " << v.view;
            double all = 0.0;
            for (int p : counted) {
                auto n = v.passFragments.find(p);
                md << " | " << (n != v.passFragments.end() ? fmt(n->second / pixels, 2, "×") : "–");
                if (n != v.passFragments.end()) all += n->second;
            }
            md << " | " << fmt(all / pixels, 2, "×") << " |\n";
        }
    }
    md << "\n";
    if (plotted) md << "![speed against error](" << png << ")\n\n";
    else md << "(plot not made: gnuplot failed or is missing)\n\n";

    md << "## Techniques\n\n"
       << "Ratio and frame time: medians over the views with water in view and the eye above it. Errors: "
       << "every water pixel of every view pooled. Refraction error = distance between the point the "
       << "refraction texture shows at the pixel and the exact refracted hit, in metres and in screen "
       << "pixels (the offset on screen that, to first order, moves the exact hit onto the shown point). "
       << "Reflection error: the lookup point against the mirror ray's exact hit, in reflection-texture "
       << "texels; \"shown\": only the pixels whose hit the reflection pass has in view (seen from the "
       << "mirrored eye, on the eye's side of the level, and on the texture: not behind a shore, not a ray the "
       << "waves send back under the level), which no lookup in that texture can find otherwise; \"not shown\": the share "
       << "of the others. Fan: per pixel, how far apart (the widest two) its own four rays, through the centres of "
       << "its quarters, lead: their mirror rays' hits over the reflection texture (texels, the shown pixels), their "
       << "refracted rays' hits on screen (pixels, as the refraction error; about 0.7 over smooth water, the quarters' "
       << "diagonal). Over waves shorter than a pixel they fan out, and no single lookup is nearer all of them than "
       << "the fan is wide. Beyond fan: max(0, error - fan), the error no lookup the pixel's own rays could justify. Coverage: pixels where one of the reference and the render sees water and the other does "
       << "not, over the reference's water pixels. Surface: the drawn mesh against the analytic surface, per "
       << "pixel of the render's water the rasterised point and the exact surface point under it (same x, y): "
       << "the angle between them at the eye, in pixels of the view's focal length. Shaded: the share of the "
       << "render's water pixels whose shaded point (the one its colour is worked out at) lies more than 2 cm "
       << "from where the pixel's ray first meets the waves. "
       << "Caustics: relative RMSE of the caustics texture against photon tracing (blocks of "
       << "texels about 1.2 m on a side, whatever the texture's window and resolution; the reference's own "
       << "counting noise in brackets). Image: the view as shown against the reference image over the "
       << "reference's water pixels, the luma SSIM (11 × 11 Gaussian window, σ 1.5) and the mean CIEDE2000, "
       << "each the mean over the views, and the worst view's.\n\n"
       << "| technique | ratio | frame ms | image SSIM | worst | image ΔE00 | worst | refr. px median | p95 | p99 | max | > 2 px "
          "| refr. fan median | beyond fan p99 | beyond fan > 2 px | own ray p99 | own ray > 2 px | refr. m median "
          "| refl. texels median | p99 | shown p99 | not shown | refl. fan median | beyond fan p99 | own ray shown p99 | own ray not shown "
          "| Fresnel err. median | max | caustics RMSE | coverage | surface px median | p99 | shaded > 2 cm | NaN px |\n"
       << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const Summary& s : summaries)
        md << "| " << s.technique << " | " << fmt(s.ratioInView, 2, "×") << " | " << fmt(s.frameMs, 1) << " | "
           << fmt(s.imageSsim, 3) << " | " << fmt(s.worstImageSsim, 3) << " | " << fmt(s.imageDeltaE, 2) << " | "
           << fmt(s.worstImageDeltaE, 2) << " | " << fmt(s.refractionPx.median, 3) << " | " << fmt(s.refractionPx.p95, 2) << " | " << fmt(s.refractionPx.p99, 2)
           << " | " << fmt(s.refractionPx.max, 1) << " | " << pct(s.refractionPx.over2) << " | "
           << fmt(s.refractionFanPx.median, 2) << " | " << fmt(s.refractionBeyondFanPx.p99, 2) << " | "
           << pct(s.refractionBeyondFanPx.over2) << " | " << fmt(s.refractionOwnPx.p99, 2) << " | "
           << pct(s.refractionOwnPx.over2) << " | " << fmt(s.refractionM.median, 4) << " | " << fmt(s.reflectionTexels.median, 2) << " | "
           << fmt(s.reflectionTexels.p99, 1) << " | " << fmt(s.reflectionShownTexels.p99, 1) << " | "
           << pct(s.reflectionNotShownShare) << " | " << fmt(s.reflectionFanTexels.median, 1) << " | "
           << fmt(s.reflectionBeyondFanTexels.p99, 1) << " | " << fmt(s.reflectionOwnShownTexels.p99, 1) << " | "
           << pct(s.reflectionOwnNotShownShare) << " | " << fmt(s.fresnel.median, 4) << " | " << fmt(s.fresnel.max, 3)
           << " | " << pct(s.causticsRmse) << (std::isfinite(s.causticsNoise) ? " (" + pct(s.causticsNoise) + ")" : "")
           << " | " << pct(s.coverageMismatchShare) << " | " << fmt(s.drawnSurfacePx.median, 3) << " | "
           << fmt(s.drawnSurfacePx.p99, 2) << " | " << pct(s.shadedPointCm.over2) << " | " << s.nanPixels << " |\n";

    md << "\n### Work counted\n\n"
       << "The per-pixel loops' work, counted by the water shader (its DEBUG_WORK output) and averaged over the "
          "render's water pixels of every view: the depth texels the refraction and the reflection searches read, "
          "and the wave heights the march to the surface evaluated. Unlike the frame time it does not depend on "
          "this machine's load, and it is what a GPU pays per pixel.\n\n"
       << "| technique | refraction depth reads | reflection depth reads | march heights | frame ms |\n"
       << "|---|---|---|---|---|\n";
    for (const Summary& s : summaries)
        md << "| " << s.technique << " | " << fmt(s.work.refractionReads, 2) << " | " << fmt(s.work.reflectionReads, 2)
           << " | " << fmt(s.work.marchHeights, 2) << " | " << fmt(s.frameMs, 1) << " |\n";

    md << "\n## Views (default technique)\n\n"
       << "Image: over the water pixels, and in brackets over the whole frame; the target (SSIM ≥ 0.95 and mean "
          "CIEDE2000 ≤ 2 over the water) met or missed. Reference noise: the reference image's own, over the "
          "water (half the mean CIEDE2000 between the two halves of its rays a pixel): error of that size is "
          "its sampling's, not the render's.\n\n"
       << "Own ray: the errors of the lookups along the rays the render traced (its shaded point and normal, "
          "traced exactly), the passes' and searches' alone whatever the pixel's filtering chose. Tails target, along "
          "those rays: the refraction's p99 ≤ 2 px with ≤ 1% of pixels over 2 px, and the reflection's where its pass "
          "shows the hit p99 ≤ 4 texels with ≤ 2% of the rays rising from the level not shown; met or missed. The mirror "
          "rays the waves send back under the level (\"sent under\") are no lookup's: their light is the shading's rule "
          "for the light the waves take back, which the image error measures.\n\n"
       << "| view | eye | water px | frame ms | plain ms | ratio | image SSIM | ΔE00 mean | ΔE00 p95 | reference noise ΔE00 "
          "| image target | refr. px median | p99 | max | refr. fan median | beyond fan p99 | beyond fan > 2 px | own ray p99 "
          "| own ray > 2 px | refr. m median | refl. texels median | p99 | shown p99 | not shown | refl. fan median | beyond fan p99 "
          "| own ray shown p99 | own ray not shown | own ray sent under | tails target | Fresnel err. median | caustics RMSE "
          "| coverage | surface px median | p99 | shaded > 2 cm | NaN px |\n"
       << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const Record& r : records) {
        if (r.technique != "default" || r.heldOut) continue;
        md << "| " << r.view << " | " << (r.eyeBelow ? "under water" : "above") << " | " << r.waterPixels << " | "
           << fmt(r.frameMs, 1) << " | " << fmt(r.plainMs, 1) << " | " << fmt(r.ratio, 2, "×") << " | "
           << fmt(r.image.ssimWater, 3) << " (" << fmt(r.image.ssimFrame, 3) << ") | " << fmt(r.image.deltaEMeanWater, 2)
           << " (" << fmt(r.image.deltaEMeanFrame, 2) << ") | " << fmt(r.image.deltaEP95Water, 2) << " ("
           << fmt(r.image.deltaEP95Frame, 2) << ") | " << fmt(r.image.referenceNoiseWater, 2) << " | "
           << status(r.image.deltaEMeanWater, r.image.ssimWater >= 0.95 && r.image.deltaEMeanWater <= 2.0) << " | "
           << fmt(r.refractionPx.median, 3) << " | " << fmt(r.refractionPx.p99, 2) << " | " << fmt(r.refractionPx.max, 1)
           << " | " << fmt(r.refractionFanPx.median, 2) << " | " << fmt(r.refractionBeyondFanPx.p99, 2) << " | "
           << pct(r.refractionBeyondFanPx.over2) << " | " << fmt(r.refractionOwnPx.p99, 2) << " | " << pct(r.refractionOwnPx.over2)
           << " | " << fmt(r.refractionM.median, 4) << " | " << fmt(r.reflectionTexels.median, 2) << " | "
           << fmt(r.reflectionTexels.p99, 1) << " | " << fmt(r.reflectionShownTexels.p99, 1) << " | "
           << pct(r.reflectionTexels.n ? double(r.reflectionNotShown) / double(r.reflectionTexels.n)
                                       : std::numeric_limits<double>::quiet_NaN())
           << " | " << fmt(r.reflectionFanTexels.median, 1) << " | " << fmt(r.reflectionBeyondFanTexels.p99, 1) << " | "
           << fmt(r.reflectionOwnShownTexels.p99, 1) << " | " << pct(ownNotShownShare(r)) << " | " << pct(sentUnderShare(r))
           << " | " << tailsStatus(r) << " | " << fmt(r.fresnelError.median, 4) << " | " << pct(r.causticsErrors.relativeRmse) << " | "
           << pct(r.waterPixels ? double(r.coverageMismatch) / double(r.waterPixels) : std::numeric_limits<double>::quiet_NaN())
           << " | " << fmt(r.drawnSurfacePx.median, 3) << " | " << fmt(r.drawnSurfacePx.p99, 2) << " | "
           << pct(r.shadedPointCm.over2) << " | " << r.nanPixels
           << " |\n";
    }
    if (std::any_of(records.begin(), records.end(), [](const Record& r) { return r.heldOut; })) {
        md << "\n## Held-out views (default technique)\n\n"
           << "Views no setting was chosen on (`--held-out`): measured with the default technique alone and kept out "
              "of every median, summary and the ablation. Columns as in the views above.\n\n"
           << "| view | eye | water px | ratio | image SSIM | ΔE00 mean | refr. px median | p99 | beyond fan p99 "
              "| own ray p99 | own ray > 2 px | refl. texels median | shown p99 | beyond fan p99 | own ray shown p99 "
              "| own ray not shown | own ray sent under | tails target | coverage | NaN px |\n"
           << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
        for (const Record& r : records) {
            if (!r.heldOut) continue;
            md << "| " << r.view << " | " << (r.eyeBelow ? "under water" : "above") << " | " << r.waterPixels << " | "
               << fmt(r.ratio, 2, "×") << " | " << fmt(r.image.ssimWater, 3) << " | " << fmt(r.image.deltaEMeanWater, 2)
               << " | " << fmt(r.refractionPx.median, 3) << " | " << fmt(r.refractionPx.p99, 2) << " | "
               << fmt(r.refractionBeyondFanPx.p99, 2) << " | " << fmt(r.refractionOwnPx.p99, 2) << " | "
               << pct(r.refractionOwnPx.over2) << " | " << fmt(r.reflectionTexels.median, 2) << " | "
               << fmt(r.reflectionShownTexels.p99, 1) << " | " << fmt(r.reflectionBeyondFanTexels.p99, 1) << " | "
               << fmt(r.reflectionOwnShownTexels.p99, 1) << " | " << pct(ownNotShownShare(r)) << " | "
               << pct(sentUnderShare(r)) << " | " << tailsStatus(r) << " | "
               << pct(r.waterPixels ? double(r.coverageMismatch) / double(r.waterPixels) : std::numeric_limits<double>::quiet_NaN())
               << " | " << r.nanPixels << " |\n";
        }
    }
    md << "\n## Refraction: the pixels over 2 px by cause (default technique)\n\n"
       << "Shares of each view's measured refraction pixels, each put down to the first cause that holds. Within "
          "the fan: the shown point lies no farther from the exact hit than the pixel's own rays' refracted hits "
          "lie apart (waves shorter than the pixel: one ray's hit is one sample of many). Shaded point: the pixel shades a surface point more "
          "than 2 cm from where its ray meets the waves, so its refracted ray starts elsewhere. Hidden: the exact "
          "hit is not in the refraction pass's view (something between its eye and the hit), so no single depth "
          "layer holds it. In front / behind: the search settled on a point the pass shows nearer its eye than the "
          "exact hit (an occluder, the near side of an edge) or farther.\n\n"
       << "Own ray: the same along the render's own refracted rays (its shaded point and normal), whose pixels "
          "over 2 px are the refraction pass's and search's alone.\n\n"
       << "| view | > 2 px | within the fan | shaded point | hidden | in front | behind | own ray > 2 px | hidden "
          "| in front | behind |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const Record& r : records) {
        if (r.technique != "default" || !r.refractionPx.n) continue;
        const double n = double(r.refractionPx.n);
        md << "| " << r.view << (r.heldOut ? " (held out)" : "") << " | " << pct(r.refractionPx.over2);
        for (size_t c : r.refractionCauses) md << " | " << pct(double(c) / n);
        const double own = double(r.refractionOwnPx.n);
        md << " | " << pct(r.refractionOwnPx.over2);
        for (int c = CAUSE_HIDDEN; c < CAUSE_COUNT; ++c)
            md << " | " << pct(own > 0.0 ? double(r.refractionOwnCauses[c]) / own : std::numeric_limits<double>::quiet_NaN());
        md << " |\n";
    }
    md << "\nEvery technique × view is in `results.csv` / `results.json` beside the run's output.\n";
    if (!md) error = "cannot write " + dir + "/BENCHMARKS.md";
    return bool(md);
}

}
