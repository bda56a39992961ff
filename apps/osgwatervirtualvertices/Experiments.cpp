#include "Experiments.h"
#include <osgWater/WaterSurface>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

namespace vv {

using osgWater::virtualvertices::SightPoint;

namespace {

const double kRadius = 142.0;  // the thesis's refractor
const int kRings = 11;         // 4 * 11^2 = 484 facets
const Medium kGlass{1.0, 1.51};

//! Measures one row (both placements) and adds it to the table.
void addRow(Table& table, const Refractor& refractor, const glm::dvec3& eye, const Medium& medium, const Box& box,
            const std::string& label0, const std::string& label1, const Published& thesis = Published())
{
    Row row;
    const auto start = std::chrono::steady_clock::now();
    row.linear = measureErrorVolume(refractor, eye, medium, box, SightPoint::Linear);
    row.solved = measureErrorVolume(refractor, eye, medium, box, SightPoint::Solved);
    row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    row.label[0] = label0;
    row.label[1] = label1;
    row.thesis = thesis;
    table.rows.push_back(row);
}

std::string number(double v, const char* format = "%.4g")
{
    char buf[64];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

std::string cell(const ErrorStats& s)
{
    if (s.samples == 0) return "— | — | 0";
    return number(s.mean) + " | " + number(s.deviation) + " | " + std::to_string(s.samples);
}

std::string published(const Published& p)
{
    if (p.points < 0) return "— | — | —";
    return number(p.mean) + " | " + number(p.deviation) + " | " + std::to_string(p.points);
}

//! The lake's rows: a 24 m patch of the waves about (0, 0) at each spacing, seen from each eye.
void addWaveRows(Table& table, const osgWater::WaterSurface& surface, const double (&spacings)[2], const glm::dvec3* eyes,
                 int eyeCount, const Medium& medium, const Box& box, bool fromBelow)
{
    for (double spacing : spacings) {
        const std::unique_ptr<Refractor> patch = makeWavePatch(surface, 0.0, glm::dvec2(0.0), 12.0, spacing, fromBelow);
        for (int i = 0; i < eyeCount; ++i) {
            const glm::dvec3& eye = eyes[i];
            addRow(table, *patch, eye, medium, box, number(spacing, "%.2f"),
                   "(" + number(eye.x, "%.0f") + ", " + number(eye.y, "%.0f") + ", " + number(eye.z, "%.1f") + ")");
        }
    }
}

} // namespace

Table eyePositionTable(const ExperimentOptions& options)
{
    Table table;
    table.title = "Table 4.1: a flat refractor, eye positions";
    table.caption = "Radius 142 units, 484 facets, indices 1.0 above and 1.51 below; the eye moved along x.";
    table.columns[0] = "eye height";
    table.columns[1] = "displacement";
    const double heights[3] = {900.0, 450.0, 150.0}, shifts[4] = {0.0, 142.0, 400.0, 800.0};
    const Published thesis[3][4] = {
        {{0.0154, 0.0085, 6988}, {0.0262, 0.0186, 8046}, {0.0529, 0.0308, 7712}, {0.0523, 0.0290, 6244}},
        {{0.0928, 0.0319, 11348}, {0.1364, 0.0963, 12144}, {0.1626, 0.0972, 8620}, {0.0670, 0.0363, 4880}},
        {{1.2789, 0.6813, 30297}, {1.0994, 0.7749, 22030}, {0.2441, 0.1575, 5964}, {0.0568, 0.0372, 3616}}};
    const std::unique_ptr<Refractor> flat = makeDisk(kRadius, kRings, std::numeric_limits<double>::infinity());
    Box box;
    box.perAxis = options.perAxis;
    for (int h = 0; h < 3; ++h)
        for (int d = 0; d < 4; ++d)
            addRow(table, *flat, glm::dvec3(shifts[d], 0.0, heights[h]), kGlass, box, number(heights[h], "%.0f"),
                   number(shifts[d], "%.0f"), thesis[h][d]);
    return table;
}

Table sphereTable(const ExperimentOptions& options)
{
    Table table;
    table.title = "Table 4.2: refractors conformed to spheres";
    table.caption = "The same refractor lifted onto a sphere (a bowl opening to the eye, rim at z = 0), "
                    "the eye 450 units above its centre.";
    table.columns[0] = "sphere radius";
    table.columns[1] = "eye height";
    const double inf = std::numeric_limits<double>::infinity();
    const double radii[6] = {inf, 710.0, 355.0, 237.0, 178.0, 142.0};
    const Published thesis[6] = {{0.0928, 0.0519, 11348}, {0.1107, 0.0413, 19856}, {0.2082, 0.0811, 27412},
                                 {0.4558, 0.1599, 35476}, {1.1152, 0.5790, 43599}, {7.5567, 9.2816, 56890}};
    Box box;
    box.perAxis = options.perAxis;
    for (int i = 0; i < 6; ++i) {
        const std::unique_ptr<Refractor> bowl = makeDisk(kRadius, kRings, radii[i]);
        addRow(table, *bowl, glm::dvec3(0.0, 0.0, 450.0), kGlass, box,
               std::isfinite(radii[i]) ? number(radii[i], "%.0f") : "∞ (flat)", "450", thesis[i]);
    }
    return table;
}

Table facetingTable(const ExperimentOptions& options)
{
    Table table;
    table.title = "The faceting's share";
    table.caption = "The flat refractor of Table 4.1 in 7, 11 and 15 rings (113, 265 and 481 vertices), the eye above "
                    "its centre: the thesis's published row beside the eye height it was measured at.";
    table.columns[0] = "facets (vertices)";
    table.columns[1] = "eye height";
    const std::pair<double, Published> eyes[2] = {{450.0, {0.0928, 0.0319, 11348}}, {150.0, {1.2789, 0.6813, 30297}}};
    Box box;
    box.perAxis = options.perAxis;
    for (int rings : {7, 11, 15}) {
        const std::unique_ptr<Refractor> flat = makeDisk(kRadius, rings, std::numeric_limits<double>::infinity());
        const std::string facets = std::to_string(flat->membrane().facets.size()) + " (" +
                                   std::to_string(flat->membrane().positions.size()) + ")";
        for (const auto& eye : eyes)
            addRow(table, *flat, glm::dvec3(0.0, 0.0, eye.first), kGlass, box, facets, number(eye.first, "%.0f"), eye.second);
    }
    return table;
}

Table waveTable(const osgWater::WaterSurface& surface, double gridSpacing, const ExperimentOptions& options)
{
    Table table;
    table.title = "The lake's waves";
    table.caption = "A 24 m square of the lake's waves at t = 0 about (0, 0), faceted with the default grid's spacing (" +
                    number(gridSpacing, "%.2f") + " m) and at 0.5 m, vertex normals from the analytic waves, indices "
                    "1.0 / 1.333; the points in a 24 x 24 x 6 m box under it; metres.";
    table.columns[0] = "facet spacing (m)";
    table.columns[1] = "eye (m)";
    const glm::dvec3 eyes[4] = {{0, 0, 10}, {0, 0, 3}, {0, 0, 1.5}, {8, 0, 3}};
    const double spacings[2] = {gridSpacing, 0.5};
    Box box;
    box.min = glm::dvec3(-12.0, -12.0, -6.0);
    box.max = glm::dvec3(12.0, 12.0, 0.0);
    box.perAxis = options.lakePerAxis;
    const Medium water{1.0, 1.333};
    addWaveRows(table, surface, spacings, eyes, 4, water, box, false);
    return table;
}

namespace {

double seenShare(const ErrorStats& s, long part)
{
    const long seen = s.samples + s.convergence + s.extrapolated + s.unimplied;
    return seen > 0 ? 100.0 * double(part) / double(seen) : 0.0;
}

//! What the tables show, in words, from their own rows.
std::string findings(const std::vector<Table>& t)
{
    std::ostringstream md;
    if (t.size() < 3 || t[0].rows.size() != 12 || t[1].rows.size() != 6 || t[2].rows.size() != 6) return "";
    const std::vector<Row>& eye = t[0].rows;    // height (900, 450, 150) x displacement (0, 142, 400, 800)
    const std::vector<Row>& bowl = t[1].rows;   // infinity, 710, 355, 237, 178, 142
    const std::vector<Row>& rings = t[2].rows;  // 7, 11, 15 rings x eye 450, 150
    const Row& worst = eye[8];
    md << "## What this run shows\n\n"
       << "- **The thesis's trend holds.** Over the flat refractor the error grows as the eye comes down: above "
          "the centre at 900, 450 and 150 units, "
       << number(eye[0].linear.mean) << ", " << number(eye[4].linear.mean) << " and " << number(worst.linear.mean)
       << " units (the thesis's 0.0154, 0.0928 and 1.2789). Off the axis, as in the thesis, it first grows (the "
          "sight rays turn more across each cell) and then falls as the visible volume within the box shrinks: "
          "with the eye 450 units up, " << number(eye[4].linear.mean) << ", " << number(eye[5].linear.mean) << ", "
       << number(eye[6].linear.mean) << " and " << number(eye[7].linear.mean)
       << " at 0, 142, 400 and 800 units off the axis (the thesis's 0.0928, 0.1364, 0.1626 and 0.0670).\n"
       << "- **The thesis's absolute figures are not reproduced by what it describes.** With the eye 150 units "
          "above the centre its mean is " << number(worst.thesis.mean / std::max(worst.linear.mean, 1e-300), "%.1f")
       << " times ours with 484 facets. The error falls with the cells' size, about as its square ("
       << number(rings[1].linear.mean) << ", " << number(rings[3].linear.mean) << " and " << number(rings[5].linear.mean)
       << " units with 196, 484 and 900 facets at that height), so a coarser refractor would explain part of it "
          "(its 125 vertices make at most 243 facets), but even 196 facets stay "
       << number(worst.thesis.mean / std::max(rings[1].linear.mean, 1e-300), "%.1f")
       << " times below its figure; its flat refractor's point counts, a fifth to a half of ours, say its box or spacing differed "
          "too. The trends are what carry over.\n"
       << "- **Solving the sight point on the facet removes the flat refractor's error**: the worst flat case, "
       << number(worst.linear.mean) << " units with the thesis's linear placement, is " << number(worst.solved.mean)
       << " solved (rounding; largest " << number(worst.solved.max) << "). On a plane the facet is the surface and its "
          "normal is exact, so the linear placement was the only error.\n"
       << "- **On a curved refractor it removes only the placement's share.** The hemisphere: "
       << number(bowl[5].linear.mean) << " linear, " << number(bowl[5].solved.mean) << " solved; the 237-unit bowl: "
       << number(bowl[3].linear.mean) << " and " << number(bowl[3].solved.mean)
       << ". What is left is the facets' departure from the sphere (the chord under the arc, the interpolated "
          "normal), which no placement within a facet removes; finer facets do.\n";
    if (t.size() >= 4 && t[3].rows.size() == 8) {
        const std::vector<Row>& lake = t[3].rows;  // thesis grid then 0.5 m, eyes 10, 3, 1.5 up and (8, 0, 3)
        md << "- **Over the lake's waves the error is the faceting's.** With the thesis's grid spacing ("
           << lake[0].label[0] << " m) and the eye 10 m up the mean is " << number(lake[0].linear.mean) << " m ("
           << number(lake[0].solved.mean) << " solved); at 0.5 m, " << number(lake[4].linear.mean) << " m ("
           << number(lake[4].solved.mean) << "). The facets' normals are not the waves' (the waves down to 0.9 m are "
              "sampled by a few vertices each), and placement within a facet cannot mend that.\n"
           << "- **Waves make the cells cross.** With 0.5 m facets and the eye 1.5 m up, "
           << number(seenShare(lake[6].linear, lake[6].linear.convergence), "%.0f")
           << "% of the points seen through the patch lie in more than one cell (a zone of convergence: left out "
              "above, where the thesis's first-virtual-vertex rule joins the wrong ones), and "
           << number(seenShare(lake[6].linear, lake[6].linear.extrapolated), "%.0f")
           << "% in a cell bounded by an extrapolated ray. Finer facets resolve more of the waves and make more "
              "crossings. That is where virtual vertices lose to a depth search over wavy water; they win where "
              "the surface is smooth against its facets, and at silhouettes, since they draw the real geometry.\n";
    }
    if (t.size() >= 5 && t[4].rows.size() == 4) {
        const std::vector<Row>& below = t[4].rows;  // thesis grid then 0.5 m, eyes (0, 0, -3) and (6, 0, -2)
        md << "- **From under the water the same construction holds with the indices swapped.** With 0.5 m facets "
              "and the eye 3 m under the centre, the points above the water seen through Snell's window are placed "
           << number(below[2].linear.mean) << " m off on average (" << number(below[2].solved.mean)
           << " solved; the thesis's grid spacing: " << number(below[0].linear.mean) << "). "
           << number(seenShare(below[2].linear, below[2].linear.extrapolated), "%.0f")
           << "% of the points in some cell are in one bounded by an extrapolated ray (beyond the window, where "
              "the real light is totally reflected): the thesis's extrapolation keeps those facets drawable, "
              "not right.\n";
    }
    md << "\n";
    return md.str();
}

} // namespace

Table underwaterWaveTable(const osgWater::WaterSurface& surface, double gridSpacing, const ExperimentOptions& options)
{
    Table table;
    table.title = "The lake's waves from under the water";
    table.caption = "The same patch seen from below: indices 1.333 at the eye and 1.0 beyond, the points in a "
                    "24 x 24 x 6 m box above the level; metres. Beyond Snell's window (48.6 degrees from the "
                    "vertical) the sight rays are totally reflected and the cells are bounded by the thesis's "
                    "extrapolated rays (left out of the error, counted in the last column).";
    table.columns[0] = "facet spacing (m)";
    table.columns[1] = "eye (m)";
    const glm::dvec3 eyes[2] = {{0, 0, -3}, {6, 0, -2}};
    const double spacings[2] = {gridSpacing, 0.5};
    Box box;
    box.min = glm::dvec3(-12.0, -12.0, 0.0);
    box.max = glm::dvec3(12.0, 12.0, 6.0);
    box.perAxis = options.lakePerAxis;
    const Medium water{1.333, 1.0};
    addWaveRows(table, surface, spacings, eyes, 2, water, box, true);
    return table;
}

std::string markdown(const std::vector<Table>& tables, const ExperimentOptions& options, const std::string& command,
                     const std::string& date)
{
    std::ostringstream md;
    md << "# Virtual vertices: the error volume\n\n"
       << "Generated by `" << command << "` on " << date << " — do not edit by hand.\n\n"
       << "Refraction by virtual vertices draws the geometry under the water where it appears to be: each "
          "water facet's cell is bounded by the refracted sight rays through its vertices, and a vertex inside "
          "a cell moves to its virtual vertex (`osgWater/optics/VirtualVertices.h`). The thesis that introduced it "
          "measured it with an *error volume*: regularly spaced points under a refractor, each one's virtual "
          "vertex, the point that virtual vertex implies (the eye's ray through it refracted exactly at the "
          "exact surface, lengthened by the foreshortening), and that point's distance from the true one. "
          "This page is that experiment done again, beside the thesis's published numbers (its Tables 4.1 "
          "and 4.2), and then over the lake's waves.\n\n"
       << "- **Sampling.** The thesis's box: 400 × 400 × 400 units, its top flush with the refractor's rim, "
       << options.perAxis << " points per side at the centres of equal cells ("
       << options.perAxis * options.perAxis * options.perAxis << " points). The thesis does not give its "
          "spacing; its point counts are smaller than ours for the flat refractor and close to ours for the "
          "deep bowls, so its box or spacing was not quite this one. Points left out, as the thesis does: "
          "not seen through the refractor, in more than one cell (a zone of convergence), in a cell bounded "
          "by an extrapolated ray (eq. 3.1, 3.2), or whose virtual vertex implies no point.\n"
       << "- **Faceting.** The thesis gives 125 vertices and 484 facets. A triangulated disk with V vertices, "
          "B of them on the rim, has 2V − B − 2 facets, so 125 vertices make at most 243: the two numbers "
          "cannot both hold. We keep the 484 facets (the cells' size is what sets the error) in 11 concentric "
          "rings, ring i with 4 i vertices: 265 vertices.\n"
       << "- **Spheres.** Each vertex is lifted vertically onto the sphere; the bowl opens towards the eye, "
          "which makes the refracted rays diverge (the thesis's diverging membranes: the visible volume grows "
          "with the curvature, as its point counts do).\n"
       << "- **Linear** is the thesis's sight point: the true vertex's barycentric coordinates in the cell's "
          "section by a plane through it, applied to the facet. **Solved** starts there and solves on the facet "
          "(Gauss-Newton on the barycentric coordinates) for the point whose refracted ray, by the "
          "interpolated vertex normal, passes through the true vertex.\n"
       << "- Units: the thesis's units, metres for the lake. Thesis columns: its published mean, standard "
          "deviation and data points. The thesis prints the flat case with the eye 450 units above the centre "
          "twice, with a standard deviation of 0.0319 (Table 4.1) and 0.0519 (Table 4.2).\n\n"
       << findings(tables);
    for (const Table& t : tables) {
        md << "## " << t.title << "\n\n" << t.caption << "\n\n"
           << "| " << t.columns[0] << " | " << t.columns[1]
           << " | thesis mean | thesis std | thesis points | linear mean | linear std | points | solved mean | "
              "solved std | points | linear max | solved max | left out (convergence / extrapolated) | s |\n"
           << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
        for (const Row& r : t.rows)
            md << "| " << r.label[0] << " | " << r.label[1] << " | " << published(r.thesis) << " | " << cell(r.linear)
               << " | " << cell(r.solved) << " | " << number(r.linear.max) << " | " << number(r.solved.max) << " | "
               << r.linear.convergence << " / " << r.linear.extrapolated << " | " << number(r.seconds, "%.1f") << " |\n";
        md << "\n";
    }
    return md.str();
}

}
