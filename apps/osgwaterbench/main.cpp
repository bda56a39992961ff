// osgwaterbench: speed against error. For every technique and view: the frame time beside the
// plain scene's (water removed) in the same run, and the error of the renderer's per-pixel
// estimates against an exact Embree reference (refraction, reflection, Fresnel) and of its
// caustics against photon tracing. Writes results.json / results.csv and, with --docs, the
// generated BENCHMARKS.md and its plot.
#include "node/WaterNodeImpl.h"
#include "FresnelFigure.h"
#include "Ablation.h"
#include "BenchOptions.h"
#include "ResumeCache.h"
#include "Probe.h"
#include "ReferenceCaustics.h"
#include "ReferenceRenderer.h"
#include "Report.h"
#include "Techniques.h"
#include "Views.h"
#include "../common/FrameTimer.h"
#include "../common/SceneWater.h"
#include "../common/Today.h"
#include "frame/SceneLighting.h"
#include <osgWater/WaterTypes>
#include <osgDB/FileUtils>
#include <osgDB/ReadFile>
#include <osgDB/WriteFile>
#include <osg/GL>
#include <osg/Switch>
#include <osg/Timer>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <thread>
#include <iostream>
#include <map>
#include <tuple>
#include <memory>
#include <glm/geometric.hpp>

using namespace bench;

namespace {

// A view's name as a file name: its letters and digits, a hyphen for each run of anything else
// the pixels whose reference ray meets the water first
std::vector<bool> waterPixelsOf(const ReferenceImage& traced)
{
    std::vector<bool> water(traced.pixels.size());
    for (size_t i = 0; i < traced.pixels.size(); ++i) water[i] = traced.pixels[i].flags & PixelRef::WATER;
    return water;
}

std::string fileName(const std::string& view)
{
    std::string f;
    for (char c : view) {
        if (std::isalnum(static_cast<unsigned char>(c))) f += char(std::tolower(static_cast<unsigned char>(c)));
        else if (!f.empty() && f.back() != '-') f += '-';
    }
    while (!f.empty() && f.back() == '-') f.pop_back();
    return f.empty() ? "view" : f;
}

// frame times are means over blocks of this many frames (then the median over blocks)
const size_t kTimingBlock = 5;
// the resume cache's name for the held-out views' records
const char* const kHeldOut = "held-out";

// Loads an .osgt with a WaterNode, or any model with water added at z = 0 over its extent.
osg::ref_ptr<osgWater::WaterNode> loadScene(const std::string& file, osg::ref_ptr<osg::Node>& root)
{
    root = osgDB::readRefNodeFile(file);
    if (!root.valid()) return nullptr;
    bool added = false;
    osg::ref_ptr<osgWater::WaterNode> water = osgWaterApps::findOrAddWater(root, file, &added);
    if (added) { // cover the model
        const osg::BoundingSphere b = water->getChild(0)->getBound();
        water->getSurface()->setSize(float(2.0 * b.radius()));
        water->getSurface()->setCenter(osg::Vec2(b.center().x(), b.center().y()));
    }
    return water;
}

// frame times of `frames` frames after `warmup`, advancing time like an animation
std::vector<double> timeFrames(osgViewer::Viewer& viewer, double& t, int warmup, int frames)
{
    std::vector<double> ms;
    for (int i = 0; i < warmup + frames; ++i) {
        const osg::Timer_t t0 = osg::Timer::instance()->tick();
        viewer.frame(t);
        t += 1.0 / 60.0;
        if (i >= warmup) ms.push_back(osg::Timer::instance()->delta_m(t0, osg::Timer::instance()->tick()));
    }
    return ms;
}

Summary summarize(const std::string& name, const std::vector<Record>& records, std::vector<ViewErrors>& errors)
{
    Summary s;
    s.technique = name;
    std::vector<double> ratios, frames, caustics, noise, ssims, deltaEs;
    std::vector<float> px, m, refl, reflShown, reflFan, reflBeyond, refrFan, refrBeyond, refrOwn, reflOwn, fres, drawn, shaded;
    size_t notShown = 0, ownNotShown = 0, coverageMismatch = 0, waterPixels = 0;
    for (size_t i = 0; i < records.size(); ++i) {
        const Record& r = records[i];
        if (r.technique != name) continue;
        if (r.waterPixels > 0 && !r.eyeBelow) {
            ratios.push_back(r.ratio);
            frames.push_back(r.frameMs);
        }
        if (r.causticsErrors.valid) {
            caustics.push_back(r.causticsErrors.relativeRmse);
            noise.push_back(r.causticsErrors.referenceNoise);
            if (!(r.causticsErrors.relativeRmse <= s.worstCausticsRmse)) {
                s.worstCausticsRmse = r.causticsErrors.relativeRmse;
                s.worstCausticsNoise = r.causticsErrors.referenceNoise;
                s.worstCausticsView = r.view;
            }
        }
        if (std::isfinite(r.image.ssimWater) && std::isfinite(r.image.deltaEMeanWater)) {
            ssims.push_back(r.image.ssimWater);
            deltaEs.push_back(r.image.deltaEMeanWater);
            if (!(r.image.ssimWater >= s.worstImageSsim)) s.worstImageSsim = r.image.ssimWater;
            if (!(r.image.deltaEMeanWater <= s.worstImageDeltaE)) {
                s.worstImageDeltaE = r.image.deltaEMeanWater;
                s.worstImageView = r.view;
            }
        }
        s.nanPixels += r.nanPixels;
        px.insert(px.end(), errors[i].refractionPx.begin(), errors[i].refractionPx.end());
        m.insert(m.end(), errors[i].refractionM.begin(), errors[i].refractionM.end());
        refl.insert(refl.end(), errors[i].reflectionTexels.begin(), errors[i].reflectionTexels.end());
        reflShown.insert(reflShown.end(), errors[i].reflectionShownTexels.begin(), errors[i].reflectionShownTexels.end());
        reflFan.insert(reflFan.end(), errors[i].reflectionFanTexels.begin(), errors[i].reflectionFanTexels.end());
        reflBeyond.insert(reflBeyond.end(), errors[i].reflectionBeyondFanTexels.begin(), errors[i].reflectionBeyondFanTexels.end());
        refrFan.insert(refrFan.end(), errors[i].refractionFanPx.begin(), errors[i].refractionFanPx.end());
        refrBeyond.insert(refrBeyond.end(), errors[i].refractionBeyondFanPx.begin(), errors[i].refractionBeyondFanPx.end());
        refrOwn.insert(refrOwn.end(), errors[i].refractionOwnPx.begin(), errors[i].refractionOwnPx.end());
        reflOwn.insert(reflOwn.end(), errors[i].reflectionOwnShownTexels.begin(), errors[i].reflectionOwnShownTexels.end());
        ownNotShown += errors[i].reflectionOwnNotShown;
        notShown += errors[i].reflectionNotShown;
        coverageMismatch += r.coverageMismatch;
        waterPixels += r.waterPixels;
        if (r.waterPixels) {
            const double share = double(r.coverageMismatch) / double(r.waterPixels);
            if (!(share <= s.worstCoverageShare)) {
                s.worstCoverageShare = share;
                s.worstCoverageView = r.view;
            }
        }
        drawn.insert(drawn.end(), errors[i].drawnSurfacePx.begin(), errors[i].drawnSurfacePx.end());
        shaded.insert(shaded.end(), errors[i].shadedPointCm.begin(), errors[i].shadedPointCm.end());
        fres.insert(fres.end(), errors[i].fresnel.begin(), errors[i].fresnel.end());
        s.work = s.work.pooledWith(r.work);
        errors[i] = ViewErrors(); // pooled: free the per-pixel values
    }
    s.ratioInView = ratios.empty() ? std::numeric_limits<double>::quiet_NaN() : osgWaterApps::median(ratios);
    s.frameMs = frames.empty() ? std::numeric_limits<double>::quiet_NaN() : osgWaterApps::median(frames);
    if (!caustics.empty()) {
        s.causticsRmse = osgWaterApps::median(caustics);
        s.causticsNoise = osgWaterApps::median(noise);
    }
    auto mean = [](const std::vector<double>& v) {
        double sum = 0.0;
        for (double x : v) sum += x;
        return v.empty() ? std::numeric_limits<double>::quiet_NaN() : sum / double(v.size());
    };
    s.imageSsim = mean(ssims);
    s.imageDeltaE = mean(deltaEs);
    s.refractionPx = quantiles(px);
    s.refractionM = quantiles(m);
    s.reflectionTexels = quantiles(refl);
    s.reflectionShownTexels = quantiles(reflShown);
    s.reflectionFanTexels = quantiles(reflFan);
    s.reflectionBeyondFanTexels = quantiles(reflBeyond);
    s.refractionFanPx = quantiles(refrFan);
    s.refractionBeyondFanPx = quantiles(refrBeyond);
    s.refractionOwnPx = quantiles(refrOwn);
    s.reflectionOwnShownTexels = quantiles(reflOwn);
    if (!reflOwn.empty() || ownNotShown) s.reflectionOwnNotShownShare = double(ownNotShown) / double(reflOwn.size() + ownNotShown);
    if (!refl.empty()) s.reflectionNotShownShare = double(notShown) / double(refl.size());
    if (waterPixels) s.coverageMismatchShare = double(coverageMismatch) / double(waterPixels);
    s.fresnel = quantiles(fres);
    s.drawnSurfacePx = quantiles(drawn);
    s.shadedPointCm = quantiles(shaded);
    return s;
}

// WaterNode::getSurfaceHeightAt with the normal, on one thread: a grid of points over the surface's
// box visited `n` times in all (the median of five such runs)
double heightQueriesPerSecond(const osgWater::WaterNode& water, int n)
{
    const osg::BoundingBox& box = water.getSurface()->getBoundingBox();
    std::vector<double> rates;
    double sink = 0.0;
    for (int run = 0; run < 5; ++run) {
        const osg::Timer_t start = osg::Timer::instance()->tick();
        for (int i = 0; i < n; ++i) {
            const double u = (i % 1009) / 1009.0, v = (i / 1009 % 997) / 997.0;
            osg::Vec3d normal;
            sink += water.getSurfaceHeightAt(box.xMin() + u * (box.xMax() - box.xMin()),
                                             box.yMin() + v * (box.yMax() - box.yMin()), 10.0 + run, &normal) + normal.z();
        }
        rates.push_back(n / std::max(osg::Timer::instance()->delta_s(start, osg::Timer::instance()->tick()), 1e-9));
    }
    if (!std::isfinite(sink)) std::cout << "height queries gave a non-finite value" << std::endl;
    return osgWaterApps::median(rates);
}

}

int main(int argc, char** argv)
{
    BenchOptions o;
    std::string error;
    if (!o.read(argc, argv, error)) {
        std::cerr << "error: " << error << std::endl;
        return 2;
    }
    if (o.help) return 0;
    if (!o.fresnelFigure.empty()) {
        std::string written;
        if (!writeFresnelFigure(o.fresnelFigure, written)) {
            std::cerr << "error: " << written << std::endl;
            return 1;
        }
        std::cout << "wrote " << written << std::endl;
        return 0;
    }
    std::vector<View> views;
    if (!readViews(o.viewsFile, views, error)) {
        std::cerr << "error: " << error << std::endl;
        return 2;
    }
    if (o.quick) views.resize(1);
    std::vector<View> heldOut;
    if (!o.heldOutFile.empty()) {
        if (!readViews(o.heldOutFile, heldOut, error)) {
            std::cerr << "error: " << error << std::endl;
            return 2;
        }
        if (o.quick) heldOut.resize(1);
    }
    std::vector<Technique> techniques;
    if (!selectTechniques(o.techniques, techniques, error)) {
        std::cerr << "error: " << error << std::endl;
        return 2;
    }
    if (!osgDB::fileExists(o.scene)) {
        std::cerr << "error: scene file " << o.scene << " not found" << std::endl;
        return 2;
    }
    osg::ref_ptr<osg::Node> loaded;
    osg::ref_ptr<osgWater::WaterNode> water = loadScene(o.scene, loaded);
    if (!water.valid()) {
        std::cerr << "error: could not read " << o.scene << std::endl;
        return 2;
    }
    if (!o.waterType.empty() && !osgWater::applyWaterType(*water->getSettings(), o.waterType)) return 2; // it names the presets
    if (!osgDB::makeDirectory(o.out)) {
        std::cerr << "error: cannot create the output folder " << o.out << std::endl;
        return 2;
    }

    // the water scene and the plain one (the same children, no water) behind one switch
    osg::ref_ptr<osg::Group> plain = new osg::Group;
    for (unsigned i = 0; i < water->getNumChildren(); ++i) plain->addChild(water->getChild(i));
    osg::ref_ptr<osg::Switch> scenes = new osg::Switch;
    scenes->addChild(loaded.get(), true);
    scenes->addChild(plain.get(), false);

    // timing: the demo's headless set-up (8-bit target, glFinish at the end of each frame)
    osgViewer::Viewer timing;
    if (!osgWaterApps::setUpViewer(timing, true, o.width, o.height)) return 1;
    timing.getCamera()->setFinalDrawCallback(new osgWaterApps::FinishFrame);
    timing.getCamera()->setClearColor(osg::Vec4(0.55f, 0.7f, 0.9f, 1.0f));
    timing.setSceneData(scenes.get());
    // errors: the same viewer with a float target while the debug outputs are read
    Probe probe(&timing);
    if (!probe.ok()) {
        std::cerr << "error: " << probe.why() << std::endl;
        return 1;
    }

    RunInfo info;
    info.command = o.commandLine;
    info.scene = o.scene;
    info.viewsFile = o.viewsFile;
    info.width = o.width;
    info.height = o.height;
    info.frames = o.frames;
    info.photons = o.photons;
    info.referenceSamples = o.referenceSamples;
    info.referenceRefine = o.referenceRefine;
    info.quick = o.quick;
    info.date = osgWaterApps::today();
    info.cpus = std::thread::hardware_concurrency();

    // settle: proxies loaded, programs linked, the caustics' automatic gather chosen
    double t = views[0].t;
    timing.getCamera()->setViewMatrixAsLookAt(views[0].eye, views[0].center, views[0].up);
    timeFrames(timing, t, o.quick ? 2 : 30, 0);
    if (const GLubyte* r = glGetString(GL_RENDERER)) info.renderer = reinterpret_cast<const char*>(r);
    info.heightQueriesPerSecond = heightQueriesPerSecond(*water, o.quick ? 20000 : 2000000);
    std::cout << "height queries (with normal, one thread): " << std::lround(info.heightQueriesPerSecond)
              << " per second" << std::endl;

    const osg::ref_ptr<osgWater::WaterSettings> base =
        new osgWater::WaterSettings(*water->getSettings(), osg::CopyOp::DEEP_COPY_ALL);

    // the ablation: every effect off in turn, the skips off, the presets, timed in one run
    const ResumeCache kept(o.out + "/resume", o.resumeKey, o);
    Ablation ablation;
    if (o.ablationRounds > 0) {
        if (kept.loadAblation(ablation))
            std::cout << "ablation: kept from an earlier run of this build" << std::endl;
        else {
            ablation = runAblation(timing, scenes.get(), *water, views, *base, o.ablationRounds, o.quick ? 2 : 5);
            if (!kept.saveAblation(ablation, error)) {
                std::cerr << "error: " << error << std::endl;
                return 1;
            }
        }
        if (!writeAblationCsv(o.out + "/ablation.csv", ablation, error)) {
            std::cerr << "error: " << error << std::endl;
            return 1;
        }
        printAblation(ablation);
        if (o.ablationOnly) return 0;
    }
    const Media media{ base->getAirIOR(), base->getWaterIOR() };
    SceneShading sceneShading;
    const RayCaster sceneCaster(collectScene(*water, &sceneShading));
    std::cout << "reference: " << sceneCaster.size() << " scene triangles" << std::endl;
    // the reference image's light and sky: the scene's own settings (no technique changes them)
    ImageSetup imageLight = imageSetup(*water, timing.getCamera()->getClearColor());
    imageLight.samplesPerAxis = o.referenceSamples;
    imageLight.refineSamplesPerAxis = o.referenceRefine;
    std::map<std::pair<size_t, int>, std::vector<glm::vec3>> referenceImages; // (view, model) -> linear light
    std::map<std::pair<size_t, int>, double> referenceNoises;                 // ... and its own noise
    const std::string tripletDir = o.out + "/triplets";
    if (!osgDB::makeDirectory(tripletDir)) {
        std::cerr << "error: cannot create the folder " << tripletDir << std::endl;
        return 2;
    }
    std::map<double, std::unique_ptr<WaterCaster>> waterCasters;
    // the references of each wave model's surface: (view, model) -> reference image, and
    // (time, caustics resolution, model) -> caustics
    std::map<std::pair<size_t, int>, ReferenceImage> references;
    std::map<std::tuple<double, int, int>, PhotonImage> photonImages;
    osgWater::WaterSurface* surface = water->getSurface();
    const osgWater::WaterSurface::MeshLayout sceneMesh = surface->getMeshLayout();
    const osgWater::WaterSurface::WaveModel sceneWaves = surface->getWaveModel();
    for (const std::vector<View>* list : { &views, &heldOut })
        for (const View& v : *list)
            if (!waterCasters.count(v.t)) waterCasters[v.t] = std::make_unique<WaterCaster>(*surface, v.t);
    std::cout << "reference: " << waterCasters.begin()->second->describe() << std::endl;
    // the caustics reference at a time, over a window at a resolution (a preset may change it)
    auto photonsAt = [&](double t, int resolution, int model, const osg::Matrixd& localToSun) -> const PhotonImage& {
        const std::tuple<double, int, int> key(t, resolution, model);
        auto it = photonImages.find(key);
        if (it == photonImages.end()) {
            PhotonSettings ps;
            ps.photons = o.photons;
            ps.resolution = resolution;
            ps.attenuation = osgWater::photonExtinction(*base); // what the photon pass fades by
            ps.media = media;
            ps.progress = !o.quick;
            std::cout << "caustics reference at t = " << t << " s:" << std::endl;
            it = photonImages.emplace(key, tracePhotons(sceneCaster, *waterCasters[t], *surface, t, localToSun,
                                                        base->getSunDirection(), ps)).first;
        }
        return it->second;
    };

    // one view under one technique (its settings `s` on the water, the surface's wave model
    // `model`): timed, captured, against its reference; `vi` keys the view's references
    auto measureOne = [&](size_t vi, const View& v, const Technique& tech, const osgWater::WaterSettings* s, int model,
                          Record& r, ViewErrors& ve) {
        r.technique = tech.name;
        r.view = v.name;
        r.t = v.t;
        r.lookup = lookupName(*s);
        r.steps = s->getRefractionLookup() == osgWater::WaterSettings::ONE_STEP ? 1 : s->getSearchSteps();
        r.textureSize = s->getRefractionTextureSize();
        r.rotation = s->getRefractionCameraRotation();
        r.apparentEye = r.rotation && s->getRefractionCameraApparentEye();
        r.fresnel = fresnelName(*s);
        r.caustics = causticsName(*s);
        r.glow = s->getGlowEnabled();

        const osg::Timer_t start = osg::Timer::instance()->tick();
        // speed: plain, water, plain again, side by side
        timing.getCamera()->setViewMatrixAsLookAt(v.eye, v.center, v.up);
        double tt = v.t;
        const int plainFrames = std::max(o.frames / 3, 3);
        scenes->setSingleChildOn(1);
        std::vector<double> plainMs = timeFrames(timing, tt, 2, plainFrames);
        scenes->setSingleChildOn(0);
        const std::vector<double> waterMs = timeFrames(timing, tt, 3, o.frames);
        scenes->setSingleChildOn(1);
        const std::vector<double> after = timeFrames(timing, tt, 2, plainFrames);
        plainMs.insert(plainMs.end(), after.begin(), after.end());
        scenes->setSingleChildOn(0);
        r.frameMs = osgWaterApps::medianOfBlockMeans(waterMs, kTimingBlock);
        r.plainMs = osgWaterApps::medianOfBlockMeans(plainMs, kTimingBlock);
        r.ratio = r.plainMs > 0.0 ? r.frameMs / r.plainMs : 0.0;

        const osg::Timer_t phase = osg::Timer::instance()->tick();
        // error: the estimates against the reference
        const Estimate e = probe.capture(*water, v.t);
        const WaterCaster& waterCaster = *waterCasters[v.t];
        const Reference reference(sceneCaster, waterCaster, *surface, v.t, media);
        ReferenceImage& traced = references[{ vi, model }];
        if (traced.pixels.empty())
            traced = traceView(reference, probe.camera()->getViewMatrix(), probe.camera()->getProjectionMatrix(), o.width,
                               o.height);
        const osgWater::CausticsCamera* cc = osgWater::internals(*water).getCausticsCamera();
        std::vector<glm::vec3>& referenceImage = referenceImages[{ vi, model }];
        if (referenceImage.empty()) {
            // the bed's caustics and underwater shadows from the photon reference, over the
            // window of this technique's caustics (any window will do: the photons are exact)
            ImageSetup setup = imageLight;
            if (cc && s->getCausticsEnabled() && !cc->getLighting().procedural) {
                UnderwaterSun sun;
                sun.photons = &photonsAt(v.t, cc->getResolution(), model, cc->getLighting().localToSun);
                sun.localToSun = cc->getLighting().localToSun;
                sun.intensity = base->getCausticsIntensity();
                const osg::Vec3f channels = osgWater::channelExtinction(*base);
                sun.channelExtinction = glm::dvec3(channels.x(), channels.y(), channels.z());
                sun.level = surface->getLevel();
                sun.towardsSun = setup.light.towardsSun;
                sun.airIOR = media.air;
                sun.waterIOR = media.water;
                setup.light.sunShare = underwaterSunShare(sun, sceneCaster);
            } else {
                std::cout << "reference image of " << v.name << " without caustics: " << tech.name
                          << " draws none from photons (measure the default first)" << std::endl;
            }
            const ReferenceRenderer renderer(reference, sceneShading, setup);
            RenderExtras extras;
            referenceImage = renderer.render(probe.camera()->getViewMatrix(), probe.camera()->getProjectionMatrix(),
                                             o.width, o.height, &extras);
            referenceNoises[{ vi, model }] = referenceNoise(extras.halves[0], extras.halves[1],
                                                            DisplayTransform{ s->getExposure(), s->getToneCurve() },
                                                            waterPixelsOf(traced));
            std::cout << "reference image of " << v.name << ": " << extras.refinedPixels << " noisy pixels took "
                      << setup.refineSamplesPerAxis << " x " << setup.refineSamplesPerAxis << " more rays" << std::endl;
        }
        const double captureAndTraceS = osg::Timer::instance()->delta_s(phase, osg::Timer::instance()->tick());
        r.eyeBelow = reference.eyeBelow(glm::dvec3(v.eye.x(), v.eye.y(), v.eye.z()));
        ve = measureView(traced, e, sceneCaster);
        ve.drawnSurfacePx = drawnSurfaceError(e, *surface, v.t);
        r.waterPixels = ve.waterPixels;
        r.misses = ve.misses;
        r.tirMismatch = ve.tirMismatch;
        r.coverageMismatch = ve.coverageMismatch;
        r.nanPixels = ve.nanPixels;
        r.work = countWork(e.work.get());
        if (e.color.valid()) {
            const DisplayTransform display{ s->getExposure(), s->getToneCurve() };
            osg::ref_ptr<osg::Image> side;
            r.image = compareWithReference(*e.color, referenceImage, display, waterPixelsOf(traced),
                                           tech.name == "default" ? &side : nullptr);
            r.image.referenceNoiseWater = referenceNoises[{ vi, model }];
            if (side.valid()) {
                osgDB::writeImageFile(*side, tripletDir + "/" + fileName(v.name) + ".png");
                if (vi == 0 && !o.docs.empty() && osgDB::makeDirectory(o.docs))
                    osgDB::writeImageFile(*side, o.docs + "/benchmark-reference.png");
            }
        }
        {
            std::vector<float> a = ve.refractionPx, b = ve.refractionM, c = ve.reflectionTexels, d = ve.fresnel,
                               c2 = ve.reflectionShownTexels, c3 = ve.reflectionFanTexels,
                               c4 = ve.reflectionBeyondFanTexels, a2 = ve.refractionFanPx,
                               a3 = ve.refractionBeyondFanPx, a4 = ve.refractionOwnPx, c5 = ve.reflectionOwnShownTexels;
            r.refractionPx = quantiles(a);
            r.refractionM = quantiles(b);
            r.reflectionTexels = quantiles(c);
            r.reflectionShownTexels = quantiles(c2);
            r.reflectionFanTexels = quantiles(c3);
            r.reflectionBeyondFanTexels = quantiles(c4);
            r.refractionFanPx = quantiles(a2);
            r.refractionBeyondFanPx = quantiles(a3);
            r.refractionOwnPx = quantiles(a4);
            r.reflectionOwnShownTexels = quantiles(c5);
            r.reflectionOwnNotShown = ve.reflectionOwnNotShown;
            r.reflectionOwnSentUnder = ve.reflectionOwnSentUnder;
            std::copy(std::begin(ve.refractionOwnCauses), std::end(ve.refractionOwnCauses), std::begin(r.refractionOwnCauses));
            r.reflectionNotShown = ve.reflectionNotShown;
            r.fresnelError = quantiles(d);
            std::vector<float> ds = ve.drawnSurfacePx, sp = ve.shadedPointCm;
            r.drawnSurfacePx = quantiles(ds);
            r.shadedPointCm = quantiles(sp);
            std::copy(std::begin(ve.refractionCauses), std::end(ve.refractionCauses), std::begin(r.refractionCauses));
        }
        if (osg::ref_ptr<osg::Image> caustics = probe.readCaustics(*water)) {
            r.nanPixels += countNonFinite(caustics.get());
            // a tile: what the scene shader reads at the bed point under each texel of the sun's
            // window, at the tile's texel size
            int resolution = cc->getResolution();
            if (cc->getLighting().tiled) {
                const double tileTexel = water->getSettings()->getCausticsTileSize() / cc->getResolution();
                const double window = std::max(cc->getWindow().x(), cc->getWindow().y());
                resolution = std::max(1, int(std::lround(window / tileTexel)));
                caustics = tileSeenFromTheSun(caustics.get(), sceneCaster, cc->getLighting(),
                                              water->getSettings()->getSunDirection(), surface->getLevel(), resolution);
            }
            const PhotonImage& photons = photonsAt(v.t, resolution, model, cc->getLighting().localToSun);
            // blocks of one size on the bed whatever the window and resolution (a focused window
            // has fewer texels of the same size): comparable across techniques
            const double texelMetres = std::max(cc->getWindow().x(), cc->getWindow().y()) / resolution;
            const int block = std::max(1, int(std::lround(kCausticsBlockMetres / texelMetres)));
            r.causticsErrors = measureCaustics(photons, caustics.get(), block);
        }
        std::printf("%-24s %-28s %8.1f ms  plain %6.1f ms  x%.2f  refraction px median %.3f p99 %.2f  NaN %zu"
                    "  (timing %.0f s, capture+reference %.0f s, metrics %.0f s)\n",
                    tech.name.c_str(), v.name.c_str(), r.frameMs, r.plainMs, r.ratio, r.refractionPx.median,
                    r.refractionPx.p99, r.nanPixels, osg::Timer::instance()->delta_s(start, phase), captureAndTraceS,
                    osg::Timer::instance()->delta_s(phase, osg::Timer::instance()->tick()) - captureAndTraceS);
        std::fflush(stdout);
    };

    std::vector<Record> records;
    std::vector<Summary> summaries;
    for (const Technique& tech : techniques) {
        std::vector<Record> techRecords;
        Summary summary;
        if (kept.loadTechnique(tech.name, techRecords, summary)) {
            std::cout << tech.name << ": kept from an earlier run of this build" << std::endl;
            records.insert(records.end(), techRecords.begin(), techRecords.end());
            summaries.push_back(summary);
            continue;
        }
        std::vector<ViewErrors> errors;
        osg::ref_ptr<osgWater::WaterSettings> s = new osgWater::WaterSettings(*base, osg::CopyOp::DEEP_COPY_ALL);
        tech.apply(*s);
        water->setSettings(s.get());
        surface->setMeshLayout(tech.mesh ? *tech.mesh : sceneMesh);
        surface->setWaveModel(tech.waves ? *tech.waves : sceneWaves);
        const int model = int(surface->getWaveModel());
        for (size_t vi = 0; vi < views.size(); ++vi) {
            Record r;
            ViewErrors ve;
            measureOne(vi, views[vi], tech, s.get(), model, r, ve);
            techRecords.push_back(r);
            errors.push_back(std::move(ve));
        }
        summary = summarize(tech.name, techRecords, errors);
        if (!kept.saveTechnique(tech.name, techRecords, summary, error)) {
            std::cerr << "error: " << error << std::endl;
            return 1;
        }
        records.insert(records.end(), techRecords.begin(), techRecords.end());
        summaries.push_back(summary);
    }
    // the held-out views: the default technique alone, kept apart from every median and the ablation
    if (!heldOut.empty()) {
        std::vector<Record> heldRecords;
        Summary unused;
        if (kept.loadTechnique(kHeldOut, heldRecords, unused))
            std::cout << "held-out views: kept from an earlier run of this build" << std::endl;
        else {
            std::vector<Technique> only;
            selectTechniques("default", only, error);
            osg::ref_ptr<osgWater::WaterSettings> s = new osgWater::WaterSettings(*base, osg::CopyOp::DEEP_COPY_ALL);
            only.front().apply(*s);
            water->setSettings(s.get());
            surface->setMeshLayout(sceneMesh);
            surface->setWaveModel(sceneWaves);
            std::vector<ViewErrors> errors;
            for (size_t hi = 0; hi < heldOut.size(); ++hi) {
                Record r;
                ViewErrors ve;
                measureOne(views.size() + hi, heldOut[hi], only.front(), s.get(), int(sceneWaves), r, ve);
                r.heldOut = true;
                heldRecords.push_back(r);
                errors.push_back(std::move(ve));
            }
            if (!kept.saveTechnique(kHeldOut, heldRecords, summarize("default", heldRecords, errors), error)) {
                std::cerr << "error: " << error << std::endl;
                return 1;
            }
        }
        records.insert(records.end(), heldRecords.begin(), heldRecords.end());
    }
    water->setSettings(new osgWater::WaterSettings(*base, osg::CopyOp::DEEP_COPY_ALL));
    surface->setMeshLayout(sceneMesh);
    surface->setWaveModel(sceneWaves);

    if (!writeJson(o.out + "/results.json", records, error) || !writeCsv(o.out + "/results.csv", records, error)) {
        std::cerr << "error: " << error << std::endl;
        return 1;
    }
    std::cout << "wrote " << o.out << "/results.json and results.csv (" << records.size() << " records)" << std::endl;
    if (!o.docs.empty()) {
        if (!osgDB::makeDirectory(o.docs) ||
            !writeDocs(o.docs, info, records, summaries, o.ablationRounds > 0 ? &ablation : nullptr, error)) {
            std::cerr << "error: " << error << std::endl;
            return 1;
        }
        std::cout << "wrote " << o.docs << "/BENCHMARKS.md" << std::endl;
    }
    return 0;
}
