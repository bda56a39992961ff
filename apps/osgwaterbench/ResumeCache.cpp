#include "ResumeCache.h"
#include <nlohmann/json.hpp>
#include <osgDB/FileUtils>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>

namespace bench {

namespace {

using nlohmann::json;

// NaN and infinities, which JSON has no words for, are kept as null
json number(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }
double number(const json& j) { return j.is_number() ? j.get<double>() : std::numeric_limits<double>::quiet_NaN(); }

json toJson(const Quantiles& q)
{
    return { { "n", q.n }, { "median", number(q.median) }, { "p95", number(q.p95) }, { "p99", number(q.p99) },
             { "max", number(q.max) }, { "over2", number(q.over2) } };
}

Quantiles quantilesFrom(const json& j)
{
    Quantiles q;
    q.n = j.at("n").get<size_t>();
    q.median = number(j.at("median"));
    q.p95 = number(j.at("p95"));
    q.p99 = number(j.at("p99"));
    q.max = number(j.at("max"));
    q.over2 = number(j.at("over2"));
    return q;
}

json toJson(const WorkCounts& w)
{
    return { { "pixels", w.pixels }, { "refractionReads", number(w.refractionReads) },
             { "reflectionReads", number(w.reflectionReads) }, { "marchHeights", number(w.marchHeights) } };
}

WorkCounts workFrom(const json& j)
{
    WorkCounts w;
    w.pixels = j.at("pixels");
    w.refractionReads = number(j.at("refractionReads"));
    w.reflectionReads = number(j.at("reflectionReads"));
    w.marchHeights = number(j.at("marchHeights"));
    return w;
}

json toJson(const Record& r)
{
    json j = { { "technique", r.technique }, { "view", r.view }, { "lookup", r.lookup }, { "fresnel", r.fresnel },
               { "caustics", r.caustics }, { "steps", r.steps }, { "textureSize", r.textureSize },
               { "rotation", r.rotation }, { "apparentEye", r.apparentEye }, { "glow", r.glow },
               { "eyeBelow", r.eyeBelow }, { "heldOut", r.heldOut }, { "t", r.t }, { "frameMs", number(r.frameMs) },
               { "plainMs", number(r.plainMs) }, { "ratio", number(r.ratio) }, { "waterPixels", r.waterPixels },
               { "misses", r.misses }, { "tirMismatch", r.tirMismatch }, { "coverageMismatch", r.coverageMismatch },
               { "nanPixels", r.nanPixels }, { "reflectionNotShown", r.reflectionNotShown },
               { "refractionPx", toJson(r.refractionPx) }, { "refractionM", toJson(r.refractionM) },
               { "reflectionTexels", toJson(r.reflectionTexels) },
               { "reflectionShownTexels", toJson(r.reflectionShownTexels) },
               { "reflectionFanTexels", toJson(r.reflectionFanTexels) },
               { "reflectionBeyondFanTexels", toJson(r.reflectionBeyondFanTexels) },
               { "refractionFanPx", toJson(r.refractionFanPx) },
               { "refractionBeyondFanPx", toJson(r.refractionBeyondFanPx) },
               { "refractionOwnPx", toJson(r.refractionOwnPx) },
               { "reflectionOwnShownTexels", toJson(r.reflectionOwnShownTexels) },
               { "reflectionOwnNotShown", r.reflectionOwnNotShown },
               { "reflectionOwnSentUnder", r.reflectionOwnSentUnder },
               { "fresnelError", toJson(r.fresnelError) }, { "drawnSurfacePx", toJson(r.drawnSurfacePx) },
               { "shadedPointCm", toJson(r.shadedPointCm) } };
    j["refractionCauses"] = json(std::vector<size_t>(std::begin(r.refractionCauses), std::end(r.refractionCauses)));
    j["refractionOwnCauses"] = json(std::vector<size_t>(std::begin(r.refractionOwnCauses), std::end(r.refractionOwnCauses)));
    j["work"] = toJson(r.work);
    const CausticsErrors& c = r.causticsErrors;
    j["causticsErrors"] = { { "valid", c.valid }, { "relativeRmse", number(c.relativeRmse) },
                            { "referenceNoise", number(c.referenceNoise) }, { "meanReference", number(c.meanReference) },
                            { "meanRendered", number(c.meanRendered) } };
    const ImageErrors& e = r.image;
    j["image"] = { { "ssimWater", number(e.ssimWater) }, { "ssimFrame", number(e.ssimFrame) },
                   { "deltaEMeanWater", number(e.deltaEMeanWater) }, { "deltaEP95Water", number(e.deltaEP95Water) },
                   { "deltaEMeanFrame", number(e.deltaEMeanFrame) }, { "deltaEP95Frame", number(e.deltaEP95Frame) },
                   { "referenceNoiseWater", number(e.referenceNoiseWater) } };
    return j;
}

Record recordFrom(const json& j)
{
    Record r;
    r.technique = j.at("technique");
    r.view = j.at("view");
    r.lookup = j.at("lookup");
    r.fresnel = j.at("fresnel");
    r.caustics = j.at("caustics");
    r.steps = j.at("steps");
    r.textureSize = j.at("textureSize");
    r.rotation = j.at("rotation");
    r.apparentEye = j.at("apparentEye");
    r.glow = j.at("glow");
    r.eyeBelow = j.at("eyeBelow");
    r.t = j.at("t");
    r.heldOut = j.value("heldOut", false);
    r.frameMs = number(j.at("frameMs"));
    r.plainMs = number(j.at("plainMs"));
    r.ratio = number(j.at("ratio"));
    r.waterPixels = j.at("waterPixels");
    r.misses = j.at("misses");
    r.tirMismatch = j.at("tirMismatch");
    r.coverageMismatch = j.at("coverageMismatch");
    r.nanPixels = j.at("nanPixels");
    r.reflectionNotShown = j.at("reflectionNotShown");
    r.refractionPx = quantilesFrom(j.at("refractionPx"));
    r.refractionM = quantilesFrom(j.at("refractionM"));
    r.reflectionTexels = quantilesFrom(j.at("reflectionTexels"));
    r.reflectionShownTexels = quantilesFrom(j.at("reflectionShownTexels"));
    r.reflectionFanTexels = quantilesFrom(j.at("reflectionFanTexels"));
    r.reflectionBeyondFanTexels = quantilesFrom(j.at("reflectionBeyondFanTexels"));
    r.refractionFanPx = quantilesFrom(j.at("refractionFanPx"));
    r.refractionBeyondFanPx = quantilesFrom(j.at("refractionBeyondFanPx"));
    r.refractionOwnPx = quantilesFrom(j.at("refractionOwnPx"));
    r.reflectionOwnShownTexels = quantilesFrom(j.at("reflectionOwnShownTexels"));
    r.reflectionOwnNotShown = j.at("reflectionOwnNotShown");
    r.reflectionOwnSentUnder = j.at("reflectionOwnSentUnder");
    r.fresnelError = quantilesFrom(j.at("fresnelError"));
    r.drawnSurfacePx = quantilesFrom(j.at("drawnSurfacePx"));
    r.shadedPointCm = quantilesFrom(j.at("shadedPointCm"));
    const std::vector<size_t> causes = j.at("refractionCauses");
    for (size_t c = 0; c < causes.size() && c < size_t(CAUSE_COUNT); ++c) r.refractionCauses[c] = causes[c];
    const std::vector<size_t> ownCauses = j.at("refractionOwnCauses");
    for (size_t c = 0; c < ownCauses.size() && c < size_t(CAUSE_COUNT); ++c) r.refractionOwnCauses[c] = ownCauses[c];
    const json& c = j.at("causticsErrors");
    r.causticsErrors.valid = c.at("valid");
    r.causticsErrors.relativeRmse = number(c.at("relativeRmse"));
    r.causticsErrors.referenceNoise = number(c.at("referenceNoise"));
    r.causticsErrors.meanReference = number(c.at("meanReference"));
    r.causticsErrors.meanRendered = number(c.at("meanRendered"));
    const json& e = j.at("image");
    r.image.ssimWater = number(e.at("ssimWater"));
    r.image.ssimFrame = number(e.at("ssimFrame"));
    r.image.deltaEMeanWater = number(e.at("deltaEMeanWater"));
    r.image.deltaEP95Water = number(e.at("deltaEP95Water"));
    r.image.deltaEMeanFrame = number(e.at("deltaEMeanFrame"));
    r.image.deltaEP95Frame = number(e.at("deltaEP95Frame"));
    r.image.referenceNoiseWater = number(e.at("referenceNoiseWater"));
    r.work = workFrom(j.at("work"));
    return r;
}

json toJson(const Summary& s)
{
    return { { "technique", s.technique }, { "ratioInView", number(s.ratioInView) }, { "frameMs", number(s.frameMs) },
             { "refractionPx", toJson(s.refractionPx) }, { "refractionM", toJson(s.refractionM) },
             { "reflectionTexels", toJson(s.reflectionTexels) }, { "fresnel", toJson(s.fresnel) },
             { "reflectionShownTexels", toJson(s.reflectionShownTexels) },
             { "reflectionFanTexels", toJson(s.reflectionFanTexels) },
             { "reflectionBeyondFanTexels", toJson(s.reflectionBeyondFanTexels) },
             { "refractionFanPx", toJson(s.refractionFanPx) },
             { "refractionBeyondFanPx", toJson(s.refractionBeyondFanPx) },
             { "refractionOwnPx", toJson(s.refractionOwnPx) },
             { "reflectionOwnShownTexels", toJson(s.reflectionOwnShownTexels) },
             { "reflectionOwnNotShownShare", number(s.reflectionOwnNotShownShare) },
             { "drawnSurfacePx", toJson(s.drawnSurfacePx) }, { "shadedPointCm", toJson(s.shadedPointCm) },
             { "worstCoverageShare", number(s.worstCoverageShare) }, { "worstCoverageView", s.worstCoverageView },
             { "reflectionNotShownShare", number(s.reflectionNotShownShare) },
             { "coverageMismatchShare", number(s.coverageMismatchShare) }, { "causticsRmse", number(s.causticsRmse) },
             { "causticsNoise", number(s.causticsNoise) }, { "worstCausticsRmse", number(s.worstCausticsRmse) },
             { "worstCausticsNoise", number(s.worstCausticsNoise) }, { "worstCausticsView", s.worstCausticsView },
             { "imageSsim", number(s.imageSsim) }, { "imageDeltaE", number(s.imageDeltaE) },
             { "worstImageSsim", number(s.worstImageSsim) }, { "worstImageDeltaE", number(s.worstImageDeltaE) },
             { "worstImageView", s.worstImageView }, { "nanPixels", s.nanPixels }, { "work", toJson(s.work) } };
}

Summary summaryFrom(const json& j)
{
    Summary s;
    s.technique = j.at("technique");
    s.ratioInView = number(j.at("ratioInView"));
    s.frameMs = number(j.at("frameMs"));
    s.refractionPx = quantilesFrom(j.at("refractionPx"));
    s.refractionM = quantilesFrom(j.at("refractionM"));
    s.reflectionTexels = quantilesFrom(j.at("reflectionTexels"));
    s.fresnel = quantilesFrom(j.at("fresnel"));
    s.reflectionShownTexels = quantilesFrom(j.at("reflectionShownTexels"));
    s.reflectionFanTexels = quantilesFrom(j.at("reflectionFanTexels"));
    s.reflectionBeyondFanTexels = quantilesFrom(j.at("reflectionBeyondFanTexels"));
    s.refractionFanPx = quantilesFrom(j.at("refractionFanPx"));
    s.refractionBeyondFanPx = quantilesFrom(j.at("refractionBeyondFanPx"));
    s.refractionOwnPx = quantilesFrom(j.at("refractionOwnPx"));
    s.reflectionOwnShownTexels = quantilesFrom(j.at("reflectionOwnShownTexels"));
    s.reflectionOwnNotShownShare = number(j.at("reflectionOwnNotShownShare"));
    s.drawnSurfacePx = quantilesFrom(j.at("drawnSurfacePx"));
    s.shadedPointCm = quantilesFrom(j.at("shadedPointCm"));
    s.worstCoverageShare = number(j.at("worstCoverageShare"));
    s.worstCoverageView = j.at("worstCoverageView");
    s.reflectionNotShownShare = number(j.at("reflectionNotShownShare"));
    s.coverageMismatchShare = number(j.at("coverageMismatchShare"));
    s.causticsRmse = number(j.at("causticsRmse"));
    s.causticsNoise = number(j.at("causticsNoise"));
    s.worstCausticsRmse = number(j.at("worstCausticsRmse"));
    s.worstCausticsNoise = number(j.at("worstCausticsNoise"));
    s.worstCausticsView = j.at("worstCausticsView");
    s.imageSsim = number(j.at("imageSsim"));
    s.imageDeltaE = number(j.at("imageDeltaE"));
    s.worstImageSsim = number(j.at("worstImageSsim"));
    s.worstImageDeltaE = number(j.at("worstImageDeltaE"));
    s.worstImageView = j.at("worstImageView");
    s.nanPixels = j.at("nanPixels");
    s.work = workFrom(j.at("work"));
    return s;
}

// the file's content when it was kept under `key`, else null
json readKept(const std::string& file, const std::string& key)
{
    std::ifstream in(file);
    if (!in) return nullptr;
    const json j = json::parse(in, nullptr, false); // a file cut off mid-write is no file
    if (j.is_discarded() || !j.is_object() || j.value("key", std::string()) != key) return nullptr;
    return j;
}

// written whole to a temporary file first: a run killed mid-write leaves no half file behind
bool writeKept(const std::string& file, json j, const std::string& key, std::string& error)
{
    j["key"] = key;
    const std::string partial = file + ".partial";
    {
        std::ofstream out(partial);
        out << j.dump(1) << '\n';
        if (!out) {
            error = "cannot write " + partial;
            return false;
        }
    }
    if (std::rename(partial.c_str(), file.c_str()) != 0) {
        error = "cannot rename " + partial + " to " + file;
        return false;
    }
    return true;
}

}

ResumeCache::ResumeCache(const std::string& dir, const std::string& sourceKey, const BenchOptions& o)
    : _dir(dir)
{
    if (sourceKey.empty()) return;
    _key = sourceKey + " scene " + o.scene + " views " + o.viewsFile + " size " + std::to_string(o.width) + "x" +
           std::to_string(o.height) + " frames " + std::to_string(o.frames) + " photons " + std::to_string(o.photons) +
           " reference samples " + std::to_string(o.referenceSamples) + " refine " + std::to_string(o.referenceRefine) + " ablation rounds " + std::to_string(o.ablationRounds) +
           (o.waterType.empty() ? "" : " water type " + o.waterType) +
           (o.heldOutFile.empty() ? "" : " held out " + o.heldOutFile) + (o.quick ? " quick" : "");
}

std::string ResumeCache::file(const std::string& name) const { return _dir + "/" + name + ".json"; }

bool ResumeCache::loadTechnique(const std::string& technique, std::vector<Record>& records, Summary& summary) const
{
    if (!enabled()) return false;
    const json j = readKept(file("technique-" + technique), _key);
    if (j.is_null()) return false;
    try {
        std::vector<Record> kept;
        for (const json& r : j.at("records")) kept.push_back(recordFrom(r));
        summary = summaryFrom(j.at("summary"));
        records = std::move(kept);
        return true;
    } catch (const json::exception&) {
        return false; // a file of another layout: measured afresh
    }
}

bool ResumeCache::saveTechnique(const std::string& technique, const std::vector<Record>& records, const Summary& summary,
                                std::string& error) const
{
    if (!enabled()) return true;
    if (!osgDB::makeDirectory(_dir)) {
        error = "cannot create " + _dir;
        return false;
    }
    json j;
    j["records"] = json::array();
    for (const Record& r : records) j["records"].push_back(toJson(r));
    j["summary"] = toJson(summary);
    return writeKept(file("technique-" + technique), j, _key, error);
}

bool ResumeCache::loadAblation(Ablation& ablation) const
{
    if (!enabled()) return false;
    const json j = readKept(file("ablation"), _key);
    if (j.is_null()) return false;
    try {
        Ablation a;
        a.configs = ablationConfigs();
        a.rounds = j.at("rounds");
        a.frames = j.at("frames");
        a.gather = j.at("gather");
        for (const json& v : j.at("views")) {
            AblationView view;
            view.view = v.at("view");
            view.waterInView = v.at("waterInView");
            view.eyeBelow = v.at("eyeBelow");
            for (const auto& [config, ms] : v.at("ms").items()) view.ms[config] = number(ms);
            for (const auto& [effect, ran] : v.at("effectRan").items()) view.effectRan[effect] = ran.get<bool>();
            for (const auto& [pass, ms] : v.at("passMs").items()) view.passMs[std::stoi(pass)] = number(ms);
            for (const auto& [pass, n] : v.at("passFragments").items()) view.passFragments[std::stoi(pass)] = number(n);
            a.views.push_back(std::move(view));
        }
        ablation = std::move(a);
        return true;
    } catch (const std::exception&) {
        return false;
    }
}

bool ResumeCache::saveAblation(const Ablation& a, std::string& error) const
{
    if (!enabled()) return true;
    if (!osgDB::makeDirectory(_dir)) {
        error = "cannot create " + _dir;
        return false;
    }
    json j = { { "rounds", a.rounds }, { "frames", a.frames }, { "gather", a.gather }, { "views", json::array() } };
    for (const AblationView& v : a.views) {
        json view = { { "view", v.view }, { "waterInView", v.waterInView }, { "eyeBelow", v.eyeBelow },
                      { "ms", json::object() }, { "effectRan", json::object() }, { "passMs", json::object() },
                      { "passFragments", json::object() } };
        for (const auto& [config, ms] : v.ms) view["ms"][config] = number(ms);
        for (const auto& [effect, ran] : v.effectRan) view["effectRan"][effect] = ran;
        for (const auto& [pass, ms] : v.passMs) view["passMs"][std::to_string(pass)] = number(ms);
        for (const auto& [pass, n] : v.passFragments) view["passFragments"][std::to_string(pass)] = number(n);
        j["views"].push_back(std::move(view));
    }
    return writeKept(file("ablation"), j, _key, error);
}

}
