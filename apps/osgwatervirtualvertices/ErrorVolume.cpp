#include "ErrorVolume.h"
#include <algorithm>
#include <cmath>
#include <thread>
#include <vector>

namespace vv {

using namespace osgWater::virtualvertices;

bool impliedPoint(const Refractor& refractor, const glm::dvec3& eye, const glm::dvec3& V, double eta, glm::dvec3& point)
{
    const glm::dvec3 dir = glm::normalize(V - eye);
    glm::dvec3 P, N;
    if (!refractor.intersect(eye, dir, P, N)) return false;
    const RefractionRay ray = refractionRay(dir, N, eta);
    if (ray.kind != RayKind::Refracted) return false;
    point = P + ray.direction * (glm::length(V - P) / eta);
    return true;
}

namespace {

struct Partial {
    double sum = 0.0, sum2 = 0.0, max = 0.0;
    ErrorStats counts;
};

void measureSlices(const Refractor& refractor, const Cells& cells, const Box& box, SightPoint method, int first,
                   int stride, Partial& out)
{
    const glm::dvec3 step = (box.max - box.min) / double(box.perAxis);
    for (int k = first; k < box.perAxis; k += stride)
        for (int j = 0; j < box.perAxis; ++j)
            for (int i = 0; i < box.perAxis; ++i) {
                const glm::dvec3 T = box.min + (glm::dvec3(i, j, k) + 0.5) * step;
                if (!refractor.beyond(T)) continue;
                const VirtualVertex v = virtualVertex(cells, T, method, true);
                if (!v.found) { ++out.counts.outside; continue; }
                if (v.containingCells > 1) { ++out.counts.convergence; continue; }
                if (v.extrapolated) { ++out.counts.extrapolated; continue; }
                glm::dvec3 implied;
                if (!impliedPoint(refractor, cells.eye, v.position, cells.eta, implied)) {
                    ++out.counts.unimplied;
                    continue;
                }
                const double e = glm::length(implied - T);
                out.sum += e;
                out.sum2 += e * e;
                out.max = std::max(out.max, e);
                ++out.counts.samples;
            }
}

} // namespace

ErrorStats measureErrorVolume(const Refractor& refractor, const glm::dvec3& eye, const Medium& medium, const Box& box,
                              SightPoint method)
{
    const Cells cells = buildCells(refractor.membrane(), eye, medium.nEye, medium.nOther);
    const int threads = std::max(1, int(std::thread::hardware_concurrency()));
    std::vector<Partial> parts(threads);
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t)
        pool.emplace_back(measureSlices, std::cref(refractor), std::cref(cells), std::cref(box), method, t, threads,
                          std::ref(parts[t]));
    for (std::thread& t : pool) t.join();

    ErrorStats s;
    double sum = 0.0, sum2 = 0.0;
    for (const Partial& p : parts) {
        sum += p.sum;
        sum2 += p.sum2;
        s.max = std::max(s.max, p.max);
        s.samples += p.counts.samples;
        s.outside += p.counts.outside;
        s.convergence += p.counts.convergence;
        s.extrapolated += p.counts.extrapolated;
        s.unimplied += p.counts.unimplied;
    }
    if (s.samples > 0) {
        s.mean = sum / s.samples;
        s.deviation = std::sqrt(std::max(0.0, sum2 / s.samples - s.mean * s.mean));
    }
    return s;
}

}
