// osgwatervirtualvertices: the error volume of refraction by virtual vertices (the thesis's Tables
// 4.1 and 4.2, done again beside its published figures, and over the lake's waves). Prints the tables
// and, with --docs, writes DIR/VIRTUAL_VERTICES.md.
#include "Experiments.h"
#include "../common/SceneWater.h"
#include "../common/Today.h"
#include <osgWater/WaterSurface>
#include <osgDB/ReadFile>
#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>

namespace {

const char* kUsage =
    "usage: osgwatervirtualvertices [--samples N] [--lake-samples N] [--scene FILE.osgt] [--docs DIR]\n"
    "  --samples N       points per side of the thesis's 400-unit box (default 40; 4..200)\n"
    "  --lake-samples N  points per side of the box under the lake's waves (default 24; 4..200)\n"
    "  --scene FILE      a scene with a WaterNode whose waves make the last table (e.g. data/lake.osgt);\n"
    "                    without it the lake's table is left out\n"
    "  --docs DIR        also write DIR/VIRTUAL_VERTICES.md\n";

bool count(const char* text, int& out)
{
    char* end = nullptr;
    const long v = std::strtol(text, &end, 10);
    if (!end || *end || v < 4 || v > 200) return false;
    out = int(v);
    return true;
}

} // namespace

int main(int argc, char** argv)
{
    vv::ExperimentOptions options;
    std::string scene, docs, command = "osgwatervirtualvertices";
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const bool hasValue = i + 1 < argc;
        if (a == "--help" || a == "-h") { std::cout << kUsage; return 0; }
        if (!hasValue) { std::cerr << "osgwatervirtualvertices: " << a << " needs a value\n" << kUsage; return 2; }
        const char* v = argv[++i];
        bool ok = true;
        if (a == "--samples") ok = count(v, options.perAxis);
        else if (a == "--lake-samples") ok = count(v, options.lakePerAxis);
        else if (a == "--scene") scene = v;
        else if (a == "--docs") docs = v;
        else { std::cerr << "osgwatervirtualvertices: unknown option " << a << "\n" << kUsage; return 2; }
        if (!ok) { std::cerr << "osgwatervirtualvertices: " << a << " takes a whole number from 4 to 200\n"; return 2; }
        command += " " + a + " " + v;
    }

    std::vector<vv::Table> tables;
    tables.push_back(vv::eyePositionTable(options));
    tables.push_back(vv::sphereTable(options));
    tables.push_back(vv::facetingTable(options));
    if (!scene.empty()) {
        osg::ref_ptr<osg::Node> root = osgDB::readRefNodeFile(scene);
        if (!root) { std::cerr << "osgwatervirtualvertices: cannot read " << scene << "\n"; return 1; }
        bool added = false;
        osg::ref_ptr<osgWater::WaterNode> water = osgWaterApps::findOrAddWater(root, scene, &added);
        if (added) { std::cerr << "osgwatervirtualvertices: " << scene << " has no WaterNode\n"; return 1; }
        const osgWater::WaterSurface* surface = water->getSurface();
        // the thesis's uniform grid (MESH_GRID): resolution vertices over the square
        const double spacing = surface->getSize() / std::max(1.0, double(surface->getResolution()) - 1.0);
        tables.push_back(vv::waveTable(*surface, spacing, options));
        tables.push_back(vv::underwaterWaveTable(*surface, spacing, options));
    }

    const std::string md = vv::markdown(tables, options, command, osgWaterApps::today());
    std::cout << md;
    if (!docs.empty()) {
        const std::string path = docs + "/VIRTUAL_VERTICES.md";
        std::ofstream out(path);
        out << md;
        if (!out) { std::cerr << "osgwatervirtualvertices: cannot write " << path << "\n"; return 1; }
        std::cerr << "wrote " << path << "\n";
    }
    return 0;
}
