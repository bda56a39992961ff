#include "Metrics.h"
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <algorithm>
#include <cmath>

namespace bench {

Quantiles quantiles(std::vector<float>& v)
{
    Quantiles q;
    q.n = v.size();
    if (v.empty()) return q;
    std::sort(v.begin(), v.end());
    auto at = [&](double f) { return double(v[size_t(std::floor(f * (v.size() - 1) + 0.5))]); };
    q.median = v.size() % 2 ? v[v.size() / 2] : 0.5 * (double(v[v.size() / 2 - 1]) + v[v.size() / 2]);
    q.p95 = at(0.95);
    q.p99 = at(0.99);
    q.max = v.back();
    q.over2 = double(v.end() - std::upper_bound(v.begin(), v.end(), 2.0f)) / double(v.size());
    return q;
}

namespace {

const osg::Vec4f& px(const osg::Image* img, int x, int y) { return *reinterpret_cast<const osg::Vec4f*>(img->data(x, y)); }
bool finite(const osg::Vec4f& v) { return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()) && std::isfinite(v.w()); }

// clip space -> texel coordinates of a square target (w = 0: a direction)
bool texel(const osg::Matrixd& mvp, const osg::Vec4d& p, int size, osg::Vec2d& out)
{
    const osg::Vec4d c = p * mvp;
    if (!(c.w() > 1e-9)) return false;
    out.set((c.x() / c.w() * 0.5 + 0.5) * size, (c.y() / c.w() * 0.5 + 0.5) * size);
    return std::isfinite(out.x()) && std::isfinite(out.y());
}

// How many reflection texels the pass's camera, at the mirrored eye, spreads a radian over around
// the sight `d` (unit, from the mirrored eye): the larger of two perpendicular turns
double texelsPerRadian(const Estimate& e, const osg::Vec3d& mirroredEye, const glm::dvec3& d)
{
    const glm::dvec3 a = std::fabs(d.z) < 0.9 ? glm::dvec3(0.0, 0.0, 1.0) : glm::dvec3(1.0, 0.0, 0.0);
    const glm::dvec3 u = glm::normalize(glm::cross(d, a)), v = glm::cross(d, u);
    const double turn = 1e-3;
    auto at = [&](const glm::dvec3& s, osg::Vec2d& out) {
        return texel(e.reflectionMVP, osg::Vec4d(mirroredEye + osg::Vec3d(s.x, s.y, s.z), 1.0), e.reflectionSize, out);
    };
    osg::Vec2d c, p, q;
    if (!at(d, c) || !at(glm::normalize(d + turn * u), p) || !at(glm::normalize(d + turn * v), q)) return 1e30;
    return std::max((p - c).length(), (q - c).length()) / turn;
}

}

size_t countNonFinite(const osg::Image* img)
{
    size_t n = 0;
    if (!img) return 0;
    for (int y = 0; y < img->t(); ++y)
        for (int x = 0; x < img->s(); ++x) n += !finite(px(img, x, y));
    return n;
}

namespace {

glm::dvec3 refractionEye(const Estimate& e) { return glm::dvec3(e.refractionEye.x(), e.refractionEye.y(), e.refractionEye.z()); }

// The refraction pass keeps one side of its clip plane: where the ray from its eye along dir
// enters that side (0 when the eye is on it); false when it never does.
bool entersPassSide(const Estimate& e, const glm::dvec3& dir, double& t0)
{
    const glm::dvec3 C = refractionEye(e);
    const double plane = e.eyeBelow ? e.level - e.clearance : e.level + e.clearance;
    t0 = 0.0;
    if (e.eyeBelow ? C.z >= plane : C.z <= plane) return true;
    if (std::fabs(dir.z) < 1e-12 || (e.eyeBelow ? dir.z < 0.0 : dir.z > 0.0)) return false;
    t0 = (plane - C.z) / dir.z;
    return true;
}

bool onTexture(const osg::Vec2d& t, int size) { return t.x() >= 0.0 && t.y() >= 0.0 && t.x() <= size && t.y() <= size; }

// The rays the render traced at pixel (x, y): from the point it shades (DEBUG_SURFACE) at the
// normal it shades with (DEBUG_SLOPES), facing its eye, mirrored and refracted, and their exact hits
struct OwnRays {
    bool valid = false, tir = false;
    glm::dvec3 Rr{ 0.0 };
    Hit reflected, refracted;
};

OwnRays ownRays(const Estimate& e, const ViewRays& rays, const RayCaster& scene, int x, int y)
{
    OwnRays o;
    if (!e.shaded.valid() || !e.slopes.valid()) return o;
    const osg::Vec4f u = px(e.shaded.get(), x, y), s = px(e.slopes.get(), x, y);
    if (!(u.w() > 1.5f && u.w() < 2.5f) || !(s.w() > 1.5f && s.w() < 2.5f) || !finite(u) || !finite(s)) return o;
    const glm::dvec3 U(u.x(), u.y(), u.z()), eye(e.eye.x(), e.eye.y(), e.eye.z());
    // the pixel's ray, not U - eye: an eye on the water shades points micrometres from it, closer
    // than the float U is exact
    const glm::dvec3 D = rays.through(x + 0.5, y + 0.5);
    glm::dvec3 N = glm::normalize(glm::dvec3(-s.x(), -s.y(), 1.0));
    if (e.eyeBelow) N = -N;
    if (glm::dot(N, D) > 0.0) N = -N; // a facet turned from the eye: as the reference takes it
    const double n1 = e.eyeBelow ? e.waterIOR : e.airIOR, n2 = e.eyeBelow ? e.airIOR : e.waterIOR;
    const double eps = 1e-6 * (1.0 + glm::length(U - eye));
    o.valid = true;
    o.Rr = glm::reflect(D, N);
    o.reflected = scene.intersect(U, o.Rr, eps);
    glm::dvec3 R;
    o.tir = !snell(D, N, n1, n2, R);
    if (!o.tir) o.refracted = scene.intersect(U, R, eps);
    return o;
}

}

bool shownPoint(const osg::Vec4f& est, const Estimate& e, const RayCaster& scene, glm::dvec3& out)
{
    // virtual vertices: the true place of what the pass drew, shown as it is
    if (est.w() > 3.5f && est.w() < 4.5f) {
        out = glm::dvec3(est.x(), est.y(), est.z());
        return true;
    }
    const glm::dvec3 C = refractionEye(e);
    glm::dvec3 dir;
    if (est.w() > 1.5f && est.w() < 2.5f) dir = glm::dvec3(est.x(), est.y(), est.z()) - C;
    else if (est.w() > 2.5f && est.w() < 3.5f) dir = glm::dvec3(est.x(), est.y(), est.z());
    else return false;
    if (!(glm::length(dir) > 1e-9)) return false;
    dir = glm::normalize(dir);
    double t0; // the ray starts where it enters the side the pass draws
    if (!entersPassSide(e, dir, t0)) return false;
    const Hit h = scene.intersect(C, dir, t0);
    if (!h.hit) return false;
    out = h.point;
    return true;
}

WorkCounts WorkCounts::pooledWith(const WorkCounts& o) const
{
    if (o.pixels == 0) return *this;
    if (pixels == 0) return o;
    WorkCounts w;
    w.pixels = pixels + o.pixels;
    const double a = double(pixels) / double(w.pixels), b = 1.0 - a;
    w.refractionReads = a * refractionReads + b * o.refractionReads;
    w.reflectionReads = a * reflectionReads + b * o.reflectionReads;
    w.marchHeights = a * marchHeights + b * o.marchHeights;
    return w;
}

WorkCounts countWork(const osg::Image* work)
{
    WorkCounts w;
    if (!work) return w;
    double sum[3] = { 0.0, 0.0, 0.0 };
    for (int y = 0; y < work->t(); ++y)
        for (int x = 0; x < work->s(); ++x) {
            const osg::Vec4f c = px(work, x, y);
            if (!(c.w() > 1.5f && c.w() < 2.5f)) continue; // not water
            for (int i = 0; i < 3; ++i) sum[i] += c[i];
            ++w.pixels;
        }
    if (w.pixels) {
        w.refractionReads = sum[0] / double(w.pixels);
        w.reflectionReads = sum[1] / double(w.pixels);
        w.marchHeights = sum[2] / double(w.pixels);
    }
    return w;
}

ViewErrors measureView(const ReferenceImage& ref, const Estimate& e, const RayCaster& scene)
{
    ViewErrors v;
    for (const osg::Image* img : { e.color.get(), e.bottom.get(), e.reflection.get(), e.fresnel.get(), e.work.get() })
        if (img) v.nanPixels += countNonFinite(img);
    v.waterPixels = ref.waterPixels;
    // the reflection pass's camera: the eye mirrored in the level
    const osg::Vec3d mirrored(e.eye.x(), e.eye.y(), 2.0 * e.level - e.eye.z());
    const ViewRays pixelRays(e.view, e.projection, ref.width, ref.height);
    for (int y = 0; y < ref.height; ++y)
        for (int x = 0; x < ref.width; ++x) {
            const PixelRef& r = ref.at(x, y);
            const osg::Vec4f b = e.bottom.valid() ? px(e.bottom.get(), x, y) : osg::Vec4f();
            // the render's water covers this pixel when a debug estimate (alpha < 0 or > 1.5) is there
            const bool covered = e.bottom.valid() && (b.w() < -0.5f || b.w() > 1.5f);
            if (!(r.flags & PixelRef::WATER)) {
                if (covered) ++v.coverageMismatch; // water drawn where the reference sees none
                continue;
            }
            if (e.bottom.valid() && !covered) { ++v.coverageMismatch; continue; }
            float shadedOffM = -1.0f; // the shaded point's distance from the exact crossing, where known
            if (e.shaded.valid()) { // both see water here
                const osg::Vec4f u = px(e.shaded.get(), x, y);
                if (u.w() > 1.5f && u.w() < 2.5f) {
                    shadedOffM = glm::length(glm::vec3(u.x(), u.y(), u.z()) - r.U);
                    v.shadedPointCm.push_back(100.0f * shadedOffM);
                }
            }
            const OwnRays own = ownRays(e, pixelRays, scene, x, y);
            if (e.fresnel.valid()) {
                const osg::Vec4f f = px(e.fresnel.get(), x, y);
                if (f.w() > 1.5f && std::isfinite(f.x())) v.fresnel.push_back(std::fabs(f.x() - r.fresnel));
            }
            if (e.reflection.valid()) {
                const osg::Vec4f l = px(e.reflection.get(), x, y);
                osg::Vec2d est, exact;
                const osg::Vec4d target = (r.flags & PixelRef::REFLECTED_HIT) ? osg::Vec4d(r.Y.x, r.Y.y, r.Y.z, 1.0)
                                                                              : osg::Vec4d(r.Y.x, r.Y.y, r.Y.z, 0.0);
                // the lookup: a point (alpha 2) or, from a plane-offset lookup whose ray meets no plane, a
                // direction (alpha 3: a point at infinity)
                const double w = l.w() > 2.5f ? 0.0 : 1.0;
                if (l.w() > 1.5f && texel(e.reflectionMVP, osg::Vec4d(l.x(), l.y(), l.z(), w), e.reflectionSize, est) &&
                    texel(e.reflectionMVP, target, e.reflectionSize, exact))
                {
                    const float texels = float((est - exact).length());
                    v.reflectionTexels.push_back(texels);
                    // shown: in the pass's view and on its texture
                    if ((r.flags & PixelRef::REFLECTION_SHOWN) && onTexture(exact, e.reflectionSize)) {
                        v.reflectionShownTexels.push_back(texels);
                        // the fan of the pixel's own mirror rays, in the pass's texels at its sight
                        const glm::dvec3 sight = (r.flags & PixelRef::REFLECTED_HIT)
                                                     ? glm::normalize(glm::dvec3(r.Y) - glm::dvec3(mirrored.x(), mirrored.y(), mirrored.z()))
                                                     : glm::normalize(glm::dvec3(r.Y));
                        const float fan = float(std::min(r.mirrorSpread * texelsPerRadian(e, mirrored, sight), 1e9));
                        v.reflectionFanTexels.push_back(fan);
                        v.reflectionBeyondFanTexels.push_back(std::max(0.0f, texels - fan));
                    } else
                        ++v.reflectionNotShown; // hidden, under the level, or off the texture
                    // the render's own mirror ray
                    osg::Vec2d ownHit;
                    if (own.valid && (e.eyeBelow ? own.Rr.z >= 0.0 : own.Rr.z <= 0.0))
                        ++v.reflectionOwnSentUnder; // the shading's rule for light the waves take back, no lookup's
                    else if (own.valid) {
                        const glm::dvec3 Y = own.reflected.hit ? own.reflected.point : own.Rr;
                        const bool shown = texel(e.reflectionMVP, osg::Vec4d(Y.x, Y.y, Y.z, own.reflected.hit ? 1.0 : 0.0),
                                                 e.reflectionSize, ownHit) && onTexture(ownHit, e.reflectionSize) &&
                                           reflectionPassShows(scene, e.level, glm::dvec3(e.eye.x(), e.eye.y(), e.eye.z()),
                                                               e.eyeBelow, own.reflected, own.Rr);
                        if (shown) v.reflectionOwnShownTexels.push_back(float((est - ownHit).length()));
                        else ++v.reflectionOwnNotShown;
                    }
                }
            }
            if (!e.bottom.valid()) continue;
            const bool tirRef = r.flags & PixelRef::TIR, tirEst = b.w() < -1.5f;
            if (tirRef != tirEst) { ++v.tirMismatch; continue; }
            if (tirRef || !(r.flags & PixelRef::REFRACTED_HIT)) continue;
            glm::dvec3 S;
            if (!shownPoint(b, e, scene, S)) { ++v.misses; continue; }
            const glm::dvec3 d = S - glm::dvec3(r.X);
            v.refractionM.push_back(float(glm::length(d)));
            if (r.flags & PixelRef::JACOBIAN) {
                const glm::dvec2 p(glm::dot(glm::dvec3(r.pixelsPerMetre[0]), d), glm::dot(glm::dvec3(r.pixelsPerMetre[1]), d));
                const float errPx = float(glm::length(p));
                v.refractionPx.push_back(errPx);
                v.refractionFanPx.push_back(r.refractionFan);
                v.refractionBeyondFanPx.push_back(std::max(0.0f, errPx - r.refractionFan));
                if (errPx > 2.0f)
                    ++v.refractionCauses[int(refractionCause(e, scene, glm::dvec3(r.X), S, errPx, r.refractionFan, shadedOffM))];
                if (own.valid && !own.tir && own.refracted.hit) {
                    const glm::dvec3 o = S - own.refracted.point;
                    const float ownPx = float(glm::length(glm::dvec2(glm::dot(glm::dvec3(r.pixelsPerMetre[0]), o),
                                                                     glm::dot(glm::dvec3(r.pixelsPerMetre[1]), o))));
                    v.refractionOwnPx.push_back(ownPx);
                    if (ownPx > 2.0f)
                        ++v.refractionOwnCauses[int(refractionCause(e, scene, own.refracted.point, S, ownPx, 0.0f, -1.0f))];
                }
            }
        }
    return v;
}

RefractionCause refractionCause(const Estimate& e, const RayCaster& scene, const glm::dvec3& exact,
                                const glm::dvec3& shown, float errPx, float fanPx, float shadedOffM)
{
    if (errPx <= fanPx) return CAUSE_WITHIN_FAN;
    if (shadedOffM > 0.02f) return CAUSE_SHADED_POINT;
    const glm::dvec3 C = refractionEye(e), toX = exact - C;
    // what lies on the other side of the pass's clip plane hides nothing
    double t0;
    if (entersPassSide(e, toX, t0) && t0 < 1.0 && scene.intersect(C, toX, t0, 1.0 - 1e-6).hit) return CAUSE_HIDDEN;
    // the shown point's distance from the pass's eye against the exact hit's
    return glm::length(shown - C) < glm::length(toX) ? CAUSE_IN_FRONT : CAUSE_BEHIND;
}

std::vector<float> drawnSurfaceError(const Estimate& e, const osgWater::WaterSurface& surface, double t)
{
    std::vector<float> out;
    if (!e.drawn.valid() || !surface.usesGrid()) return out;
    for (int y = 0; y < e.drawn->t(); ++y)
        for (int x = 0; x < e.drawn->s(); ++x) {
            const osg::Vec4f d = px(e.drawn.get(), x, y);
            if (!(d.w() > 1.5f && d.w() < 2.5f) || !std::isfinite(d.x() + d.y() + d.z())) continue;
            const osg::Vec3d drawn(d.x(), d.y(), d.z()), exact(d.x(), d.y(), surface.height(d.x(), d.y(), t));
            const osg::Vec3d a = drawn - e.eye, b = exact - e.eye;
            out.push_back(float(std::atan2((a ^ b).length(), a * b) * e.pixelsPerRadian));
        }
    return out;
}

CausticsErrors measureCaustics(const PhotonImage& ref, const osg::Image* img, int block)
{
    CausticsErrors c;
    if (!img || img->s() != ref.resolution || img->t() != ref.resolution || block < 1) return c;
    const int n = ref.resolution / block;
    double sumSq = 0.0, sumRef = 0.0, sumGpu = 0.0, noise = 0.0;
    size_t count = 0;
    const bool halves = ref.half[0].size() == ref.value.size() && ref.half[1].size() == ref.value.size();
    for (int by = 0; by < n; ++by)
        for (int bx = 0; bx < n; ++bx) {
            double r = 0.0, g = 0.0, h[2] = { 0.0, 0.0 };
            for (int y = by * block; y < (by + 1) * block; ++y)
                for (int x = bx * block; x < (bx + 1) * block; ++x) {
                    const size_t i = size_t(y) * ref.resolution + x;
                    r += ref.value[i];
                    g += px(img, x, y).x();
                    if (halves) {
                        h[0] += ref.half[0][i];
                        h[1] += ref.half[1][i];
                    }
                }
            r /= block * block;
            g /= block * block;
            if (!(r > 0.0) && !(g > 0.0)) continue;
            if (!std::isfinite(g)) g = 1e9;
            sumSq += (g - r) * (g - r);
            sumRef += r;
            sumGpu += g;
            // the mean of two independent halves A, B: its error's variance is that of (A - B) / 2
            const double d = (h[0] - h[1]) / (2.0 * block * block);
            noise += d * d;
            ++count;
        }
    if (!count || !(sumRef > 0.0)) return c;
    c.valid = true;
    c.meanReference = sumRef / count;
    c.meanRendered = sumGpu / count;
    c.relativeRmse = std::sqrt(sumSq / count) / c.meanReference;
    if (halves) c.referenceNoise = std::sqrt(noise / count) / c.meanReference;
    return c;
}

}
