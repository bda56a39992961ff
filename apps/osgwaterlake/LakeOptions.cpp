#include "LakeOptions.h"
#include <osgWater/Sky>
#include <osgWater/WaterTypes>
#include <osg/CullFace>
#include <osgDB/FileUtils>
#include <osgDB/FileNameUtils>
#include <osgDB/ReadFile>
#include <iostream>
#include <functional>
#include <string>
#include <vector>

namespace {

using Setters = std::vector<std::function<void(osgWater::WaterSettings&)>>;

using osgWater::WaterSettings;
using osgWater::WaterSurface;

// An option naming one value of one of the kit's enums. --help and the message for a name it does
// not know both list the kit's own name table, so a value added to the kit shows here untouched.
struct EnumOption {
    const char* option;
    std::string (*names)();
    const char* help;
    // takes a name: a setter for the settings, or the name kept for apply(); false if it names nothing
    std::function<bool(const std::string& name, LakeOptions& o, Setters& setters)> take;
};

template <typename E>
std::function<bool(const std::string&, LakeOptions&, Setters&)> setting(bool (*fromName)(const std::string&, E&),
                                                                       void (WaterSettings::*set)(E))
{
    return [fromName, set](const std::string& name, LakeOptions&, Setters& setters) {
        E value;
        if (!fromName(name, value)) return false;
        setters.push_back([set, value](WaterSettings& w) { (w.*set)(value); });
        return true;
    };
}

template <typename E>
std::function<bool(const std::string&, LakeOptions&, Setters&)> kept(bool (*fromName)(const std::string&, E&),
                                                                    std::string LakeOptions::*field)
{
    return [fromName, field](const std::string& name, LakeOptions& o, Setters&) {
        E value;
        if (!fromName(name, value)) return false;
        o.*field = name;
        return true;
    };
}

// --quality first: a preset sets the speed settings, and the options after it come on top of it
const std::vector<EnumOption>& enumOptions()
{
    static const std::vector<EnumOption> options = {
        { "--quality", WaterSettings::qualityNames, "Speed preset; the other options come on top of it (default balanced)",
          setting(WaterSettings::qualityFromName, &WaterSettings::setQuality) },
        { "--lookup", WaterSettings::refractionLookupNames, "Refraction lookup technique",
          setting(WaterSettings::refractionLookupFromName, &WaterSettings::setRefractionLookup) },
        { "--reflection-lookup", WaterSettings::reflectionLookupNames, "Reflection lookup technique (default search)",
          setting(WaterSettings::reflectionLookupFromName, &WaterSettings::setReflectionLookup) },
        { "--fresnel", WaterSettings::fresnelModelNames, "Fresnel model",
          setting(WaterSettings::fresnelModelFromName, &WaterSettings::setFresnelModel) },
        { "--gather", WaterSettings::causticsGatherNames,
          "Caustics photon gather: points from a copied vertex buffer, points reading the photon texture, CPU",
          setting(WaterSettings::causticsGatherFromName, &WaterSettings::setCausticsGather) },
        { "--caustics", WaterSettings::causticsMethodNames,
          "Caustics method: photon splatting (thesis), the area-ratio mesh (DeepWater), procedural (in the bed's space or the screen's)",
          setting(WaterSettings::causticsMethodFromName, &WaterSettings::setCausticsMethod) },
        { "--underwater-model", WaterSettings::underwaterModelNames,
          "Surface seen from below: Snell with total internal reflection, or the thesis's eq. 12",
          setting(WaterSettings::underwaterModelFromName, &WaterSettings::setUnderwaterModel) },
        { "--tone", WaterSettings::toneCurveNames,
          "Tone curve of the exposed light before the sRGB encoding: none (clip) or ACES's filmic curve (default clip)",
          setting(WaterSettings::toneCurveFromName, &WaterSettings::setToneCurve) },
        { "--waves", WaterSurface::waveModelNames,
          "The wave model: the wind's waves (the scene's default) or the thesis's sum of sines (key j)",
          kept(WaterSurface::waveModelFromName, &LakeOptions::waves) },
        { "--mesh", WaterSurface::meshLayoutNames, "The surface's mesh: rings around the eye (default) or the thesis's uniform grid",
          kept(WaterSurface::meshLayoutFromName, &LakeOptions::mesh) },
    };
    return options;
}

}


void LakeOptions::describe(osg::ApplicationUsage& u)
{
    u.setDescription("osgWater lake demo: the thesis's lake with reflection, refraction, Fresnel and depth colour");
    u.setCommandLineUsage("osgwaterlake [options] [scene.osgt]");
    u.addCommandLineOption("--headless", "Render off-screen (pbuffer), write a screenshot, print frame times, exit");
    u.addCommandLineOption("--frames <n>", "Headless: frames per measured scene, in up to 5 alternating blocks (default 60)");
    u.addCommandLineOption("--no-compare", "Headless: do not also time the scene without water");
    u.addCommandLineOption("--screenshot <file>", "Screenshot file (default osgwaterlake.png)");
    u.addCommandLineOption("--size <w> <h>", "Window or image size, 16 to 8192 per side (default 1024 768)");
    u.addCommandLineOption("--eye <x> <y> <z>", "Eye position (water plane z = 0)");
    u.addCommandLineOption("--center <x> <y> <z>", "Point looked at");
    u.addCommandLineOption("--up <x> <y> <z>", "Up direction");
    u.addCommandLineOption("--time <t>", "Simulation time of the first frame, seconds (default 10)");
    u.addCommandLineOption("--no-hud", "Hide the on-screen text");
    u.addCommandLineOption("--floaters", "Show the buoy and the boat riding the waves (key b)");
    u.addCommandLineOption("--pond", "Show a garden pond on the north rim, a second water above the lake (key p)");
    for (const EnumOption& e : enumOptions())
        u.addCommandLineOption(std::string(e.option) + " <" + e.names() + ">", e.help);
    u.addCommandLineOption("--choppy <0-1>", "How far the wind's waves move the water toward their crests (0 none, 1 Tessendorf's full; default the scene's)");
    u.addCommandLineOption("--dome", "The lake's sky dome (data/lake/sky.obj, a textured mesh) in place of the scene's clear sky (osgWater::Sky, lit by the water's sun)");
    u.addCommandLineOption("--calm", "Flat water: the scene's waves off (the wind's and the sum's)");
    u.addCommandLineOption("--wind <m/s>", "The wind's waves, raised by a wind of this speed (0-40) over the lake (its fetch the lake's size); default the scene's, a 5 m/s breeze (keys w, W)");
    u.addCommandLineOption("--planes <height> <depth>", "Plane-offset lookups' planes, metres from the level (0: from the scene)");
    u.addCommandLineOption("--steps <n>", "Candidates of the iterative search (1-8)");
    u.addCommandLineOption("--budget <texels>", "The searches' error budget, texels of the texture each reads (1/64-16; 0.25)");
    u.addCommandLineOption("--reciprocal-power <p>", "Power of the reciprocal Fresnel model 1/(1+E.N)^p (default 6.62)");
    u.addCommandLineOption("--q <q>", "Fresnel exponent");
    u.addCommandLineOption("--water-type <name>", "The water: " + osgWater::waterTypeNames() + " (per-channel absorption and scattering; default clear-lake), or thesis (one k, one colour; the default with --k or --water-color)");
    u.addCommandLineOption("--k <k>", "Attenuation per metre (thesis model)");
    u.addCommandLineOption("--c <c>", "Reflection lookup scale");
    u.addCommandLineOption("--water-color <r> <g> <b>", "Water colour (thesis model)");
    u.addCommandLineOption("--fov-ext <near> <far> <falloff>", "Pass FOV extension near/far the water, e-folding height");
    u.addCommandLineOption("--texture-size <n>", "Reflection and refraction texture size");
    u.addCommandLineOption("--environment", "Reflect the surroundings from an environment cube map where the reflection texture ends");
    u.addCommandLineOption("--no-reflection", "Switch reflection off");
    u.addCommandLineOption("--no-refraction", "Switch refraction off");
    u.addCommandLineOption("--no-rotation", "Do not rotate the refraction camera (thesis 5.1)");
    u.addCommandLineOption("--thesis-rotation", "Rotate the refraction camera rigidly about O, as the thesis does (not to the apparent eye)");
    u.addCommandLineOption("--no-caustics", "Switch caustics off");
    u.addCommandLineOption("--supersample", "Caustics: the gather drawn four times, jittered by a quarter texel (2x2 supersampling)");
    u.addCommandLineOption("--caustics-tile <metres>", "Tileable caustics over tiles of this side (the waves moved to the nearest that repeat over it)");
    u.addCommandLineOption("--reflective-caustics", "The sun reflected off the water lights what stands above it");
    u.addCommandLineOption("--caustics-size <n>", "Caustics texture size (default 256)");
    u.addCommandLineOption("--photons <n>", "Photons per side of the photon grid (default 512)");
    u.addCommandLineOption("--sun <x> <y> <z>", "Direction towards the sun");
    u.addCommandLineOption("--underwater", "Start under water (same as pressing u)");
    u.addCommandLineOption("--no-glow", "Switch the sun's glow off");
    u.addCommandLineOption("--glow <intensity>", "Glow intensity (default 1)");
    u.addCommandLineOption("--exposure <e>", "Linear light times e before the sRGB encoding (default 1)");
    u.addCommandLineOption("--compare-glow", "Headless: time glow off and on in one run");
    u.addCommandLineOption("--compare-caustics", "Headless: time caustics off and each gather path in one run");
}

bool LakeOptions::read(osg::ArgumentParser& args)
{
    headless = args.read("--headless");
    args.read("--frames", frames);
    frames = std::max(frames, 2);
    if (args.read("--no-compare")) compare = false;
    if (args.read("--compare-caustics")) compareCaustics = true;
    if (args.read("--compare-glow")) compareGlow = true;
    if (args.read("--no-hud")) hud = false;
    if (args.read("--floaters")) floaters = true;
    if (args.read("--pond")) pond = true;
    args.read("--screenshot", screenshot);
    if (args.read("--size", width, height) && (width < 16 || height < 16 || width > 8192 || height > 8192)) {
        std::cerr << "error: --size " << width << " " << height << ": expected 16 to 8192 pixels per side" << std::endl;
        return false;
    }
    args.read("--eye", eye.x(), eye.y(), eye.z());
    args.read("--center", center.x(), center.y(), center.z());
    args.read("--up", up.x(), up.y(), up.z());
    args.read("--time", time);
    if (args.read("--underwater")) {
        underwater = true;
        eye = underwaterEye;
        center = underwaterCenter;
    }

    std::string s;
    float f, g, h;
    int n;
    for (const EnumOption& e : enumOptions())
        if (args.read(e.option, s) && !e.take(s, *this, _setters)) {
            std::cerr << "error: " << e.option << " " << s << ": not one of " << e.names() << std::endl;
            return false;
        }
    if (args.read("--steps", n)) _setters.push_back([n](WaterSettings& w) { w.setSearchSteps(n); });
    if (args.read("--budget", f)) _setters.push_back([f](WaterSettings& w) { w.setErrorBudget(f); });
    if (args.read("--planes", f, g)) _setters.push_back([f, g](WaterSettings& w) {
        w.setReflectionPlaneHeight(f);
        w.setRefractionPlaneDepth(g);
    });
    if (args.read("--q", f)) _setters.push_back([f](WaterSettings& w) { w.setFresnelExponent(f); });
    if (args.read("--reciprocal-power", f)) _setters.push_back([f](WaterSettings& w) { w.setFresnelReciprocalPower(f); });
    const bool typeGiven = args.read("--water-type", s);
    if (typeGiven) waterType = s;
    // the thesis model's own knobs ask for the thesis model, unless a type is named too
    if (!typeGiven && (args.find("--k") > 0 || args.find("--water-color") > 0)) waterType = "thesis";
    if (waterType != "thesis" && !osgWater::findWaterType(waterType)) {
        std::cerr << "error: --water-type " << waterType << ": not one of " << osgWater::waterTypeNames() << ", thesis"
                  << std::endl;
        return false;
    }
    if (args.read("--k", f)) _setters.push_back([f](WaterSettings& w) { w.setAttenuation(f); });
    if (args.read("--c", f)) _setters.push_back([f](WaterSettings& w) { w.setReflectionScale(f); });
    if (args.read("--water-color", f, g, h)) _setters.push_back([f, g, h](WaterSettings& w) { w.setWaterColor(osg::Vec3(f, g, h)); });
    if (args.read("--fov-ext", f, g, h)) _setters.push_back([f, g, h](WaterSettings& w) { w.setFovExtension(f, g, h); });
    if (args.read("--texture-size", n)) _setters.push_back([n](WaterSettings& w) { w.setReflectionTextureSize(n); w.setRefractionTextureSize(n); });
    if (args.read("--environment")) _setters.push_back([](WaterSettings& w) { w.setEnvironmentMapEnabled(true); });
    if (args.read("--no-reflection")) _setters.push_back([](WaterSettings& w) { w.setReflectionEnabled(false); });
    if (args.read("--no-refraction")) _setters.push_back([](WaterSettings& w) { w.setRefractionEnabled(false); });
    if (args.read("--no-rotation")) _setters.push_back([](WaterSettings& w) { w.setRefractionCameraRotation(false); });
    if (args.read("--thesis-rotation")) _setters.push_back([](WaterSettings& w) { w.setRefractionCameraApparentEye(false); });
    if (args.read("--no-caustics")) _setters.push_back([](WaterSettings& w) { w.setCausticsEnabled(false); });
    if (args.read("--supersample")) _setters.push_back([](WaterSettings& w) { w.setCausticsSupersampling(true); });
    args.read("--caustics-tile", causticsTile);
    if (args.read("--calm")) calm = true;
    if (args.read("--dome")) dome = true;
    if (args.read("--wind", wind) && !(wind >= 0.0 && wind <= 40.0)) {
        std::cerr << "error: --wind takes a speed in m/s, 0 to 40" << std::endl;
        return false;
    }
    if (args.read("--choppy", choppiness) && !(choppiness >= 0.0 && choppiness <= 1.0)) {
        std::cerr << "error: --choppy takes a choppiness, 0 to 1" << std::endl;
        return false;
    }
    if (args.read("--reflective-caustics")) _setters.push_back([](WaterSettings& w) { w.setReflectiveCaustics(true); });
    if (args.read("--caustics-size", n)) _setters.push_back([n](WaterSettings& w) { w.setCausticsResolution(n); });
    if (args.read("--photons", n)) _setters.push_back([n](WaterSettings& w) { w.setPhotonGridSize(n); });
    if (args.read("--no-glow")) _setters.push_back([](WaterSettings& w) { w.setGlowEnabled(false); });
    if (args.read("--glow", f)) _setters.push_back([f](WaterSettings& w) { w.setGlowIntensity(f); });
    if (args.read("--exposure", f)) _setters.push_back([f](WaterSettings& w) { w.setExposure(f); });
    if (args.read("--sun", f, g, h)) _setters.push_back([f, g, h](WaterSettings& w) { w.setSunDirection(osg::Vec3(f, g, h)); });

    for (int pos = 1; pos < args.argc(); ++pos)
        if (!args.isOption(pos)) { scene = args[pos]; args.remove(pos); break; }
    args.reportRemainingOptionsAsUnrecognized();
    if (args.errors()) {
        args.writeErrorMessages(std::cerr);
        return false;
    }
    return true;
}

void LakeOptions::apply(osgWater::WaterNode& water) const
{
    WaterSettings& s = *water.getSettings();
    if (const osgWater::WaterType* type = osgWater::findWaterType(waterType)) osgWater::applyWaterType(s, *type);
    else s.setWaterModel(WaterSettings::WATER_THESIS);
    for (const auto& set : _setters) set(s);
    osgWater::WaterSurface& waterSurface = *water.getSurface();
    osgWater::WaterSurface::WaveModel model;
    if (osgWater::WaterSurface::waveModelFromName(waves, model)) waterSurface.setWaveModel(model);
    if (wind >= 0.0 || calm) {
        osgWater::WindWaves w = waterSurface.getWind();
        w.speed = calm ? 0.0f : float(wind);
        waterSurface.setWind(w);
        if (wind >= 0.0 && waves.empty()) waterSurface.setWaveModel(osgWater::WaterSurface::WAVES_WIND);
    }
    if (choppiness >= 0.0) {
        osgWater::WindWaves w = waterSurface.getWind();
        w.choppiness = float(choppiness);
        waterSurface.setWind(w);
    }
    if (calm) waterSurface.setWaves({});
    // the scene's clear skies are lit by the water's sun (--sun moves both), or give way to the dome
    osg::ref_ptr<osg::Node> domeMesh;
    if (dome) {
        const std::string path = osgDB::concatPaths(osgDB::getFilePath(findSceneFile(scene)), "lake/sky.obj");
        domeMesh = osgDB::readRefNodeFile(path);
        if (domeMesh.valid()) {
            // from outside (a view beyond it) the dome must not hide the lake
            domeMesh->getOrCreateStateSet()->setAttributeAndModes(new osg::CullFace(osg::CullFace::BACK), osg::StateAttribute::ON);
            water.addChild(domeMesh.get());
        } else {
            std::cerr << "warning: --dome: cannot read " << path << " (it is generated by the build): the clear sky stays" << std::endl;
        }
    }
    for (unsigned int i = 0; i < water.getNumChildren(); ++i)
        if (osgWater::Sky* clearSky = dynamic_cast<osgWater::Sky*>(water.getChild(i))) {
            clearSky->setSunDirection(s.getSunDirection());
            if (domeMesh.valid()) clearSky->setNodeMask(0);
        }
    osgWater::WaterSurface::MeshLayout layout;
    if (osgWater::WaterSurface::meshLayoutFromName(mesh, layout)) water.getSurface()->setMeshLayout(layout);
    if (causticsTile > 0.0) {
        s.setCausticsTileSize(float(causticsTile));
        osgWater::WaterSurface& surface = *water.getSurface();
        if (!osgWater::WaterSurface::wavesTileOver(surface.getWaves(), causticsTile)) {
            surface.setWaves(osgWater::WaterSurface::wavesSnappedToTile(surface.getWaves(), causticsTile));
            std::cout << "caustics tile " << causticsTile << " m: the waves moved to the nearest that repeat over it"
                      << std::endl;
        }
    }
}

std::string findSceneFile(const std::string& name)
{
    if (osgDB::fileExists(name)) return name;
    // installed: share/osgWater/data beside the program's own prefix, wherever that was moved (Linux
    // names the running program in /proc); built: the source tree's data/
    const std::string installed = osgDB::getFilePath(osgDB::getRealPath("/proc/self/exe")) + "/" + OSGWATER_DATA_FROM_BIN;
    for (const std::string& dir : { installed, std::string(OSGWATER_SOURCE_DATA_DIR) }) {
        const std::string base = osgDB::getSimpleFileName(name);
        if (osgDB::fileExists(dir + "/" + base)) return osgDB::getRealPath(dir + "/" + base);
    }
    return std::string();
}
