// The error-volume experiments: the thesis's Tables 4.1 (eye positions over a flat refractor) and
// 4.2 (refractors conformed to spheres), its published figures beside ours, and the same
// measurement over a patch of a scene's water waves.
#pragma once
#include "ErrorVolume.h"
#include <string>
#include <vector>

namespace osgWater { class WaterSurface; }

namespace vv {

//! A published row: mean, standard deviation, data points (negative: not published).
struct Published { double mean = -1.0, deviation = -1.0; long points = -1; };

struct Row {
    std::string label[2];  //!< the row's two defining values, as the table prints them
    Published thesis;
    ErrorStats linear, solved;
    double seconds = 0.0;  //!< both methods, this machine
};

struct Table {
    std::string title, caption, columns[2];
    std::vector<Row> rows;
};

struct ExperimentOptions {
    int perAxis = 40;      //!< thesis volumes: samples per side of the 400-unit cube
    int lakePerAxis = 24;  //!< the lake patch's box
};

//! Table 4.1: refractor of radius 142 in 11 rings (484 facets), indices 1.0 / 1.51, eye 900 / 450 / 150
//! units above the plane and 0 / 142 / 400 / 800 units off the axis.
Table eyePositionTable(const ExperimentOptions& options);
//! Table 4.2: the same refractor conformed to spheres of radius infinity / 710 / 355 / 237 / 178 / 142
//! units, eye 450 units above the centre.
Table sphereTable(const ExperimentOptions& options);
//! The faceting's share: the flat refractor in 7, 11 and 15 rings (196, 484 and 900 facets), the eye
//! 450 and 150 units above the centre.
Table facetingTable(const ExperimentOptions& options);
//! The lake: a 24 m square of `surface`'s waves at t = 0 about (0, 0), faceted at the default grid's
//! spacing and at 0.5 m, indices 1.0 / 1.333, a 24 x 24 x 6 m box under it, eyes above and off the centre.
Table waveTable(const osgWater::WaterSurface& surface, double gridSpacing, const ExperimentOptions& options);
//! The same patch seen from under the water (the indices swapped: 1.333 at the eye, 1.0 beyond), the
//! eye 3 m down under the centre and 2 m down 6 m off it, the points in a 24 x 24 x 6 m box above.
Table underwaterWaveTable(const osgWater::WaterSurface& surface, double gridSpacing, const ExperimentOptions& options);

//! The tables as Markdown (VIRTUAL_VERTICES.md), with how they were made and what they show; the
//! tables in the order eyePositionTable, sphereTable, facetingTable, then waveTable and
//! underwaterWaveTable if measured.
std::string markdown(const std::vector<Table>& tables, const ExperimentOptions& options, const std::string& command,
                     const std::string& date);

}
