/* osgWater - natural water for OpenSceneGraph */
#ifndef OSGWATER_OPTICS
#define OSGWATER_OPTICS 1

#include <osgWater/Export>
#include <glm/glm.hpp>
#include <cmath>
#include <functional>

//! CPU mirror of the maths in shaders/optics.glsl (same names, same guards), so tests and the
//! benchmark can hold the GPU to closed forms and explain its errors.
namespace osgWater { namespace optics {

//! Normalise, or return `fallback` for a (near) zero-length vector.
OSGWATER_EXPORT glm::vec3 safeNormalize(const glm::vec3& v, const glm::vec3& fallback);

//! GLSL refract(): I incident (unit), N unit normal facing against I, eta = n1/n2.
//! Returns the zero vector under total internal reflection.
OSGWATER_EXPORT glm::vec3 refract(const glm::vec3& I, const glm::vec3& N, float eta);
//! GLSL reflect().
OSGWATER_EXPORT glm::vec3 reflect(const glm::vec3& I, const glm::vec3& N);
//! True when a ray at cosine cosI to the normal is totally reflected going from n1 into n2.
OSGWATER_EXPORT bool totalInternalReflection(float cosI, float n1, float n2);
//! Critical angle (radians) going from n1 into n2 > ... or pi/2 when there is none.
OSGWATER_EXPORT float criticalAngle(float n1, float n2);

//! Bends N towards E so that E.N >= minCos: wave normals facing away from the eye
//! (grazing views) would otherwise give negative cosines and a refract() of the wrong side.
OSGWATER_EXPORT glm::vec3 faceNormal(const glm::vec3& N, const glm::vec3& E, float minCos = 1.0e-3f);

//! f of eq. 8: reflectance at normal incidence.
OSGWATER_EXPORT float normalReflectance(float n1, float n2);
//! Eq. 7: F = f + (1-f)(1-cosE)^q, cosE clamped to [0,1].
OSGWATER_EXPORT float fresnelSchlick(float cosE, float f, float q);
//! F = (1-cosE)^q.
OSGWATER_EXPORT float fresnelPower(float cosE, float q);
//! F = 1 / (1+cosE)^p (DeepWater), cosE clamped to [0,1].
OSGWATER_EXPORT float fresnelReciprocal(float cosE, float p);
//! How far F = 1/(1+cos)^p lies from the exact curve from n1 into n2 over the incidence angles
//! 0..90 degrees (samples + 1 of them, evenly spaced): the largest and the root-mean-square error.
struct FitError { double max = 0.0, rms = 0.0; };
OSGWATER_EXPORT FitError reciprocalFresnelError(double p, float n1, float n2, int samples = 900);
//! The power p in [1, 32], to 0.01, with the least largest error (leastMax) or the least RMS error.
OSGWATER_EXPORT double bestReciprocalPower(float n1, float n2, bool leastMax);
//! Unpolarised Fresnel reflectance from n1 into n2 at incidence cosine cosI (1 under TIR).
OSGWATER_EXPORT float fresnelExact(float cosI, float n1, float n2);

//! Fresnel model numbers as the shader's OSGWATER_FRESNEL (WaterSettings::FresnelModel): 0 Schlick
//! (eq. 7-8), 1 power, 2 exact, 3 reciprocal power. Evaluated at cosE (Schlick's f from n1, n2);
//! q is the model's exponent (WaterSettings::getFresnelModelExponent).
OSGWATER_EXPORT float fresnelModel(int model, float cosE, float n1, float n2, float q);
//! fresnelModel averaged over the facets the eye sees where the pixel's normal hides slopes of
//! variance `roughness` (mean |grad h|^2, alike every way), each facet weighted by its area seen from
//! the eye (fresnelAndLean's F for a pixel whose normal is the level's).
OSGWATER_EXPORT float fresnelOverSlopes(int model, float cosE, float roughness, float n1, float n2, float q);
//! Smith's Lambda for Gaussian slopes of deviation `s` along a ray leaving at elevation atan(tanUp)
//! above the level: a wave ahead meets the ray from a share Lambda / (1 + Lambda) of its starts.
OSGWATER_EXPORT float smithLambda(float tanUp, float s);
//! The light a pixel reflects where its normal hides slopes of variance `roughness`
//! (owFresnelAndLean): (F, the mean slope towards the eye of the seen facets weighted by the light
//! each reflects, that slope's deviation, the share of that light whose mirror rays leave the waves).
//! The seen facets lean towards the eye (more of their area faces it, the far-tilted hide), so their
//! mirror rays rise; the most tilted reflect least, so the light's lean is the F-weighted mean. A
//! facet tilted away by a turns the pixel's mirror ray (sine of its elevation above the level:
//! sinMirror) down by 2 atan(a): past the level it goes under; above it a wave ahead meets it from
//! Smith's share of the facets (smithLambda). Four Gauss-Legendre nodes over the rising facets, two
//! over the ones sent under.
OSGWATER_EXPORT glm::vec4 fresnelAndLean(int model, float cosE, float sinMirror, float roughness, float n1, float n2,
                                         float q);

//! The surface seen from below (thesis §7.5): E unit towards the eye (down, into the water), N unit
//! normal on the eye's side, n1 water, n2 air. R: direction of the transmitted ray (not unit for the
//! thesis model), tir: no transmitted ray, F: reflected share.
struct FromBelow { glm::vec3 R{0.0f}; bool tir = false; float F = 0.0f; };
//! Eq. 12 R1 = n (-N_up - E) + N_up with N_up = -N and n = n1/n2 (never zero, no TIR); F Schlick at E.N.
OSGWATER_EXPORT FromBelow underwaterThesis(const glm::vec3& E, const glm::vec3& N, float n1, float n2, float q);
//! Snell water -> air: R = refract(-E, N, n1/n2), total internal reflection beyond the critical angle
//! (F = 1); otherwise F of `model` (see fresnelModel) evaluated at the transmitted angle's cosine
//! (exact: at the incident one, where it is exact). Schlick at the incident angle is wrong there
//! by up to ~0.97 just inside the critical angle.
OSGWATER_EXPORT FromBelow underwaterPhysical(const glm::vec3& E, const glm::vec3& N, float n1, float n2,
                                             int model, float q);

//! Eq. 4: a = exp(-k d); d < 0 or NaN means "no bottom" and gives 0.
OSGWATER_EXPORT float attenuation(float k, float d);
//! Eq. 5: C_water + a (C_refract - C_water).
OSGWATER_EXPORT glm::vec3 waterTint(const glm::vec3& refracted, const glm::vec3& water, float a);
//! Per channel (the WATER_PER_CHANNEL model): exp(-k_i d) for each channel, 0 for d < 0 or NaN.
OSGWATER_EXPORT glm::vec3 attenuation(const glm::vec3& k, float d);
//! Eq. 5 per channel: C_water + a (C_refract - C_water), a per channel.
OSGWATER_EXPORT glm::vec3 waterTint(const glm::vec3& refracted, const glm::vec3& water, const glm::vec3& a);
//! Irradiance reflectance just below the surface of infinitely deep water of absorption a and
//! backscattering bb (per metre): Gordon, Brown & Jacobs, Appl. Opt. 14, 417 (1975),
//! R = 0.0001 + 0.3244 u + 0.1425 u^2 + 0.1308 u^3 with u = bb / (a + bb). 0 for bb <= 0.
OSGWATER_EXPORT float deepWaterReflectance(float a, float bb);
//! Eq. 9: C_refract + F (C_reflect - C_refract).
OSGWATER_EXPORT glm::vec3 fresnelMix(const glm::vec3& refracted, const glm::vec3& reflected, float F);

//! Eq. 3: the point on line p (U + t R) where it meets the line through A1 with direction Q.
//! Returns false (and leaves out unchanged) when the lines are (near) parallel.
OSGWATER_EXPORT bool lineIntersection(const glm::vec3& U, const glm::vec3& R,
                                      const glm::vec3& A1, const glm::vec3& Q, glm::vec3& out);

//! What the depth texture answers for the camera ray through an eye-space point P:
//! the eye-space Z of the first surface on that ray, or hit = false for sky (depth 1.0).
struct DepthSample { bool hit; float z; };
using DepthLookup = std::function<DepthSample(const glm::vec3& P)>;

//! When a search's candidate is close enough to the surface point A it sees: within `metres` plus
//! `perMetre` times A's distance in front of the pass's camera. A budget of texels (the settings'
//! ErrorBudget) is a length across the line of sight that the pass's camera sees as that many
//! texels: growing with the distance for a perspective camera, fixed for an orthographic one.
//! Mirrored in optics.glsl (owTexelTolerance).
struct SearchTolerance {
    float metres = 0.0f, perMetre = 0.0f;
    SearchTolerance(float m = 0.0f, float perMetreOfDepth = 0.0f) : metres(m), perMetre(perMetreOfDepth) {}
    //! `texels` of a pass whose projection is `proj` and whose target is `texelsHigh` texels high
    OSGWATER_EXPORT static SearchTolerance ofTexels(const glm::mat4& proj, int texelsHigh, float texels);
    float at(const glm::vec3& A) const { return metres + perMetre * -A.z; }
};

//! Result of a bottom search, in the refraction camera's eye space (camera at origin, -Z forward).
struct BottomHit {
    bool valid = false;   //!< false: every lookup saw sky; no bottom along R
    glm::vec3 W{0.0f};    //!< estimate of where U + t R meets the bottom
    glm::vec3 A{0.0f};    //!< bottom point seen through W (its error is |A - W|)
    float error = 0.0f;   //!< |A - W|
};

//! The bottom point on the camera ray through P: A = P * (Z / P.z).
OSGWATER_EXPORT bool bottomAlongRay(const glm::vec3& P, const DepthLookup& lookup, glm::vec3& A);

//! One-step lookup (SCCG 2008 eq. 1): W = U + clamp(scale*dv, 0, maxDv) R, dv = |A1 - U|.
OSGWATER_EXPORT BottomHit oneStepSearch(const glm::vec3& U, const glm::vec3& R, float scale, float maxDv,
                                        const DepthLookup& lookup);
//! Iterative search of thesis §7.1: tests `steps` candidates W_1..W_n (each one depth lookup,
//! plus one for A_1) and keeps the one with the smallest |A - W|. A candidate that sees sky
//! (under a clipped shore, off the texture) is replaced by the point half way back to U; with no
//! candidate on a bottom the answer is A_1, the bottom straight behind U. Invalid when U itself
//! sees sky, unless `eyeAmongWaves` (the eye within the waves' height of the level, where a crest
//! ahead can stand above all the pass sees): then A_1 is the first of ten points along R, doubling
//! from a quarter of U's distance, that sees a bottom, and invalid when none does. The search
//! stops early once a candidate is within `tolerance` of its bottom point (0: always all steps).
//! `reads`, when given: how many depth lookups it made.
OSGWATER_EXPORT BottomHit iterativeSearch(const glm::vec3& U, const glm::vec3& R, int steps,
                                          const DepthLookup& lookup, const SearchTolerance& tolerance = {},
                                          int* reads = nullptr, bool eyeAmongWaves = false);

//! The reflected ray U + t R (t > 0) in the reflection pass's eye space (the mirrored scene): its
//! hit, or invalid when it meets nothing (look it up by its direction). f(t), how far U + t R lies
//! in front of the surface on its camera ray (sky: in front of everything), has the hit as its
//! first root. The candidates go out from t_1 = |A_1 - U| (the thesis's first guess) by secant
//! steps until one lies behind a surface, then close in by regula falsi (Illinois) between the last
//! in front and the first behind. A surface under `floorPlane` (eye space, dot < 0) counts as sky:
//! the water shader puts it at U's height, on the side the ray leaves to. Where U's line of sight
//! sees sky, t_1 comes from what the pass sees along R from its eye (the ray's far end); invalid
//! when that sees sky too. No candidate within tolerance + 1% of its distance: the root's estimate
//! in its bracket, or invalid when there is none. The lookup says off-texture points see sky; the
//! candidates go no further than `tExit`, where the ray leaves the texture (frustumExit): one
//! beyond it sees sky, and the search would step on past a hit it had not bracketed yet.
OSGWATER_EXPORT BottomHit mirrorSearch(const glm::vec3& U, const glm::vec3& R, int steps, const DepthLookup& lookup,
                                       const SearchTolerance& tolerance = {}, const glm::vec4& floorPlane = glm::vec4(0, 0, 0, 1),
                                       float tExit = INFINITY, int* reads = nullptr);

//! How far the ray P + t R (eye space of a pass with projection `proj`) stays on the pass's
//! texture: the largest t whose point lies inside the frustum's four sides and in front of the
//! camera; infinity when it never leaves.
OSGWATER_EXPORT float frustumExit(const glm::mat4& proj, const glm::vec3& P, const glm::vec3& R);

//! Exact hit of U + t R with the plane z = planeZ (t > 0), for analytic tests.
OSGWATER_EXPORT bool intersectPlaneZ(const glm::vec3& U, const glm::vec3& R, float planeZ, glm::vec3& hit);

} }

#endif
