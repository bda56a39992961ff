// Optics of the water shader. Mirrored line by line in osgWater/optics/Optics.cpp (same names, same
// guards); tests hold both to the same numbers. Robust by construction: refract() returns 0 under
// total internal reflection (a mask, never normalised), every division is guarded, depth 1.0 is
// sky (a miss, not a bottom).
#pragma include "contract.glsl"

vec3 owSafeNormalize(vec3 v, vec3 fallback)
{
    float l2 = dot(v, v);
    return l2 > 1e-20 ? v * inversesqrt(l2) : fallback;
}

// Bends N towards E so that E.N >= minCos (wave normals facing away from a grazing eye).
vec3 owFaceNormal(vec3 N, vec3 E, float minCos)
{
    float c = dot(N, E);
    return c >= minCos ? N : owSafeNormalize(N + (minCos - c) * E, E);
}

float owFresnelSchlick(float cosE, float f, float q)
{
    return f + (1.0 - f) * pow(1.0 - clamp(cosE, 0.0, 1.0), q);
}

float owFresnelPower(float cosE, float q)
{
    return pow(1.0 - clamp(cosE, 0.0, 1.0), q);
}

// DeepWater's reciprocal power: 1 at grazing incidence, 2^-p at normal incidence
float owFresnelReciprocal(float cosE, float p)
{
    return 1.0 / pow(1.0 + clamp(cosE, 0.0, 1.0), p);
}

float owFresnelExact(float cosI, float n1, float n2)
{
    float ci = clamp(cosI, 0.0, 1.0);
    float eta = n1 / n2;
    float s2 = eta * eta * (1.0 - ci * ci);
    if (s2 >= 1.0) return 1.0;
    float ct = sqrt(1.0 - s2);
    float rs = (n1 * ci - n2 * ct) / max(n1 * ci + n2 * ct, 1e-12);
    float rp = (n1 * ct - n2 * ci) / max(n1 * ct + n2 * ci, 1e-12);
    return 0.5 * (rs * rs + rp * rp);
}

// The Fresnel model chosen by OSGWATER_FRESNEL (WaterSettings::FresnelModel: 0 Schlick eq. 7-8,
// 1 power, 2 exact, 3 reciprocal power); q: the model's exponent. The includer lists
// OSGWATER_FRESNEL in its import_defines.
float owFresnel(float cosE, float n1, float n2, float q)
{
#if defined(OSGWATER_FRESNEL) && OSGWATER_FRESNEL == OSGWATER_FRESNEL_RECIPROCAL
    return owFresnelReciprocal(cosE, q);
#elif defined(OSGWATER_FRESNEL) && OSGWATER_FRESNEL == OSGWATER_FRESNEL_EXACT
    return owFresnelExact(cosE, n1, n2);
#elif defined(OSGWATER_FRESNEL) && OSGWATER_FRESNEL == OSGWATER_FRESNEL_POWER
    return owFresnelPower(cosE, q);
#else
    float r = (n1 - n2) / (n1 + n2);
    return owFresnelSchlick(cosE, r * r, q);
#endif
}

// Smith's Lambda for Gaussian slopes of deviation s along the way a ray leaves, tanUp the tangent
// of its elevation above the level (> 0): a wave ahead meets the ray from a share Lambda / (1 + Lambda)
// of its starting points. erfc from Abramowitz and Stegun's 7.1.26 (within 1.5e-7), which carries the
// exp(-nu^2) the first term has too.
float owSmithLambda(float tanUp, float s)
{
    float nu = max(tanUp, 1e-6) / (1.41421356 * s);
    float t = 1.0 / (1.0 + 0.3275911 * nu);
    float erfcOverGauss = ((((1.061405429 * t - 1.453152027) * t + 1.421413741) * t - 0.284496736) * t + 0.254829592) * t;
    return max(0.5 * exp(-nu * nu) * (0.56418958 / nu - erfcOverGauss), 0.0);
}

// The reflectance of a pixel whose normal hides slopes of variance `roughness` (their mean
// |grad h|^2, alike every way), with where its reflected light comes from and how much of it leaves
// the waves: (F, lean, deviation, escapes).
// - F: owFresnel averaged over the facets the eye sees, each weighted by its area seen from the eye
//   (Smith's visible normals: masking does not depend on a facet's slope, only facets turned away
//   are hidden). Along the plane of incidence a slope a tilts the facet towards or away from the
//   eye: its seen area per unit of level is cosE - sinE a, its cosine that over sqrt(1 + a^2 + b^2).
//   Across the plane, b only shortens that, taken at its mean square. At grazing under a breeze
//   (0.029) F falls from 1 to about 0.45, as Bruneton, Neyret and Holzschuch's mean Fresnel (2010);
//   facing the water it hardly moves.
// - lean, deviation: the mean slope towards the eye of the seen facets weighted by the light each
//   reflects, and its deviation. Facets tilted towards the eye show more area and the ones tilted
//   far away hide, so the seen facets lean towards the eye and their mirror rays rise by twice the
//   lean; but the most tilted reflect least, so the light's mean lean is the F-weighted one. At
//   grazing under a breeze the reflection comes from sky a few tenths of a radian above the mean
//   normal's mirror ray, as every ray of the exact reference finds.
// - escapes: the share of that light whose mirror rays leave the waves. A facet tilted away by a
//   turns its mirror ray (elevation e above the level, sinMirror its sine) down by 2 atan(a): beyond
//   tan(e / 2) the ray goes back under the level (the slopes across the plane turn it a little
//   lower, taken at their mean square); below, it rises, and a wave ahead still meets it from Smith's
//   share Lambda / (1 + Lambda) of the facets. Where the eye grazes, the facets that reflect most
//   are the least tilted, and their rays rise lowest: under a breeze a sixth of far water's
//   reflected light meets the next wave (the exact reference's rays agree). That light passes
//   mostly into the water: the caller shows it as the water's own.
// Gauss-Legendre in four nodes over the rising facets (from -3 deviations to tan(e / 2)) and two over
// the ones sent under (to where the facets turn away), so that no node straddles the kink: within
// 0.007 of the full integrals over both slopes for F, 0.15 deviations for the lean, 0.03 for the
// escaping share (tests). Mirrored in osgWater::optics::fresnelAndLean.
vec4 owFresnelAndLean(float cosE, float sinMirror, float roughness, float n1, float n2, float q)
{
    float s = sqrt(max(0.5 * roughness, 1e-12)); // the slopes' deviation along the plane
    float c = clamp(cosE, 0.0, 1.0);
    float sinE = sqrt(max(1.0 - c * c, 0.0));
    float lo = -3.0 * s, hi = min(3.0 * s, c / max(sinE, 1e-6));
    // the level's up in the pixel's frame (z its normal, the eye towards -y), from the mirror ray's
    // elevation e; the eye's own elevation's sine; tan(e / 2), where facets start sending rays under
    float sinUp = clamp(sinMirror, -1.0, 1.0), cosUp = sqrt(1.0 - sinUp * sinUp);
    float upY = sinUp * sinE - cosUp * c, upZ = sinUp * c + cosUp * sinE;
    float eyeUp = c * upZ - sinE * upY;
    float under = clamp(sinUp / (1.0 + cosUp), lo, hi);
    float across = 1.0 + 0.5 * roughness; // the slopes across the plane, at their mean square
    const vec4 node = vec4(-0.8611363116, -0.3399810436, 0.3399810436, 0.8611363116);
    const vec4 weight = vec4(0.3478548451, 0.6521451549, 0.6521451549, 0.3478548451);
    float sum = 0.0, total = 0.0, lean = 0.0, lean2 = 0.0, escapes = 0.0;
    for (int i = 0; i < 6; ++i) {
        bool rising = i < 4;
        float from = rising ? lo : under, to = rising ? under : hi;
        float x = rising ? node[i] : (i == 4 ? -0.5773502692 : 0.5773502692);
        float a = 0.5 * (from + to) + 0.5 * (to - from) * x;
        float seen = max(c - sinE * a, 0.0);
        float w = (rising ? weight[i] : 1.0) * (to - from) * seen * exp(-0.5 * a * a / (s * s));
        float wf = w * owFresnel(seen * inversesqrt(across + a * a), n1, n2, q);
        sum += wf;
        total += w;
        lean -= wf * a; // a tilts away from the eye
        lean2 += wf * a * a;
        if (!rising) continue; // sent under: none of its light escapes
        // the facet's mirror ray's elevation sine: the slopes across the plane lower it too
        float rise = 2.0 * seen * (a * upY + upZ) / (across + a * a) - eyeUp;
        if (rise > 0.0) escapes += wf / (1.0 + owSmithLambda(rise * inversesqrt(max(1.0 - rise * rise, 1e-12)), s));
    }
    if (!(total > 0.0) || !(sum > 0.0)) return vec4(owFresnel(c, n1, n2, q), 0.0, 0.0, sinUp < 0.0 ? 0.0 : 1.0);
    lean /= sum;
    return vec4(sum / total, lean, sqrt(max(lean2 / sum - lean * lean, 0.0)), escapes / sum);
}

// eq. 4; d < 0 means "no bottom along the ray"
float owAttenuation(float k, float d)
{
    return d >= 0.0 ? exp(-k * d) : 0.0;
}

// eq. 4 per channel
vec3 owAttenuation(vec3 k, float d)
{
    return d >= 0.0 ? exp(-k * d) : vec3(0.0);
}

// eq. 3: the point on U + t R where it meets the line A1 + s Q; false for near-parallel lines
bool owLineIntersection(vec3 U, vec3 R, vec3 A1, vec3 Q, out vec3 W)
{
    vec3 rq = cross(R, Q);
    float n = dot(rq, rq);
    W = U;
    if (!(n > 1e-8 * dot(R, R) * dot(Q, Q))) return false;
    W = U + (dot(cross(A1 - U, Q), rq) / n) * R;
    return true;
}

// --- a pass's depth texture, read in that pass's eye space --------------------------------
// The searches take the pass as its depth texture and an owDepthPass: the refraction pass (the
// bottom search), the reflection pass (the mirror search) and the sun's camera (photons).
struct owDepthPass {
    mat4 proj;
    vec4 floorPlane;     // eye space: a surface with dot(floorPlane, A) < 0 does not count (seen as sky)
    bool offTextureSky;  // a point off the texture sees sky (else the texture's edge answers for it)
};

// texture coordinate of an eye-space point of a pass; false behind the camera
bool owPassTexCoord(mat4 proj, vec3 P, out vec2 tc)
{
    vec4 c = proj * vec4(P, 1.0);
    tc = vec2(0.5);
    if (!(c.w > 1e-6)) return false;
    tc = c.xy / c.w * 0.5 + 0.5;
    return true;
}

// The eye-space z of what a pass's depth target holds at depth d: the projection's z and w rows do
// not depend on x and y (perspective, frustum, ortho), so z_ndc = (P22 z + P32) / (P23 z + P33)
// solved for z (a sixth of the inverse projection's product, on every depth read of a search)
float owPassEyeZ(owDepthPass pass, float d)
{
    mat4 P = pass.proj;
    float zn = 2.0 * d - 1.0;
    return (P[3][2] - zn * P[3][3]) / (zn * P[2][3] - P[2][2]);
}

// How many depth reads the searches made on this fragment (the work debug output counts them)
int owDepthReads = 0;

// How close a search's candidate must come to the surface point A it sees for the pass's camera to
// see them at most `texels` apart (the settings' ErrorBudget): that many of the texels' heights at
// A's depth, which grow with the distance for a perspective camera and not for an orthographic one.
// Made once a search, as (metres, metres per metre of depth); owToleranceAt reads it at A.
// Mirrored in osgWater::optics::SearchTolerance.
vec2 owTexelTolerance(mat4 proj, sampler2D depthTex, float texels)
{
    // a texel's height at eye-space z: 2 w / (P11 height), w = P23 z + P33
    float k = texels * 2.0 / (proj[1][1] * float(textureSize(depthTex, 0).y));
    return k * vec2(proj[3][3], -proj[2][3]);
}

float owToleranceAt(vec2 tolerance, vec3 A)
{
    return tolerance.x - tolerance.y * A.z;
}

// A: the first surface on the pass camera's ray through P; false for sky (the cleared depth), a
// surface under the pass's floor plane, or a point off the texture where the pass says so. Camera
// rays meet at the eye (A = P Z / P.z), or are parallel to -Z when the includer defines
// OSGWATER_ORTHO_DEPTH (the sun's orthographic camera of the caustics pass: A = (P.xy, Z)).
bool owSurfaceAlongRay(sampler2D depthTex, owDepthPass pass, vec3 P, out vec3 A)
{
    A = P;
    vec2 tc;
    if (!(P.z < -1e-6) || !owPassTexCoord(pass.proj, P, tc)) return false;
    if (pass.offTextureSky && !(all(greaterThanEqual(tc, vec2(0.0))) && all(lessThanEqual(tc, vec2(1.0)))))
        return false;
    float d = texture(depthTex, tc).r;
    ++owDepthReads;
    // only the cleared depth is sky: a sky dome drawn just inside the far plane is a surface
    if (d >= 1.0) return false;
    float Z = owPassEyeZ(pass, d);
#ifdef OSGWATER_ORTHO_DEPTH
    A = vec3(P.xy, Z);
#else
    A = P * (Z / P.z);
#endif
    return dot(pass.floorPlane, vec4(A, 1.0)) >= 0.0;
}

struct owBottomHit { bool valid; vec3 W; vec3 A; float error; };

// How far the ray P + t R (eye space of a pass) stays on the pass's texture: the largest t whose
// point lies inside the frustum's four sides and in front of the camera (1e30: it never leaves).
// Mirrored in osgWater::optics::frustumExit.
float owFrustumExit(mat4 proj, vec3 P, vec3 R)
{
    vec4 a = proj * vec4(P, 1.0), b = proj * vec4(R, 0.0);
    // each side's distance, linear along the ray: w - x, w + x, w - y, w + y, and w
    float g0[5] = float[5](a.w - a.x, a.w + a.x, a.w - a.y, a.w + a.y, a.w);
    float g1[5] = float[5](b.w - b.x, b.w + b.x, b.w - b.y, b.w + b.y, b.w);
    float t = 1e30;
    for (int i = 0; i < 5; ++i)
        if (g1[i] < 0.0 && g0[i] >= 0.0) t = min(t, g0[i] / -g1[i]);
    return t;
}

// The loop's static bound is the search steps' define (the includer imports OSGWATER_SEARCH_STEPS):
// a software rasteriser pays for a loop up to its static bound more than for a uniform's count.
#ifndef OSGWATER_SEARCH_STEPS
#define OSGWATER_SEARCH_STEPS 8
#endif

// The reflected ray U + t R (t > 0) in the reflection pass's eye space, where the mirrored scene
// lies: its hit. Invalid: the ray meets nothing the pass drew (the sky, or open water under water):
// the caller looks it up by its direction. Mirrored in osgWater::optics::mirrorSearch.
// f(t): how far the ray's point W(t) lies in front of the surface on its camera ray (eye-space z;
// sky: in front of everything). f(0) >= 0, and the hit is the first root. The candidates go out
// from t_1 = |A_1 - U| (the thesis's first guess) by secant steps on f until one lies behind a
// surface, then close in on the root by regula falsi (Illinois) between the last point in front
// and the first behind. The pass's floor plane: the ray leaves U away from the water, so what lies
// behind U's height is no hit (the pass keeps a band beyond the level for the crests: a shore under
// the troughs would hide the ray's true hit). Off the texture the pass sees nothing. Where U's own
// line of sight sees no surface, t_1 comes from what the pass sees along R from its eye (the ray's
// far end), and there is none when that sees none either. Where the pass's texture ends, so does
// the search: the candidates go no further than where the ray leaves it. No candidate within
// `budget` (texels, owTexelTolerance) + 1% of its distance: the root's estimate in its bracket when
// there is one, else the ray went on past everything: none.
owBottomHit owMirrorSearch(sampler2D depthTex, owDepthPass pass, vec3 U, vec3 R, int steps, float budget)
{
    owBottomHit none = owBottomHit(false, U, U, 0.0);
    vec3 A;
    float f0 = 1e30;
    if (owSurfaceAlongRay(depthTex, pass, U, A)) f0 = max(U.z - A.z, 0.0);
    else if (!owSurfaceAlongRay(depthTex, pass, R, A)) return none;
    owBottomHit best = owBottomHit(true, A, A, 1e30);
    vec2 tolerance = owTexelTolerance(pass.proj, depthTex, budget);
    float tLo = 0.0, fLo = f0, tHi = -1.0, fHi = 0.0; // tHi < 0: no point behind a surface yet
    int side = 0; // the end the last candidate replaced: -1 the front one, 1 the back one
    // the candidates stay on the texture: one past its edge sees sky, and the search would step on
    // past a hit it had not bracketed yet (a far sky dome near the texture's edge)
    float tExit = pass.offTextureSky ? 0.9999 * owFrustumExit(pass.proj, U, R) : 1e30;
    float t = min(max(length(A - U), 1e-3), tExit);
    for (int i = 1; i <= OSGWATER_SEARCH_STEPS; ++i) {
        if (i > steps) break;
        vec3 W = U + t * R;
        float f = 1e30;
        if (owSurfaceAlongRay(depthTex, pass, W, A)) {
            f = W.z - A.z;
            float e = length(A - W);
            if (e < best.error) { best.W = W; best.A = A; best.error = e; }
            if (e < owToleranceAt(tolerance, A)) break;
        }
        float tPrev = tLo, fPrev = fLo;
        // Illinois: an end kept twice in a row has its value halved, so the other end moves too
        if (f > 0.0) { tLo = t; fLo = f; if (side < 0) fHi *= 0.5; side = -1; }
        else { tHi = t; fHi = f; if (side > 0 && fLo < 1e29) fLo *= 0.5; side = 1; }
        if (tHi < 0.0) { // still in front: the secant on the last two points, at most 4x further
            if (t >= tExit) break; // in front where it leaves the texture: it meets nothing the pass drew
            t = min(fPrev > f && fPrev < 1e29 ? min(t + (t - tPrev) * f / (fPrev - f), 4.0 * t) : 2.0 * t, tExit);
        } else // bracketed: regula falsi (bisection next to the sky)
            t = fLo < 1e29 ? tLo + (tHi - tLo) * fLo / (fLo - fHi) : 0.5 * (tLo + tHi);
    }
    if (best.error <= owToleranceAt(tolerance, best.A) + 0.01 * length(best.W - U)) return best;
    if (tHi < 0.0) return none;
    best.W = U + t * R; // the root's best estimate in its bracket
    best.A = best.W;
    best.error = 0.0;
    return best;
}

// --- the refraction pass ------------------------------------------------------------------
uniform sampler2D osgWater_RefractionDepth;
uniform mat4 osgWater_RefractionProj;
uniform mat4 osgWater_RefractionInvProj;

owDepthPass owRefractionPass()
{
    return owDepthPass(osgWater_RefractionProj, vec4(0.0, 0.0, 0.0, 1.0), false);
}

bool owRefractionTexCoord(vec3 P, out vec2 tc)
{
    return owPassTexCoord(osgWater_RefractionProj, P, tc);
}

bool owBottomAlongRay(vec3 P, out vec3 A)
{
    return owSurfaceAlongRay(osgWater_RefractionDepth, owRefractionPass(), P, A);
}

// SCCG 2008 eq. 1: W = U + clamp(scale dv, 0, maxDv) R
owBottomHit owOneStepSearch(vec3 U, vec3 R, float scale, float maxDv)
{
    owBottomHit r = owBottomHit(false, U, U, 0.0);
    vec3 A1;
    if (!owBottomAlongRay(U, A1)) return r;
    float dv = clamp(scale * length(A1 - U), 0.0, maxDv);
    r.valid = true;
    r.W = U + dv * R;
    r.A = A1;
    return r;
}

// Thesis §7.1: candidates W_1..W_steps, keep the one with the smallest |A - W|; stop early once
// a candidate is within `budget` texels of its bottom point (owTexelTolerance).
// A candidate whose camera ray sees sky (it went under a clipped shore, or off the texture) is
// no bottom: the next candidate is half way back towards U. If no candidate sees a bottom, A_1
// (the bottom straight behind U, no refraction offset) is the answer: better than none.
// Mirrored in osgWater::optics::iterativeSearch.
owBottomHit owIterativeSearch(vec3 U, vec3 R, int steps, float budget)
{
    owBottomHit best = owBottomHit(false, U, U, 0.0);
    vec3 Aprev;
    bool seen = owBottomAlongRay(U, Aprev);
#ifdef OSGWATER_EYE_AMONG_WAVES
    // An eye within the waves' height of the level: U's own texel may show nothing behind it, a crest
    // ahead standing above everything the pass (its camera at the eye, the scene beyond the level)
    // sees. The refracted ray goes on into what it sees: step along it, doubling from a quarter of
    // U's distance, until a point's texel shows something. Only such eyes compile these reads.
    float t = 0.25 * length(U);
    for (int k = 0; k < 10 && !seen; ++k, t *= 2.0) seen = owBottomAlongRay(U + t * R, Aprev);
#endif
    if (!seen) return best;
    best = owBottomHit(true, Aprev, Aprev, 1e30);
    vec2 tolerance = owTexelTolerance(osgWater_RefractionProj, osgWater_RefractionDepth, budget);
    vec3 W = U + length(Aprev - U) * R;
    for (int i = 1; i <= OSGWATER_SEARCH_STEPS; ++i) {
        if (i > steps) break;
        vec3 A;
        if (!owBottomAlongRay(W, A)) { W = 0.5 * (U + W); continue; }
        float e = length(A - W);
        if (e < best.error) { best.W = W; best.A = A; best.error = e; }
        if (i == steps || e < owToleranceAt(tolerance, A)) break; // converged: saves the remaining lookups
        vec3 Wn;
        vec3 Q = A - Aprev;
        bool ok = owLineIntersection(U, R, Aprev, Q, Wn)
               && length(Wn - Aprev) + length(A - Wn) <= length(Q) * 1.001 + 1e-5;
        if (!ok) {
            float zn = abs(W.z) > abs(A.z) ? -1.0 : 1.0;
            Wn = W + zn * e * R;
        }
        Aprev = A;
        W = Wn;
    }
    if (best.error > 1e29) best.error = 0.0;
    return best;
}

// A depth map read between its four texels around tc (the maps are filtered to the nearest texel: a
// sloping surface read there moves by up to half a texel's rise); next to a texel the map leaves
// clear (1: nothing there), the nearest texel.
float owDepthBetweenTexels(sampler2D map, vec2 tc)
{
    vec2 size = vec2(textureSize(map, 0));
    vec2 at = tc * size - 0.5, f = fract(at);
    ivec2 i = ivec2(floor(at)), hi = ivec2(size) - 1;
    vec4 d = vec4(texelFetch(map, clamp(i, ivec2(0), hi), 0).r,
                  texelFetch(map, clamp(i + ivec2(1, 0), ivec2(0), hi), 0).r,
                  texelFetch(map, clamp(i + ivec2(0, 1), ivec2(0), hi), 0).r,
                  texelFetch(map, clamp(i + ivec2(1, 1), ivec2(0), hi), 0).r);
    return max(max(d.x, d.y), max(d.z, d.w)) >= 1.0 ? texture(map, tc).r
                                                    : mix(mix(d.x, d.y, f.x), mix(d.z, d.w, f.x), f.y);
}
