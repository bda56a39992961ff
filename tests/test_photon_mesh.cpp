// The CPU area-ratio mesh (osgWater::meshPhotons), the mirror its GPU path is held to: on mappings
// whose caustic is known in closed form. A photon texel (i, j) of an n x n grid sits at
// ((i + 0.5) / n, (j + 0.5) / n) in the sun's texture space; a mapping moves it there.
#include "caustics/PhotonSplat.h"
#include <gtest/gtest.h>
#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>
#include <vector>

using namespace osgWater;

namespace {

using Mapping = std::function<void(double u, double v, double& x, double& y)>;

std::vector<float> photonsAt(int n, const Mapping& map, float energy = 1.0f)
{
    std::vector<float> p(std::size_t(n) * n * 4);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            double x, y;
            map((i + 0.5) / n, (j + 0.5) / n, x, y);
            float* q = &p[4 * (std::size_t(j) * n + i)];
            q[0] = float(x);
            q[1] = float(y);
            q[2] = energy;
            q[3] = 1.0f;
        }
    return p;
}

std::vector<float> mesh(const std::vector<float>& photons, int n, int size)
{
    std::vector<float> c(std::size_t(size) * size, 0.0f);
    meshPhotons(photons.data(), n, 1.0f, c.data(), size);
    return c;
}

double total(const std::vector<float>& c) { return std::accumulate(c.begin(), c.end(), 0.0); }

}

TEST(PhotonMesh, UndisplacedPhotonsGiveTheirEnergyEverywhereTheMeshCovers)
{
    const int n = 64, size = 32;
    const std::vector<float> c = mesh(photonsAt(n, [](double u, double v, double& x, double& y) { x = u; y = v; }, 0.8f), n, size);
    // the mesh spans the photon texel centres: every caustics texel but the outermost ring
    for (int j = 1; j < size - 1; ++j)
        for (int i = 1; i < size - 1; ++i) ASSERT_NEAR(c[j * size + i], 0.8f, 1e-5f) << i << ", " << j;
}

TEST(PhotonMesh, AContractionConcentratesByItsAreaRatioAndConservesEnergy)
{
    // every photon moved halfway to the centre: the light of the whole grid on a quarter of the area
    // (the hull's edges fall on texel centres, which the top-left rule counts once per pair of edges)
    const int n = 64, size = 128;
    const std::vector<float> c = mesh(photonsAt(n, [](double u, double v, double& x, double& y) {
        x = 0.5 + 0.5 * (u - 0.5);
        y = 0.5 + 0.5 * (v - 0.5);
    }), n, size);
    EXPECT_NEAR(c[64 * size + 64], 4.0f, 1e-4f);
    EXPECT_NEAR(c[40 * size + 80], 4.0f, 1e-4f);
    EXPECT_EQ(c[10 * size + 10], 0.0f) << "outside the contracted mesh";
    // the mesh's power (its (n-1)^2 cells) in caustics texels of area 1 / size^2
    const double cells = double(n - 1) * (n - 1) / (double(n) * n);
    EXPECT_NEAR(total(c) / (size * size), cells, 1e-4 * cells);
}

TEST(PhotonMesh, AFoldCountsByItsAbsoluteArea)
{
    // mirrored in u: every triangle flips; the light lands the same, positive
    const int n = 32, size = 32;
    const std::vector<float> c = mesh(photonsAt(n, [](double u, double v, double& x, double& y) { x = 1.0 - u; y = v; }), n, size);
    for (int j = 1; j < size - 1; ++j)
        for (int i = 1; i < size - 1; ++i) ASSERT_NEAR(c[j * size + i], 1.0f, 1e-5f) << i << ", " << j;
}

TEST(PhotonMesh, OverlappingSheetsAdd)
{
    // a fold along u = 0.5: the right half mirrored onto the left, two sheets over the left half
    const int n = 64, size = 64;
    const std::vector<float> c = mesh(photonsAt(n, [](double u, double v, double& x, double& y) {
        x = u < 0.5 ? u : 1.0 - u;
        y = v;
    }), n, size);
    EXPECT_NEAR(c[32 * size + 16], 2.0f, 1e-4f);
    EXPECT_EQ(c[32 * size + 48], 0.0f);
}

TEST(PhotonMesh, DegenerateTrianglesAreCappedAndNeverNaN)
{
    // every photon on one point: triangles of no area add nothing; a sliver is capped
    const int n = 16, size = 16;
    std::vector<float> c = mesh(photonsAt(n, [](double, double, double& x, double& y) { x = 0.5; y = 0.5; }), n, size);
    EXPECT_EQ(total(c), 0.0);
    // squeezed in u onto the texel centres' column x = 8.5 texels: slivers 1e-5 texels wide, a
    // 10^5-fold concentration uncapped; the n - 1 cells of a row stack over the same centres
    c = mesh(photonsAt(n, [](double u, double v, double& x, double& y) {
        x = (8.5 + 1e-5 * (u - 0.5)) / 16.0;
        y = 0.5 + 0.5 * (v - 0.5);
    }), n, size);
    float top = 0.0f;
    for (float x : c) {
        ASSERT_TRUE(std::isfinite(x));
        top = std::max(top, x);
    }
    EXPECT_GT(top, 0.0f) << "the slivers cover texel centres";
    EXPECT_LE(top, 2 * (n - 1) * kMaxCausticConcentration) << "each stacked triangle capped";
}

TEST(PhotonMesh, ATriangleWithADroppedPhotonIsDropped)
{
    const int n = 16, size = 64;
    std::vector<float> p = photonsAt(n, [](double u, double v, double& x, double& y) { x = u; y = v; });
    const double whole = total(mesh(p, n, size));
    // a NaN photon and a missing one (alpha 0), each inside: their six triangles each, 3 cells
    p[4 * (5 * n + 5) + 0] = std::nanf("");
    p[4 * (10 * n + 10) + 3] = 0.0f;
    const std::vector<float> c = mesh(p, n, size);
    for (float x : c) ASSERT_TRUE(std::isfinite(x));
    const double cellPower = double(size) * size / (double(n) * n); // one cell's power in texel units
    EXPECT_NEAR(whole - total(c), 2 * 3 * cellPower, 0.5 * cellPower);
}

TEST(PhotonMesh, DarkPhotonsKeepTheirTrianglesWhichFadeToThem)
{
    // photons of zero energy (the sun's ray meets the scene before the water there) from column 8
    // on: the cells between column 7 and 8 fade from the lit side to the dark one and give half a
    // cell each; dropping the dark photons instead would leave those cells unlit
    const int n = 16, size = 64;
    std::vector<float> p = photonsAt(n, [](double u, double v, double& x, double& y) { x = u; y = v; });
    for (int j = 0; j < n; ++j)
        for (int i = 8; i < n; ++i) p[4 * (std::size_t(j) * n + i) + 2] = 0.0f;
    const double cellPower = double(size) * size / (double(n) * n);
    EXPECT_NEAR(total(mesh(p, n, size)), (7 + 0.5) * (n - 1) * cellPower, 0.5 * cellPower);
}

TEST(PhotonMesh, SupersampledATexelAnEdgeCrossesGetsTheShareOfItsFourSamplesInside)
{
    // every photon moved halfway to the centre (as above): the mesh's left edge at x = 32.5 + 0.1
    // texels after a shift of 0.1, so texel 32 (samples at 32.25 and 32.75 across) is half
    // covered; one pass samples its centre 32.5, outside
    const int n = 64, size = 128;
    const std::vector<float> photons = photonsAt(n, [](double u, double v, double& x, double& y) {
        x = 0.5 + 0.5 * (u - 0.5) + 0.1 / 128.0;
        y = 0.5 + 0.5 * (v - 0.5);
    });
    std::vector<float> once(std::size_t(size) * size, 0.0f), four(once);
    meshPhotons(photons.data(), n, 1.0f, once.data(), size);
    for (const GatherShift& shift : kSupersampleShifts) meshPhotons(photons.data(), n, 1.0f, four.data(), size, shift);
    EXPECT_EQ(once[64 * size + 32], 0.0f);
    EXPECT_NEAR(four[64 * size + 32], 2.0f, 1e-4f) << "two of four samples inside, 4x the sun each";
    EXPECT_NEAR(four[64 * size + 64], 4.0f, 1e-4f) << "inside: all four";
    EXPECT_NEAR(total(four), total(once), 1e-3 * total(once)) << "the same energy";
}

TEST(PhotonMesh, GatherPassesAreOneFourNineOrThirtySixAndConserveTheEnergy)
{
    EXPECT_EQ(gatherPasses(false, false, 64).size(), 1u);
    EXPECT_EQ(gatherPasses(true, false, 64).size(), 4u);
    EXPECT_EQ(gatherPasses(false, true, 64).size(), 9u);
    EXPECT_EQ(gatherPasses(true, true, 64).size(), 36u);
    for (bool supersampled : { false, true }) {
        double weight = 0;
        for (const GatherShift& p : gatherPasses(supersampled, true, 64)) {
            weight += p.weight;
            EXPECT_TRUE(std::fabs(std::round(p.x / 64.0) * 64.0 - p.x) <= 0.25f) << "whole tiles, jittered";
        }
        EXPECT_NEAR(weight, 9.0, 1e-6) << "each tile's passes carry the whole energy once";
    }
}

TEST(PhotonMesh, TiledLightThatLandsInANeighbouringTileWrapsIn)
{
    // a tile's samples on both its edges (n - 1 apart), every photon moved a third of a tile
    // along +x: wrapped, the light is uniform again, with no seam where the tiles meet
    const int n = 32, size = 32;
    std::vector<float> photons = photonsAt(n, [](double, double, double&, double&) {});
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            float* p = &photons[4 * (std::size_t(j) * n + i)];
            p[0] = float(i) / (n - 1) + 1.0f / 3.0f;
            p[1] = float(j) / (n - 1);
        }
    std::vector<float> c(std::size_t(size) * size, 0.0f);
    const float spacing = float(size) / (n - 1);
    for (const GatherShift& shift : gatherPasses(false, true, size))
        meshPhotons(photons.data(), n, 1.0f, c.data(), size, shift, spacing);
    for (int j = 0; j < size; ++j)
        for (int i = 0; i < size; ++i) ASSERT_NEAR(c[j * size + i], 1.0f, 1e-4f) << i << ", " << j;
}
