#include "optics/Optics.h"
#include <algorithm>
#include <cmath>

namespace osgWater { namespace optics {

glm::vec3 safeNormalize(const glm::vec3& v, const glm::vec3& fallback)
{
    const float l2 = glm::dot(v, v);
    return (l2 > 1.0e-20f && std::isfinite(l2)) ? v / std::sqrt(l2) : fallback;
}

glm::vec3 refract(const glm::vec3& I, const glm::vec3& N, float eta)
{
    const float d = glm::dot(N, I);
    const float k = 1.0f - eta * eta * (1.0f - d * d);
    if (k < 0.0f) return glm::vec3(0.0f);
    return eta * I - (eta * d + std::sqrt(k)) * N;
}

glm::vec3 reflect(const glm::vec3& I, const glm::vec3& N) { return I - 2.0f * glm::dot(N, I) * N; }

bool totalInternalReflection(float cosI, float n1, float n2)
{
    const float eta = n1 / n2;
    return 1.0f - eta * eta * (1.0f - cosI * cosI) < 0.0f;
}

float criticalAngle(float n1, float n2)
{
    return n1 > n2 ? std::asin(n2 / n1) : float(M_PI_2);
}

glm::vec3 faceNormal(const glm::vec3& N, const glm::vec3& E, float minCos)
{
    const float c = glm::dot(N, E);
    if (c >= minCos) return N;
    return safeNormalize(N + (minCos - c) * E, E);
}

float normalReflectance(float n1, float n2)
{
    const float r = (n1 - n2) / (n1 + n2);
    return r * r;
}

float fresnelSchlick(float cosE, float f, float q)
{
    const float c = 1.0f - std::min(std::max(cosE, 0.0f), 1.0f);
    return f + (1.0f - f) * std::pow(c, q);
}

float fresnelPower(float cosE, float q)
{
    return std::pow(1.0f - std::min(std::max(cosE, 0.0f), 1.0f), q);
}

float fresnelReciprocal(float cosE, float p)
{
    return 1.0f / std::pow(1.0f + std::min(std::max(cosE, 0.0f), 1.0f), p);
}

FitError reciprocalFresnelError(double p, float n1, float n2, int samples)
{
    FitError e;
    samples = std::max(samples, 1);
    for (int i = 0; i <= samples; ++i) {
        const double angle = 0.5 * 3.14159265358979323846 * i / samples;
        const float c = float(std::cos(angle));
        const double d = std::fabs(double(fresnelReciprocal(c, float(p))) - fresnelExact(c, n1, n2));
        e.max = std::max(e.max, d);
        e.rms += d * d;
    }
    e.rms = std::sqrt(e.rms / (samples + 1));
    return e;
}

double bestReciprocalPower(float n1, float n2, bool leastMax)
{
    double best = 1.0, bestError = 1e30;
    for (int k = 100; k <= 3200; ++k) {
        const FitError e = reciprocalFresnelError(k / 100.0, n1, n2);
        const double v = leastMax ? e.max : e.rms;
        if (v < bestError) {
            bestError = v;
            best = k / 100.0;
        }
    }
    return best;
}

float fresnelExact(float cosI, float n1, float n2)
{
    const float ci = std::min(std::max(cosI, 0.0f), 1.0f);
    const float eta = n1 / n2;
    const float s2 = eta * eta * (1.0f - ci * ci);
    if (s2 >= 1.0f) return 1.0f;
    const float ct = std::sqrt(1.0f - s2);
    const float rs = (n1 * ci - n2 * ct) / std::max(n1 * ci + n2 * ct, 1.0e-12f);
    const float rp = (n1 * ct - n2 * ci) / std::max(n1 * ct + n2 * ci, 1.0e-12f);
    return 0.5f * (rs * rs + rp * rp);
}

float fresnelModel(int model, float cosE, float n1, float n2, float q)
{
    if (model == 3) return fresnelReciprocal(cosE, q);
    if (model == 2) return fresnelExact(cosE, n1, n2);
    if (model == 1) return fresnelPower(cosE, q);
    return fresnelSchlick(cosE, normalReflectance(n1, n2), q);
}

float smithLambda(float tanUp, float s)
{
    const double nu = std::max(double(tanUp), 1e-6) / (std::sqrt(2.0) * double(s));
    return float(std::max(0.5 * (std::exp(-nu * nu) / (nu * std::sqrt(3.14159265358979)) - std::erfc(nu)), 0.0));
}

glm::vec4 fresnelAndLean(int model, float cosE, float sinMirror, float roughness, float n1, float n2, float q)
{
    const float s = std::sqrt(std::max(0.5f * roughness, 1.0e-12f));
    const float c = std::min(std::max(cosE, 0.0f), 1.0f);
    const float sinE = std::sqrt(std::max(1.0f - c * c, 0.0f));
    const float lo = -3.0f * s, hi = std::min(3.0f * s, c / std::max(sinE, 1.0e-6f));
    // the level's up in the pixel's frame (z its normal, the eye towards -y), from the mirror ray's
    // elevation e; the eye's elevation's sine; tan(e / 2), beyond which facets send their rays under
    const float sinUp = std::min(std::max(sinMirror, -1.0f), 1.0f), cosUp = std::sqrt(1.0f - sinUp * sinUp);
    const float upY = sinUp * sinE - cosUp * c, upZ = sinUp * c + cosUp * sinE;
    const float eyeUp = c * upZ - sinE * upY;
    const float under = std::min(std::max(sinUp / (1.0f + cosUp), lo), hi);
    const float across = 1.0f + 0.5f * roughness; // the slopes across the plane, at their mean square
    // four nodes over the rising facets, two over the ones sent under: none straddles the kink
    const float node[6] = { -0.8611363116f, -0.3399810436f, 0.3399810436f, 0.8611363116f, -0.5773502692f, 0.5773502692f };
    const float weight[6] = { 0.3478548451f, 0.6521451549f, 0.6521451549f, 0.3478548451f, 1.0f, 1.0f };
    float sum = 0.0f, total = 0.0f, lean = 0.0f, lean2 = 0.0f, escapes = 0.0f;
    for (int i = 0; i < 6; ++i) {
        const bool rising = i < 4;
        const float from = rising ? lo : under, to = rising ? under : hi;
        const float a = 0.5f * (from + to) + 0.5f * (to - from) * node[i];
        const float seen = std::max(c - sinE * a, 0.0f);
        const float w = weight[i] * (to - from) * seen * std::exp(-0.5f * a * a / (s * s));
        const float wf = w * fresnelModel(model, seen / std::sqrt(across + a * a), n1, n2, q);
        sum += wf;
        total += w;
        lean -= wf * a; // a tilts away from the eye
        lean2 += wf * a * a;
        if (!rising) continue; // sent under: none of its light escapes
        // the facet's mirror ray's elevation sine (the slopes across the plane lower it too)
        const float rise = 2.0f * seen * (a * upY + upZ) / (across + a * a) - eyeUp;
        if (rise > 0.0f) escapes += wf / (1.0f + smithLambda(rise / std::sqrt(std::max(1.0f - rise * rise, 1e-12f)), s));
    }
    if (!(total > 0.0f) || !(sum > 0.0f))
        return glm::vec4(fresnelModel(model, c, n1, n2, q), 0.0f, 0.0f, sinUp < 0.0f ? 0.0f : 1.0f);
    lean /= sum;
    return glm::vec4(sum / total, lean, std::sqrt(std::max(lean2 / sum - lean * lean, 0.0f)), escapes / sum);
}

float fresnelOverSlopes(int model, float cosE, float roughness, float n1, float n2, float q)
{
    return fresnelAndLean(model, cosE, cosE, roughness, n1, n2, q).x; // the level's own mirror ray
}

FromBelow underwaterThesis(const glm::vec3& E, const glm::vec3& N, float n1, float n2, float q)
{
    FromBelow r;
    r.R = (n1 / n2) * (N - E) - N;
    r.F = fresnelSchlick(glm::dot(E, N), normalReflectance(n1, n2), q);
    return r;
}

FromBelow underwaterPhysical(const glm::vec3& E, const glm::vec3& N, float n1, float n2, int model, float q)
{
    FromBelow r;
    r.R = refract(-E, N, n1 / n2);
    r.tir = glm::dot(r.R, r.R) < 0.5f;
    if (r.tir) { r.F = 1.0f; return r; }
    const float cosT = std::min(std::max(-glm::dot(r.R, N), 0.0f), 1.0f);
    r.F = model == 2 ? fresnelExact(glm::dot(E, N), n1, n2) : fresnelModel(model, cosT, n1, n2, q);
    return r;
}

float attenuation(float k, float d)
{
    if (!(d >= 0.0f)) return 0.0f; // NaN or "no bottom"
    return std::exp(-k * d);
}

glm::vec3 attenuation(const glm::vec3& k, float d)
{
    return glm::vec3(attenuation(k.x, d), attenuation(k.y, d), attenuation(k.z, d));
}

glm::vec3 waterTint(const glm::vec3& refracted, const glm::vec3& water, float a)
{
    return water + a * (refracted - water);
}

glm::vec3 waterTint(const glm::vec3& refracted, const glm::vec3& water, const glm::vec3& a)
{
    return water + a * (refracted - water);
}

float deepWaterReflectance(float a, float bb)
{
    if (!(a >= 0.0f) || !(bb > 0.0f)) return 0.0f; // nothing scattered back (or NaN)
    const float u = bb / (a + bb);
    return 0.0001f + u * (0.3244f + u * (0.1425f + u * 0.1308f));
}

glm::vec3 fresnelMix(const glm::vec3& refracted, const glm::vec3& reflected, float F)
{
    return refracted + F * (reflected - refracted);
}

bool lineIntersection(const glm::vec3& U, const glm::vec3& R, const glm::vec3& A1, const glm::vec3& Q, glm::vec3& out)
{
    const glm::vec3 rq = glm::cross(R, Q);
    const float n = glm::dot(rq, rq);
    // relative test: |R x Q|^2 against |R|^2 |Q|^2 rejects near-parallel lines at any scale
    if (!(n > 1.0e-8f * glm::dot(R, R) * glm::dot(Q, Q))) return false;
    const float m = glm::dot(glm::cross(A1 - U, Q), rq);
    out = U + (m / n) * R;
    return true;
}

bool bottomAlongRay(const glm::vec3& P, const DepthLookup& lookup, glm::vec3& A)
{
    if (!(P.z < -1.0e-6f)) return false; // behind or on the camera plane: no texel to read
    const DepthSample s = lookup(P);
    if (!s.hit) return false;
    A = P * (s.z / P.z);
    return true;
}

BottomHit oneStepSearch(const glm::vec3& U, const glm::vec3& R, float scale, float maxDv, const DepthLookup& lookup)
{
    BottomHit r;
    glm::vec3 A1;
    if (!bottomAlongRay(U, lookup, A1)) return r;
    const float dv = std::min(std::max(scale * glm::length(A1 - U), 0.0f), maxDv);
    r.valid = true;
    r.W = U + dv * R;
    r.A = A1;
    r.error = 0.0f;
    return r;
}

SearchTolerance SearchTolerance::ofTexels(const glm::mat4& proj, int texelsHigh, float texels)
{
    // a texel's height at eye-space z is 2 w / (proj[1][1] texelsHigh), w = proj[2][3] z + proj[3][3]
    const float k = 2.0f * texels / (proj[1][1] * float(std::max(texelsHigh, 1)));
    return SearchTolerance(k * proj[3][3], k * -proj[2][3]);
}

// A lookup that counts its calls into `reads`, when there is a counter
static DepthLookup counted(const DepthLookup& lookup, int* reads)
{
    if (!reads) return lookup;
    *reads = 0;
    return [&lookup, reads](const glm::vec3& P) { ++*reads; return lookup(P); };
}

BottomHit iterativeSearch(const glm::vec3& U, const glm::vec3& R, int steps, const DepthLookup& uncounted,
                          const SearchTolerance& tolerance, int* reads, bool eyeAmongWaves)
{
    const DepthLookup lookup = counted(uncounted, reads);
    BottomHit best;
    steps = std::min(std::max(steps, 1), 8);
    glm::vec3 Aprev;
    bool seen = bottomAlongRay(U, lookup, Aprev);
    // an eye among the waves: U's own texel may show nothing (a crest ahead stands above all the
    // pass sees); step along R, doubling from a quarter of U's distance, until a point's does
    float t = 0.25f * glm::length(U);
    for (int k = 0; eyeAmongWaves && k < 10 && !seen; ++k, t *= 2.0f) seen = bottomAlongRay(U + t * R, lookup, Aprev);
    if (!seen) return best;
    // fallback: the bottom straight behind U (no refraction offset) beats no bottom at all
    best.valid = true;
    best.W = best.A = Aprev;
    best.error = INFINITY;
    glm::vec3 W = U + glm::length(Aprev - U) * R; // W_1: the one-step guess
    for (int i = 1; i <= steps; ++i) {
        glm::vec3 A;
        if (!bottomAlongRay(W, lookup, A)) { W = 0.5f * (U + W); continue; } // sky: back towards U
        const float e = glm::length(A - W);
        if (e < best.error) { best.W = W; best.A = A; best.error = e; }
        if (i == steps || e < tolerance.at(A)) break; // converged: further lookups cannot do better by much
        // W_{i+1}: where p crosses the segment A_i A_{i+1} (eq. 3) ...
        glm::vec3 Wn;
        const glm::vec3 Q = A - Aprev;
        const float lq = glm::length(Q);
        const bool ok = lineIntersection(U, R, Aprev, Q, Wn)
                        && glm::length(Wn - Aprev) + glm::length(A - Wn) <= lq * 1.001f + 1.0e-5f;
        if (!ok) {
            // ... else step |A - W| along R, back towards U when the bottom is nearer than W (fig. 11, 12)
            const float zn = std::fabs(W.z) > std::fabs(A.z) ? -1.0f : 1.0f;
            Wn = W + zn * e * R;
        }
        Aprev = A;
        W = Wn;
    }
    if (std::isinf(best.error)) best.error = 0.0f;
    return best;
}

float frustumExit(const glm::mat4& proj, const glm::vec3& P, const glm::vec3& R)
{
    const glm::vec4 a = proj * glm::vec4(P, 1.0f), b = proj * glm::vec4(R, 0.0f);
    // each side's distance, linear along the ray: w - x, w + x, w - y, w + y, and w
    const float g0[5] = { a.w - a.x, a.w + a.x, a.w - a.y, a.w + a.y, a.w };
    const float g1[5] = { b.w - b.x, b.w + b.x, b.w - b.y, b.w + b.y, b.w };
    float t = INFINITY;
    for (int i = 0; i < 5; ++i)
        if (g1[i] < 0.0f && g0[i] >= 0.0f) t = std::min(t, g0[i] / -g1[i]);
    return t;
}

BottomHit mirrorSearch(const glm::vec3& U, const glm::vec3& R, int steps, const DepthLookup& uncounted,
                       const SearchTolerance& tolerance, const glm::vec4& floorPlane, float tExit, int* reads)
{
    const DepthLookup lookup = counted(uncounted, reads);
    // a surface under the floor plane is seen as sky
    const DepthLookup aboveFloor = [&](const glm::vec3& P) {
        DepthSample s = lookup(P);
        if (s.hit && glm::dot(floorPlane, glm::vec4(P * (s.z / P.z), 1.0f)) < 0.0f) s.hit = false;
        return s;
    };
    const float sky = 1.0e30f;
    glm::vec3 A;
    float f0 = sky;
    // U's line of sight, else the camera ray through the point R (parallel to the ray): its far end
    if (bottomAlongRay(U, aboveFloor, A)) f0 = std::max(U.z - A.z, 0.0f);
    else if (!bottomAlongRay(R, aboveFloor, A)) return BottomHit();
    BottomHit best;
    best.valid = true;
    best.W = best.A = A;
    best.error = INFINITY;
    // f(t): how far U + t R lies in front of the surface on its camera ray; the hit is its first root
    float tLo = 0.0f, fLo = f0, tHi = -1.0f, fHi = 0.0f; // tHi < 0: no point behind a surface yet
    int side = 0; // the end the last candidate replaced: -1 the front one, 1 the back one
    tExit *= 0.9999f; // on the texture's edge, not a rounding past it
    float t = std::min(std::max(glm::length(A - U), 1.0e-3f), tExit);
    steps = std::min(std::max(steps, 1), 8);
    for (int i = 1; i <= steps; ++i) {
        const glm::vec3 W = U + t * R;
        float f = sky;
        if (bottomAlongRay(W, aboveFloor, A)) {
            f = W.z - A.z;
            const float e = glm::length(A - W);
            if (e < best.error) { best.W = W; best.A = A; best.error = e; }
            if (e < tolerance.at(A)) break;
        }
        const float tPrev = tLo, fPrev = fLo;
        // Illinois: an end kept twice in a row has its value halved, so the other end moves too
        if (f > 0.0f) { tLo = t; fLo = f; if (side < 0) fHi *= 0.5f; side = -1; }
        else { tHi = t; fHi = f; if (side > 0 && fLo < 1.0e29f) fLo *= 0.5f; side = 1; }
        if (tHi < 0.0f) { // still in front: the secant on the last two points, at most 4x further
            if (t >= tExit) break; // in front where it leaves the texture: it meets nothing the pass drew
            t = std::min(fPrev > f && fPrev < 1.0e29f ? std::min(t + (t - tPrev) * f / (fPrev - f), 4.0f * t) : 2.0f * t,
                         tExit);
        } else // bracketed: regula falsi (bisection next to the sky)
            t = fLo < 1.0e29f ? tLo + (tHi - tLo) * fLo / (fLo - fHi) : 0.5f * (tLo + tHi);
    }
    if (best.error <= tolerance.at(best.A) + 0.01f * glm::length(best.W - U)) return best;
    if (tHi < 0.0f) return BottomHit(); // every candidate in front: the ray went on past everything
    best.W = best.A = U + t * R; // the root's best estimate in its bracket
    best.error = 0.0f;
    return best;
}

bool intersectPlaneZ(const glm::vec3& U, const glm::vec3& R, float planeZ, glm::vec3& hit)
{
    if (std::fabs(R.z) < 1.0e-12f) return false;
    const float t = (planeZ - U.z) / R.z;
    if (!(t > 0.0f)) return false;
    hit = U + t * R;
    return true;
}

} }
