// Command-line options of osgwaterlake: the scene, the view, and every water setting worth trying.
#pragma once
#include <osgWater/WaterNode>
#include <osg/ArgumentParser>
#include <functional>
#include <string>
#include <vector>

struct LakeOptions {
    std::string scene = "data/lake.osgt";
    int width = 1024, height = 768;
    osg::Vec3d eye{ 0, -42, 4.5 }, center{ 0, 10, -1 }, up{ 0, 0, 1 };
    // the view under water (u or --underwater): 2 m down, looking up the slope towards the south shore
    osg::Vec3d underwaterEye{ 0, -26, -2 }, underwaterCenter{ 0, -33, 1 };
    bool underwater = false;
    double time = 10.0;            // simulation time of the first frame
    double causticsTile = 0.0;     // tileable caustics: the tile's side, the waves snapped to it (0: off)
    bool calm = false;             // the scene's waves off
    bool dome = false;             // the lake's sky dome (data/lake/sky.obj) in place of the scene's clear sky
    double wind = -1.0;            // m/s: the wind's speed, and its waves drawn (< 0: the scene's)
    double choppiness = -1.0;      // the wind's waves' choppiness, 0..1 (< 0: the scene's)
    std::string waves;             // the wave model (wind|sum), "" for the scene's
    std::string mesh;              // the surface's mesh layout (grid|rings), "" for the scene's
    bool headless = false;
    int frames = 60;
    bool compare = true;           // headless: also time the scene without water
    bool compareCaustics = false;  // headless: time caustics off and each gather path
    bool compareGlow = false;      // headless: time glow off and on
    std::string screenshot = "osgwaterlake.png";
    bool hud = true;
    bool floaters = false;         // the buoy and the boat (key b)
    bool pond = false;             // the pond above the lake (key p)
    std::string waterType = "clear-lake"; // a WaterTypes preset, or "thesis"

    static void describe(osg::ApplicationUsage& usage);
    //! Reads the options; false (with a message) on an error.
    bool read(osg::ArgumentParser& args);
    //! Applies the water options given on the command line to a WaterNode's settings (and its
    //! skies: lit by its sun, or the dome in their place).
    void apply(osgWater::WaterNode& water) const;

private:
    std::vector<std::function<void(osgWater::WaterSettings&)>> _setters;
};

//! The scene file: as given, else in the installed share/osgWater/data/ beside the program, else in
//! the source tree's data/.
std::string findSceneFile(const std::string& name);
