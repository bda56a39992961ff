#include "BenchOptions.h"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>

namespace bench {

namespace {

const char* kUsage =
    "usage: osgwaterbench --scene FILE --views FILE [--size WxH] [--out DIR] [--techniques LIST]\n"
    "                     [--docs DIR] [--frames N] [--photons N] [--reference-samples N] [--quick]\n"
    "                     [--ablation-rounds N] [--ablation-only] [--resume KEY] [--water-type NAME]\n"
    "                     [--held-out FILE]\n"
    "       osgwaterbench --fresnel-figure DIR\n"
    "  --scene FILE       .osgt/.osgb with an osgWater::WaterNode, or any model (water added at z = 0)\n"
    "  --views FILE       one view per line: ex ey ez cx cy cz ux uy uz [t] [# name]\n"
    "  --size WxH         viewport (default 1280x720)\n"
    "  --out DIR          results.json and results.csv go here (default bench-out)\n"
    "  --techniques LIST  comma-separated technique names, or all (default)\n"
    "  --docs DIR         also regenerate DIR/BENCHMARKS.md and DIR/benchmark-speed-error.png\n"
    "  --frames N         timed frames per technique and view (default 30, at least 30)\n"
    "  --photons N        photons of the caustics reference (default 4000000)\n"
    "  --reference-samples N  the reference image's rays a pixel: N x N (default 2, 1..8)\n"
    "  --reference-refine M   and M x M more where the two halves of a pixel's rays disagree by over 1%\n"
    "                     (the far water's sub-pixel waves; default 4, 0..8, 0: none)\n"
    "  --water-type NAME  a water preset (WaterTypes: clear-lake, murky-pond, ...) on the scene's\n"
    "                     settings before every technique (default: the scene's as they are)\n"
    "  --held-out FILE    more views (the same format), measured with the default technique alone and\n"
    "                     kept out of every median, summary and the ablation: views no setting was\n"
    "                     chosen on, with their own table (--quick: the first)\n"
    "  --ablation-rounds N  alternating rounds of the ablation table (default 3, 0: none)\n"
    "  --ablation-only    the ablation table alone (timing; no techniques, no reference)\n"
    "  --resume KEY       keep each finished technique and the ablation under OUT/resume, and take\n"
    "                     those a run with the same KEY and options finished instead of measuring\n"
    "                     them again (KEY names the build: scripts/bench.sh gives the sources' trees)\n"
    "  --fresnel-figure DIR  only write DIR/FRESNEL.md and DIR/fresnel-approximations.png (the\n"
    "                     reciprocal-power Fresnel fit) and exit\n"
    "  --quick            smoke run: 96x64, first view, default and one-step, 3 frames, 20000 photons\n";

bool number(const char* s, double& out)
{
    char* end = nullptr;
    out = std::strtod(s, &end);
    return end != s && *end == '\0' && std::isfinite(out);
}

// option `name`'s value `v` as a whole number lo..hi, else false with a message
bool wholeNumber(const std::string& name, const std::string& v, int lo, int hi, int& out, std::string& error)
{
    double x = 0.0;
    if (!number(v.c_str(), x) || x < lo || x > hi || x != std::floor(x)) {
        error = name + " " + v + ": expected a whole number " + std::to_string(lo) + ".." + std::to_string(hi);
        return false;
    }
    out = int(x);
    return true;
}

}

bool BenchOptions::read(int argc, char** argv, std::string& error)
{
    bool sizeGiven = false, framesGiven = false, photonsGiven = false;
    // the command as the docs show it: the resume key names a build, not a measurement
    for (int i = 0; i < argc; ++i) {
        if (i > 0 && std::string(argv[i]) == "--resume") { ++i; continue; }
        commandLine += (i ? " " : "") + std::string(i ? argv[i] : "osgwaterbench");
    }
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&](std::string& out) {
            if (i + 1 >= argc) { error = a + " needs a value"; return false; }
            out = argv[++i];
            return true;
        };
        std::string v;
        double x = 0.0;
        if (a == "-h" || a == "--help") { std::cout << kUsage; help = true; return true; }
        else if (a == "--quick") quick = true;
        else if (a == "--ablation-only") ablationOnly = true;
        else if (a == "--ablation-rounds") {
            if (!value(v)) return false;
            if (!number(v.c_str(), x) || x < 0 || x > 100) { error = "--ablation-rounds " + v + ": expected 0..100"; return false; }
            ablationRounds = int(x);
        }
        else if (a == "--scene") { if (!value(scene)) return false; }
        else if (a == "--views") { if (!value(viewsFile)) return false; }
        else if (a == "--out") { if (!value(out)) return false; }
        else if (a == "--docs") { if (!value(docs)) return false; }
        else if (a == "--fresnel-figure") { if (!value(fresnelFigure)) return false; }
        else if (a == "--techniques") { if (!value(techniques)) return false; }
        else if (a == "--water-type") { if (!value(waterType)) return false; }
        else if (a == "--held-out") { if (!value(heldOutFile)) return false; }
        else if (a == "--resume") { if (!value(resumeKey)) return false; }
        else if (a == "--size") {
            if (!value(v)) return false;
            if (std::sscanf(v.c_str(), "%dx%d", &width, &height) != 2 || width < 1 || height < 1 || width > 8192 || height > 8192) {
                error = "--size " + v + ": expected WxH with 1..8192 pixels per side";
                return false;
            }
            sizeGiven = true;
        } else if (a == "--frames") {
            if (!value(v)) return false;
            if (!number(v.c_str(), x) || x < 1 || x > 100000) { error = "--frames " + v + ": expected 1..100000"; return false; }
            frames = int(x);
            framesGiven = true;
        } else if (a == "--photons") {
            if (!value(v)) return false;
            if (!number(v.c_str(), x) || x < 1 || x > 1e10) { error = "--photons " + v + ": expected 1..1e10"; return false; }
            photons = size_t(x);
            photonsGiven = true;
        } else if (a == "--reference-samples") {
            if (!value(v) || !wholeNumber(a, v, 1, 8, referenceSamples, error)) return false;
        } else if (a == "--reference-refine") {
            if (!value(v) || !wholeNumber(a, v, 0, 8, referenceRefine, error)) return false;
        } else {
            error = "unknown option " + a + "\n" + kUsage;
            return false;
        }
    }
    if (!fresnelFigure.empty()) return true; // nothing else is read
    if (scene.empty() || viewsFile.empty()) {
        error = std::string("--scene and --views are required\n") + kUsage;
        return false;
    }
    if (quick) {
        if (!sizeGiven) { width = 96; height = 64; }
        if (!framesGiven) frames = 3;
        if (!photonsGiven) photons = 20000;
        if (techniques.empty()) techniques = "default,one-step";
        ablationRounds = std::min(ablationRounds, 1);
    } else if (frames < 30) {
        std::cerr << "warning: --frames " << frames << " is below 30; using 30 (medians need them)" << std::endl;
        frames = 30;
    }
    return true;
}

}
