#include "PhotonTracer.h"
#include <osgWater/WaterSurface>
#include <glm/geometric.hpp>
#include <atomic>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <thread>

namespace bench {

namespace {

// splitmix64: a small deterministic generator, the same on every library
struct Rng {
    uint64_t s;
    double next()
    {
        uint64_t z = (s += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return double((z ^ (z >> 31)) >> 11) * (1.0 / 9007199254740992.0);
    }
};

// rows of photons done out of all rows; every row holds `perRow` photons
void progressBar(size_t done, size_t total, size_t perRow)
{
    const int width = 40, filled = int(double(done) / double(total) * width);
    std::fprintf(stderr, "\r  photons [%.*s%*s] %3d%% of %zu", filled, "########################################",
                 width - filled, "", int(100.0 * done / total), total * perRow);
    if (done == total) std::fprintf(stderr, "\n");
    std::fflush(stderr);
}

}

PhotonImage tracePhotons(const RayCaster& scene, const WaterCaster& water, const osgWater::WaterSurface& surface,
                         double t, const osg::Matrixd& localToSun, const osg::Vec3d& towardsSun,
                         const PhotonSettings& s)
{
    PhotonImage out;
    out.resolution = s.resolution;
    // two independent sets of jittered strata over the whole window, side x side each: rows
    // 0..side-1 are the first half's, side..2 side-1 the second's. (Interleaved rows of one set
    // would not do: how many of a half's rows cross a texel varies from texel to texel, and their
    // difference would count that as noise the whole set does not have.)
    const size_t side = std::max<size_t>(1, size_t(std::ceil(std::sqrt(double(s.photons) / 2.0))));
    const size_t rows = 2 * side;
    out.photons = rows * side;
    out.value.assign(size_t(s.resolution) * s.resolution, 0.0f);
    out.half[0] = out.half[1] = out.value;
    const osg::Matrixd sunToLocal = osg::Matrixd::inverse(localToSun);
    const glm::dvec3 L = glm::normalize(glm::dvec3(towardsSun.x(), towardsSun.y(), towardsSun.z()));
    // each half's photons carry twice the full set's weight: either half alone estimates the image
    const double halfWeight = 2.0 * double(s.resolution) * s.resolution / double(out.photons);
    std::mutex merge;
    std::atomic<size_t> rowsDone{ 0 };
    auto work = [&](size_t r0, size_t r1, unsigned seed) {
        std::vector<double> acc[2] = { std::vector<double>(out.value.size(), 0.0), std::vector<double>(out.value.size(), 0.0) };
        Rng rng{ seed * 0x12345ull + 7 };
        for (size_t r = r0; r < r1; ++r) {
            const size_t h = r / side, row = r % side;
            for (size_t c = 0; c < side; ++c) {
                const double u = (c + rng.next()) / side, v = (row + rng.next()) / side;
                const osg::Vec3d o = osg::Vec3d(u, v, 0.0) * sunToLocal; // on the sun camera's near plane
                const glm::dvec3 org(o.x(), o.y(), o.z());
                const Hit w = water.intersect(org, -L);
                if (!w.hit) continue;
                if (scene.intersect(org, -L, 0.0, w.t).hit) continue; // the scene shades this water from the sun
                glm::dvec3 N(0, 0, 1);
                if (surface.usesGrid()) {
                    const osg::Vec3d n = surface.normal(w.point.x, w.point.y, t);
                    N = glm::normalize(glm::dvec3(n.x(), n.y(), n.z()));
                } else if (w.normal.z < 0.0) N = -w.normal; else N = w.normal;
                if (glm::dot(N, L) <= 0.0) continue; // the sun behind this facet
                glm::dvec3 T;
                if (!snell(-L, N, s.media.air, s.media.water, T)) continue;
                const Hit b = scene.intersect(w.point, T, 1e-6 * (1.0 + w.t));
                if (!b.hit) continue;
                const double energy = (1.0 - fresnelExact(glm::dot(N, L), s.media.air, s.media.water)) *
                                      std::exp(-s.attenuation * b.t);
                const osg::Vec3d tex = osg::Vec3d(b.point.x, b.point.y, b.point.z) * localToSun;
                const int i = int(std::floor(tex.x() * s.resolution)), j = int(std::floor(tex.y() * s.resolution));
                if (i < 0 || j < 0 || i >= s.resolution || j >= s.resolution) continue;
                acc[h][size_t(j) * s.resolution + i] += energy * halfWeight;
            }
            const size_t done = ++rowsDone;
            if (s.progress && seed == 0 && (done % std::max<size_t>(1, rows / 50) == 0)) progressBar(done, rows, side);
        }
        std::lock_guard<std::mutex> lock(merge);
        for (int h = 0; h < 2; ++h)
            for (size_t i = 0; i < acc[h].size(); ++i) out.half[h][i] += float(acc[h][i]);
    };
    const unsigned threads = std::max(1u, std::min(8u, std::thread::hardware_concurrency()));
    std::vector<std::thread> pool;
    for (unsigned i = 0; i < threads; ++i) pool.emplace_back(work, rows * i / threads, rows * (i + 1) / threads, i);
    for (std::thread& th : pool) th.join();
    if (s.progress) progressBar(rows, rows, side);
    for (size_t i = 0; i < out.value.size(); ++i) out.value[i] = 0.5f * (out.half[0][i] + out.half[1][i]);
    return out;
}

osg::ref_ptr<osg::Image> tileSeenFromTheSun(const osg::Image* tile, const RayCaster& scene,
                                            const osgWater::CausticsLighting& lighting, const osg::Vec3d& towardsSun,
                                            double level, int resolution)
{
    osg::ref_ptr<osg::Image> out = new osg::Image;
    out->allocateImage(resolution, resolution, 1, GL_RGBA, GL_FLOAT);
    std::fill_n(reinterpret_cast<float*>(out->data()), size_t(resolution) * resolution * 4, 0.0f);
    const osg::Matrixd sunToLocal = osg::Matrixd::inverse(lighting.localToSun);
    const glm::dvec3 L = glm::normalize(glm::dvec3(towardsSun.x(), towardsSun.y(), towardsSun.z()));
    const int n = tile->s();
    auto texel = [&](int i, int j) {
        i = ((i % n) + n) % n; // the tile repeats
        j = ((j % n) + n) % n;
        return reinterpret_cast<const float*>(tile->data(i, j))[0];
    };
    for (int j = 0; j < resolution; ++j)
        for (int i = 0; i < resolution; ++i) {
            const osg::Vec3d o = osg::Vec3d((i + 0.5) / resolution, (j + 0.5) / resolution, 0.0) * sunToLocal;
            if (!(L.z > 0.0) || o.z() < level) continue;
            // from where the sun ray crosses the water level down to the first thing it meets
            const glm::dvec3 start = glm::dvec3(o.x(), o.y(), o.z()) - L * ((o.z() - level) / L.z);
            const Hit b = scene.intersect(start, -L);
            if (!b.hit) continue;
            const osg::Vec3d q = osg::Vec3d(b.point.x, b.point.y, b.point.z) * lighting.localToTile;
            // bilinear between texel centres, as the texture filter reads it
            const double x = q.x() * n - 0.5, y = q.y() * n - 0.5;
            const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
            const double fx = x - x0, fy = y - y0;
            const double v = (1 - fx) * (1 - fy) * texel(x0, y0) + fx * (1 - fy) * texel(x0 + 1, y0) +
                             (1 - fx) * fy * texel(x0, y0 + 1) + fx * fy * texel(x0 + 1, y0 + 1);
            // faded as the scene program fades it: by the bed point's depth (the green channel's, as
            // the reference's photons)
            const double fade = std::exp(-double(lighting.channelExtinction.y()) * std::max(0.0, level - b.point.z));
            reinterpret_cast<float*>(out->data(i, j))[0] = float(v * fade);
        }
    return out;
}

}
