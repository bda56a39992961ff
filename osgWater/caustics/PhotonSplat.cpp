#include "caustics/PhotonSplat.h"
#include <algorithm>
#include <cmath>
#include <iterator>
#include <utility>

namespace {
// the acceptance test of splat.vert (NaN fails every comparison): a photon on the texture or on
// one of its neighbours (which the tiled gather shifts in)
bool acceptedPhoton(const float* p)
{
    return p[3] > 0.5f && p[2] >= 0.0f && p[0] > -1.01f && p[0] < 2.01f && p[1] > -1.01f && p[1] < 2.01f;
}

struct MeshVertex {
    float x, y, energy; // caustics pixels, transmitted energy
};

// GL's top-left rule: a centre exactly on an edge belongs to one of the two triangles sharing it
bool ownsEdge(float ex, float ey) { return ey > 0.0f || (ey == 0.0f && ex < 0.0f); }

void rasterTriangle(MeshVertex a, MeshVertex b, MeshVertex c, float sourceArea, float valueScale,
                    float* caustics, int size)
{
    float area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x); // twice the signed area
    if (!(std::abs(area) > 0.0f)) return;                              // no area: nothing covered
    if (area < 0.0f) { std::swap(b, c); area = -area; }                // a fold counts like any triangle
    const float ratio = std::min(sourceArea / (0.5f * area), osgWater::kMaxCausticConcentration);
    const MeshVertex v[3] = { a, b, c };
    const int x0 = std::max(0, int(std::floor(std::min({ a.x, b.x, c.x }) - 0.5f)));
    const int x1 = std::min(size - 1, int(std::ceil(std::max({ a.x, b.x, c.x }) - 0.5f)));
    const int y0 = std::max(0, int(std::floor(std::min({ a.y, b.y, c.y }) - 0.5f)));
    const int y1 = std::min(size - 1, int(std::ceil(std::max({ a.y, b.y, c.y }) - 0.5f)));
    for (int ty = y0; ty <= y1; ++ty)
        for (int tx = x0; tx <= x1; ++tx) {
            const float px = tx + 0.5f, py = ty + 0.5f;
            float w[3];
            bool inside = true;
            for (int e = 0; e < 3 && inside; ++e) {
                const MeshVertex& p = v[(e + 1) % 3];
                const MeshVertex& q = v[(e + 2) % 3];
                const float ex = q.x - p.x, ey = q.y - p.y;
                w[e] = ex * (py - p.y) - ey * (px - p.x); // the barycentric weight of v[e], times twice the area
                inside = w[e] > 0.0f || (w[e] == 0.0f && ownsEdge(ex, ey));
            }
            if (!inside) continue;
            const float energy = (w[0] * v[0].energy + w[1] * v[1].energy + w[2] * v[2].energy) / area;
            caustics[std::size_t(ty) * size + tx] += energy * ratio / valueScale;
        }
}
}

void osgWater::meshPhotons(const float* photons, int grid, float valueScale, float* caustics, int size,
                           const GatherShift& shift, float spacing)
{
    // a surface cell in caustics pixels: the photon texel's side is size / grid of them
    const float texel = spacing > 0.0f ? spacing : float(size) / float(grid);
    const float sourceArea = 0.5f * texel * texel;
    auto vertex = [&](int i, int j, MeshVertex& m) {
        const float* p = photons + 4 * (std::size_t(j) * grid + i);
        m = { p[0] * size + shift.x, p[1] * size + shift.y, p[2] * shift.weight };
        return acceptedPhoton(p) && std::isfinite(m.x) && std::isfinite(m.y) && std::isfinite(m.energy);
    };
    for (int j = 0; j + 1 < grid; ++j)
        for (int i = 0; i + 1 < grid; ++i) {
            MeshVertex a, b, c, d; // (i,j) (i+1,j) (i+1,j+1) (i,j+1)
            const bool va = vertex(i, j, a), vb = vertex(i + 1, j, b), vc = vertex(i + 1, j + 1, c),
                       vd = vertex(i, j + 1, d);
            if (va && vb && vc) rasterTriangle(a, b, c, sourceArea, valueScale, caustics, size);
            if (va && vc && vd) rasterTriangle(a, c, d, sourceArea, valueScale, caustics, size);
        }
}

void osgWater::splatPhotons(const float* photons, std::size_t count, float weight, float* caustics, int size,
                            const GatherShift& shift)
{
    for (std::size_t i = 0; i < count; ++i) {
        const float* p = photons + 4 * i;
        if (!acceptedPhoton(p) || !(p[2] > 0.0f)) continue; // a dark photon adds nothing
        const float e = p[2] * weight * shift.weight;
        if (!std::isfinite(e)) continue;
        // texel centres sit at integer + 0.5: the four around (x, y) start at floor(x - 0.5)
        const float x = p[0] * size + shift.x - 0.5f, y = p[1] * size + shift.y - 0.5f;
        const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
        const float fx = x - x0, fy = y - y0;
        const float w[2][2] = { { (1 - fx) * (1 - fy), fx * (1 - fy) }, { (1 - fx) * fy, fx * fy } };
        for (int j = 0; j < 2; ++j)
            for (int k = 0; k < 2; ++k) {
                const int tx = x0 + k, ty = y0 + j;
                if (tx < 0 || ty < 0 || tx >= size || ty >= size) continue;
                caustics[std::size_t(ty) * size + tx] += e * w[j][k];
            }
    }
}

std::vector<osgWater::GatherShift> osgWater::gatherPasses(bool supersampled, bool tiled, int size)
{
    std::vector<GatherShift> passes;
    const std::vector<GatherShift> jitters = supersampled ? std::vector<GatherShift>(std::begin(kSupersampleShifts),
                                                                                      std::end(kSupersampleShifts))
                                                          : std::vector<GatherShift>(1);
    for (int ty = tiled ? -1 : 0; ty <= (tiled ? 1 : 0); ++ty)
        for (int tx = tiled ? -1 : 0; tx <= (tiled ? 1 : 0); ++tx)
            for (const GatherShift& j : jitters)
                passes.push_back({ j.x + float(tx * size), j.y + float(ty * size), j.weight });
    return passes;
}
