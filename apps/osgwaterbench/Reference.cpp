#include "Reference.h"
#include <osgWater/WaterSurface>
#include "surface/SpectralWaves.h"
#include <glm/geometric.hpp>
#include <glm/mat2x2.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <thread>

namespace bench {

bool snell(const glm::dvec3& d, const glm::dvec3& n, double n1, double n2, glm::dvec3& out)
{
    const double eta = n1 / n2, cosI = -glm::dot(d, n);
    const double k = 1.0 - eta * eta * (1.0 - cosI * cosI);
    if (k < 0.0) return false;
    out = glm::normalize(eta * d + (eta * cosI - std::sqrt(k)) * n);
    return true;
}

double fresnelExact(double cosI, double n1, double n2)
{
    cosI = std::min(std::max(cosI, 0.0), 1.0);
    const double sinT = n1 / n2 * std::sqrt(std::max(0.0, 1.0 - cosI * cosI));
    if (sinT >= 1.0) return 1.0;
    const double cosT = std::sqrt(1.0 - sinT * sinT);
    const double rs = (n1 * cosI - n2 * cosT) / (n1 * cosI + n2 * cosT);
    const double rp = (n2 * cosI - n1 * cosT) / (n2 * cosI + n1 * cosT);
    return 0.5 * (rs * rs + rp * rp);
}

Reference::Reference(const RayCaster& scene, const WaterCaster& water, const osgWater::WaterSurface& surface, double t,
                     Media media)
    : _scene(scene), _water(water), _surface(surface), _t(t), _media(media)
{
}

bool Reference::eyeBelow(const glm::dvec3& e) const
{
    const double h = _surface.usesGrid() ? _surface.height(e.x, e.y, _t) : _surface.getLevel();
    return e.z < h;
}

glm::dvec3 Reference::normalAt(const Hit& h) const
{
    if (_surface.usesGrid()) { // the analytic normal the fragment shader evaluates at U
        const osg::Vec3d n = _surface.normal(h.point.x, h.point.y, _t);
        return glm::normalize(glm::dvec3(n.x(), n.y(), n.z()));
    }
    return h.normal.z < 0.0 ? -h.normal : h.normal;
}

double Reference::roughnessAt(const Hit& h) const
{
    const osgWater::detail::SpectralWaves* wind = _surface.usesGrid() ? _surface.getSpectralWaves() : nullptr;
    return wind ? wind->at(_t).roughness(h.point.x, h.point.y) : 0.0;
}

Hit Reference::waterFirst(const glm::dvec3& eye, const glm::dvec3& dir) const
{
    const Hit w = _water.intersect(eye, dir);
    if (!w.hit) return w;
    const Hit s = _scene.intersect(eye, dir, 0.0, w.t);
    return s.hit && s.t < w.t ? Hit() : w; // something in front of the water
}

glm::dvec3 Reference::mirroredEye(const glm::dvec3& eye) const
{
    return glm::dvec3(eye.x, eye.y, 2.0 * _surface.getLevel() - eye.z);
}

PixelTrace Reference::trace(const glm::dvec3& eye, const glm::dvec3& dir) const
{
    PixelTrace p;
    const Hit w = waterFirst(eye, dir);
    if (!w.hit) return p;
    p.water = true;
    p.below = eyeBelow(eye);
    p.U = w.point;
    const double n1 = p.below ? _media.water : _media.air, n2 = p.below ? _media.air : _media.water;
    glm::dvec3 N = normalAt(w);
    if (p.below) N = -N;
    if (glm::dot(N, dir) > 0.0) N = -N; // the ray met a side the analytic normal turns away from
    p.N = N;
    p.Rr = glm::reflect(dir, N);
    const double cosI = -glm::dot(dir, N);
    p.fresnel = fresnelExact(cosI, n1, n2);
    p.tir = !snell(dir, N, n1, n2, p.R);
    const double eps = 1e-6 * (1.0 + w.t);
    if (!p.tir) p.refracted = _scene.intersect(p.U, p.R, eps);
    p.reflected = _scene.intersect(p.U, p.Rr, eps);
    p.underwaterPath = p.below ? w.t : (p.refracted.hit ? p.refracted.t : 0.0);
    p.reflectionShown = reflectionPassShows(_scene, _surface.getLevel(), eye, p.below, p.reflected, p.Rr);
    return p;
}

glm::dvec3 Reference::mirrorSight(const glm::dvec3& eye, const PixelTrace& p) const
{
    return p.reflected.hit ? glm::normalize(p.reflected.point - mirroredEye(eye)) : p.Rr;
}

PixelFan pixelFan(const Reference& ref, const glm::dvec3& eye, const glm::dvec3 quarterDirs[4])
{
    PixelFan fan;
    glm::dvec3 sight[4];
    bool refracted = true;
    for (int i = 0; i < 4; ++i) {
        const PixelTrace q = ref.trace(eye, quarterDirs[i]);
        if (!q.water) return fan;
        sight[i] = ref.mirrorSight(eye, q);
        refracted = refracted && !q.tir && q.refracted.hit;
        fan.X[i] = q.refracted.point;
    }
    fan.refracted = refracted;
    double widest = 0.0;
    for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j)
            widest = std::max(widest, std::acos(std::min(std::max(glm::dot(sight[i], sight[j]), -1.0), 1.0)));
    fan.mirrorSpread = widest;
    return fan;
}

bool reflectionPassShows(const RayCaster& scene, double level, const glm::dvec3& eye, bool below, const Hit& reflected,
                         const glm::dvec3& Rr)
{
    const double side = below ? -1.0 : 1.0;
    const glm::dvec3 mirrored(eye.x, eye.y, 2.0 * level - eye.z);
    // the mirrored eye's line of sight to the hit (t = 1 at it), or along the ray to the sky
    const glm::dvec3 d = reflected.hit ? reflected.point - mirrored : Rr;
    if (reflected.hit && side * (reflected.point.z - level) < 0.0) return false;
    if (!(side * d.z > 0.0)) return false; // it never reaches the pass's side
    // from where it crosses the level (at the eye already when the eye sits between a trough and the level)
    const double t0 = std::max((level - mirrored.z) / d.z, 0.0);
    const double t1 = reflected.hit ? 1.0 - 1e-6 : 1e30;
    return !scene.intersect(mirrored, d, t0, t1).hit;
}

namespace {

glm::dvec3 toGlm(const osg::Vec3d& v) { return glm::dvec3(v.x(), v.y(), v.z()); }

// metres -> pixels: least-squares inverse of the 3x2 Jacobian [dX/dx dX/dy]
bool pseudoInverse(const glm::dvec3& jx, const glm::dvec3& jy, glm::mat2x3& out)
{
    const double a = glm::dot(jx, jx), b = glm::dot(jx, jy), d = glm::dot(jy, jy);
    const double det = a * d - b * b;
    if (!(det > 1e-4 * a * d) || !(a > 0.0) || !(d > 0.0)) return false;
    // (J^T J)^-1 J^T: row 0 = (d jx - b jy) / det, row 1 = (a jy - b jx) / det
    const glm::dvec3 r0 = (d * jx - b * jy) / det, r1 = (a * jy - b * jx) / det;
    // glm::mat2x3 has 2 columns of 3: store the rows as columns (apply with dot products)
    out[0] = glm::vec3(r0);
    out[1] = glm::vec3(r1);
    return true;
}

}

ViewRays::ViewRays(const osg::Matrixd& viewMatrix, const osg::Matrixd& projection, int w, int h)
    : eye(toGlm(osg::Matrixd::inverse(viewMatrix).getTrans())), _inverse(osg::Matrixd::inverse(viewMatrix * projection)),
      _width(w), _height(h)
{
}

glm::dvec3 ViewRays::through(double x, double y) const
{
    const double nx = x / _width * 2.0 - 1.0, ny = y / _height * 2.0 - 1.0;
    return glm::normalize(toGlm(osg::Vec3d(nx, ny, 1.0) * _inverse) - toGlm(osg::Vec3d(nx, ny, -1.0) * _inverse));
}

void forEachPixelRay(const osg::Matrixd& viewMatrix, const osg::Matrixd& projection, int width, int height,
                     const std::function<void(int, int, const glm::dvec3&, const glm::dvec3&)>& pixel,
                     const glm::dvec2& offset)
{
    const ViewRays rays(viewMatrix, projection, width, height);
    auto rows = [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < width; ++x) pixel(x, y, rays.eye, rays.through(x + offset.x, y + offset.y));
    };
    const int threads = std::max(1u, std::min(8u, std::thread::hardware_concurrency()));
    std::vector<std::thread> pool;
    for (int i = 0; i < threads; ++i) pool.emplace_back(rows, height * i / threads, height * (i + 1) / threads);
    for (std::thread& th : pool) th.join();
}

ReferenceImage traceView(const Reference& ref, const osg::Matrixd& viewMatrix, const osg::Matrixd& projection,
                         int width, int height)
{
    ReferenceImage img;
    img.width = width;
    img.height = height;
    img.pixels.resize(size_t(width) * height);
    std::vector<PixelTrace> full(size_t(width) * height);
    // per water pixel, the fans of its own rays: the mirror rays' widest angle, and the refracted
    // hits kept relative to the centre's (in pixels once the Jacobian below is known)
    std::vector<float> spread(size_t(width) * height, 0.0f);
    std::vector<std::array<glm::vec3, 4>> quarterHits(size_t(width) * height);
    std::vector<uint8_t> quartersRefract(size_t(width) * height, 0); // (bytes: threads write their own)
    const ViewRays rays(viewMatrix, projection, width, height);
    forEachPixelRay(viewMatrix, projection, width, height, [&](int x, int y, const glm::dvec3& eye, const glm::dvec3& dir) {
        const size_t i = size_t(y) * width + x;
        full[i] = ref.trace(eye, dir);
        if (!full[i].water) return;
        const glm::dvec3 quarters[4] = { rays.through(x + 0.25, y + 0.25), rays.through(x + 0.75, y + 0.25),
                                         rays.through(x + 0.25, y + 0.75), rays.through(x + 0.75, y + 0.75) };
        const PixelFan fan = pixelFan(ref, eye, quarters);
        spread[i] = float(fan.mirrorSpread);
        for (int q = 0; q < 4; ++q) quarterHits[i][q] = glm::vec3(fan.X[q] - full[i].refracted.point);
        quartersRefract[i] = fan.refracted && full[i].refracted.hit;
    });

    auto hitOk = [&](int x, int y, const Hit& h0) {
        if (x < 0 || y < 0 || x >= width || y >= height) return false;
        const PixelTrace& q = full[size_t(y) * width + x];
        // a neighbour on the same smooth surface (normals within ~25 deg), else an edge
        return q.water && q.refracted.hit && std::fabs(glm::dot(q.refracted.normal, h0.normal)) > 0.9;
    };
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const PixelTrace& p = full[size_t(y) * width + x];
            PixelRef& r = img.pixels[size_t(y) * width + x];
            if (!p.water) continue;
            ++img.waterPixels;
            r.flags = PixelRef::WATER | (p.below ? PixelRef::BELOW : 0) | (p.tir ? PixelRef::TIR : 0);
            r.U = glm::vec3(p.U);
            r.fresnel = float(p.fresnel);
            r.Y = glm::vec3(p.reflected.hit ? p.reflected.point : p.Rr);
            if (p.reflected.hit) r.flags |= PixelRef::REFLECTED_HIT;
            if (p.reflectionShown) r.flags |= PixelRef::REFLECTION_SHOWN;
            r.mirrorSpread = spread[size_t(y) * width + x];
            if (!p.refracted.hit) continue;
            r.flags |= PixelRef::REFRACTED_HIT;
            r.X = glm::vec3(p.refracted.point);
            const int sx = hitOk(x + 1, y, p.refracted) ? 1 : hitOk(x - 1, y, p.refracted) ? -1 : 0;
            const int sy = hitOk(x, y + 1, p.refracted) ? 1 : hitOk(x, y - 1, p.refracted) ? -1 : 0;
            if (!sx || !sy) continue;
            const glm::dvec3 jx = (full[size_t(y) * width + x + sx].refracted.point - p.refracted.point) * double(sx);
            const glm::dvec3 jy = (full[size_t(y + sy) * width + x].refracted.point - p.refracted.point) * double(sy);
            if (!pseudoInverse(jx, jy, r.pixelsPerMetre)) continue;
            r.flags |= PixelRef::JACOBIAN;
            r.refractionFan = 1e9f;
            if (!quartersRefract[size_t(y) * width + x]) continue;
            const std::array<glm::vec3, 4>& q = quarterHits[size_t(y) * width + x];
            // the widest two of the pixel's five rays (the centre's hit is q's origin)
            auto onScreen = [&](const glm::vec3& d) {
                return glm::length(glm::vec2(glm::dot(r.pixelsPerMetre[0], d), glm::dot(r.pixelsPerMetre[1], d)));
            };
            float widest = 0.0f;
            for (int a = 0; a < 4; ++a) {
                widest = std::max(widest, onScreen(q[a]));
                for (int b = a + 1; b < 4; ++b) widest = std::max(widest, onScreen(q[a] - q[b]));
            }
            r.refractionFan = widest;
        }
    return img;
}

}
