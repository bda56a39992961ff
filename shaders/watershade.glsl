// Colour of the water surface at a point U (water-local frame), thesis ch. 7, §7.5 and §9.1:
// refraction by bottom search in the refraction pass's depth texture, reflection by the same search
// in the reflection pass's (or the thesis's lookup W = U + c R), depth attenuation, Fresnel, final
// mix (eq. 9). Shared by the surface (water.frag) and the near-plane cap (cap.frag), which shades the
// surface where the near plane cut it away; the defines it switches on are listed once, here.
// OSGWATER_ENVIRONMENT: the surroundings above the water in a cube map (local frame), read along
// rays the pass textures do not hold.
// Debug output (OSGWATER_DEBUG, one of the OSGWATER_DEBUG_* of contract.glsl): alpha says what rgb
// holds (see osgWater::DebugOutput). The eye's side is a define (set per view), not a uniform: a
// software rasteriser runs both sides of a branch.
#pragma import_defines(OSGWATER_GRID, OSGWATER_EYE_BELOW, OSGWATER_EYE_AMONG_WAVES, OSGWATER_REFRACTION, OSGWATER_REFLECTION, OSGWATER_FRESNEL, OSGWATER_UNDERWATER, OSGWATER_NO_REFLECTION, OSGWATER_NO_REFRACTION, OSGWATER_SEARCH_STEPS, OSGWATER_ENVIRONMENT, OSGWATER_DEBUG)
#pragma include "contract.glsl"
#pragma include "optics.glsl"
#pragma include "srgb.glsl"

uniform sampler2D osgWater_ReflectionTex;
uniform sampler2D osgWater_RefractionTex;
uniform vec3 osgWater_EyeLocal;
uniform mat4 osgWater_ReflectionMVP;        // local -> reflection pass clip space
uniform sampler2D osgWater_ReflectionDepth;
uniform mat4 osgWater_ReflectionView;       // local -> reflection pass eye space (the mirror in it)
uniform mat4 osgWater_ReflectionViewInverse;
uniform mat4 osgWater_ReflectionProj;
uniform mat4 osgWater_RefractionView;       // local -> refraction pass eye space
uniform mat4 osgWater_RefractionViewInverse;

uniform vec2 osgWater_IOR;                  // (air, water)
uniform vec3 osgWater_WaterColor;          // the body colour a long path through water tends to
uniform vec3 osgWater_Extinction;           // k per channel (the thesis model: the same k thrice)
uniform float osgWater_FresnelQ;            // q
uniform float osgWater_ReflectionScale;     // c
uniform int osgWater_SearchSteps;
uniform float osgWater_ErrorBudget;         // texels of the texture a search reads
uniform vec2 osgWater_OneStep;              // (dv scale, dv max)
uniform float osgWater_UnderwaterScale;     // m of eq. 13, 15
uniform vec2 osgWater_LookupPlanes;         // plane-offset lookups: (height above the level, depth below it)

#ifdef OSGWATER_ENVIRONMENT
uniform samplerCube osgWater_EnvironmentTex;
#endif

// The texture's texels where the point P (w = 0: a direction) projects through `mvp`
vec3 owSampleProjected(sampler2D tex, mat4 mvp, vec4 P, vec3 fallback)
{
    vec4 c = mvp * P;
    if (!(c.w > 1e-6)) return fallback;
    return texture(tex, c.xy / c.w * 0.5 + 0.5).rgb;
}

// The same blurred over `spread`, the blur's (width, height) in texels (zero: level 0).
// Taller than wide: kSpreadTaps reads stacked up the texture, each at the level whose texels are
// as wide as the blur and as tall as its share of the height (filtering hardware would do this
// anisotropically, but a software rasteriser pays its sixteen reads on every fragment; two reads
// look as four did, at half their cost). Only the wind's waves leave slopes below the pixel: the
// sum's read once, at level 0.
#ifdef OSGWATER_WIND
const int kSpreadTaps = 2;
#else
const int kSpreadTaps = 1;
#endif
vec3 owSampleProjectedSpread(sampler2D tex, mat4 mvp, vec4 P, vec3 fallback, vec2 spread)
{
    vec4 c = mvp * P;
    if (!(c.w > 1e-6)) return fallback;
    vec2 uv = c.xy / c.w * 0.5 + 0.5;
    float tapHeight = spread.y / float(kSpreadTaps);
    float lod = log2(max(max(spread.x, tapHeight), 1.0));
    float step = tapHeight / float(textureSize(tex, 0).y);
    vec3 sum = vec3(0.0);
    for (int k = 0; k < kSpreadTaps; ++k)
        sum += textureLod(tex, uv + vec2(0.0, (float(k) + 0.5 - 0.5 * float(kSpreadTaps)) * step), lod).rgb;
    return sum / float(kSpreadTaps);
}

// The reflection blurred by the slopes the shaded normal does not show: the blur's (width, height)
// in texels of the reflection pass's texture, for seen facets whose slopes deviate by `slopes`
// (along the plane of incidence, across it; 0 but under the wind). A slope a along the plane turns
// the mirrored ray up or down by 2a; one across it turns the ray sideways by only 2a sin(e), e the
// ray's elevation: at grazing angles reflections smear into vertical streaks, not round blurs (the
// mirrored camera keeps the texture's vertical upright). The pass sees a turn from its (mirrored)
// eye, L metres from U, at the lookup point P D metres on, as the angle turn D / (L + D) (at
// infinity: the turn itself); the blur spans it either way.
vec2 owReflectionSpread(vec3 U, vec4 P, vec3 Rr, vec2 slopes)
{
    float seen = P.w > 0.5 ? length(P.xyz - U) / (length(osgWater_EyeLocal - U) + length(P.xyz - U)) : 1.0;
    float texelsPerRadian = 0.5 * float(textureSize(osgWater_ReflectionTex, 0).y) * osgWater_ReflectionProj[1][1];
    vec2 turn = 2.0 * 2.0 * seen * texelsPerRadian * slopes;
    return vec2(turn.y * abs(Rr.z), turn.x);
}

// The same for a ray along `dir` whose lookup point is P: where P falls outside the texture (or
// behind its camera), the environment along dir, when there is one (`fromEnvironment` says so).
vec3 owSampleOrEnvironment(sampler2D tex, mat4 mvp, vec4 P, vec3 dir, vec3 fallback, vec2 spread, out bool fromEnvironment)
{
    fromEnvironment = false;
#ifdef OSGWATER_ENVIRONMENT
    vec4 c = mvp * P;
    vec2 tc = c.xy / c.w * 0.5 + 0.5; // NaN behind the camera: not inside
    bool inside = c.w > 1e-6 && all(greaterThanEqual(tc, vec2(0.0))) && all(lessThanEqual(tc, vec2(1.0)));
    if (!inside) {
        fromEnvironment = true;
        return texture(osgWater_EnvironmentTex, dir).rgb;
    }
#endif
    return owSampleProjectedSpread(tex, mvp, P, fallback, spread);
}

// DeepWater's plane-offset lookups: the scene taken as the plane z = planeZ; the ray from U along D
// meets it at a point (w = 1), or never (w = 0: the direction, a point at infinity).
vec4 owPlanePoint(vec3 U, vec3 D, float planeZ)
{
    float t = (planeZ - U.z) / (abs(D.z) > 1e-6 ? D.z : 1e-6);
    return t > 0.0 && t < 1e6 ? vec4(U + t * D, 1.0) : vec4(D, 0.0);
}

// The refracted ray's hit in the refraction pass (its eye space, R1 unit): the thesis's iterative
// search, or the reflection's bracketed one (OSGWATER_REFRACTION 3, WaterSettings::BRACKETED),
// which finds the hit beyond a depth edge where the thesis's secants through two bottom points
// point anywhere. A bracketed ray that meets nothing the pass drew is none (seen from below: the
// sky along its direction).
owBottomHit owRefractionSearch(vec3 u1, vec3 R1)
{
#if defined(OSGWATER_REFRACTION) && OSGWATER_REFRACTION == OSGWATER_REFRACTION_BRACKETED
    return owMirrorSearch(osgWater_RefractionDepth, owRefractionPass(), u1, R1, osgWater_SearchSteps,
                          osgWater_ErrorBudget);
#else
    return owIterativeSearch(u1, R1, osgWater_SearchSteps, osgWater_ErrorBudget);
#endif
}

// Virtual vertices (OSGWATER_REFRACTION 4): the point the pass drew at u1's own place (its eye
// is this view's), or none where it drew nothing.
owBottomHit owVirtualHit(vec3 u1)
{
    vec2 tc;
    owRefractionTexCoord(u1, tc);
    float depth = texture(osgWater_RefractionDepth, tc).r;
    vec4 p = osgWater_RefractionInvProj * vec4(vec3(tc, depth) * 2.0 - 1.0, 1.0);
    vec3 V = p.xyz / p.w;
    return owBottomHit(depth < 1.0, V, V, 0.0);
}

// The refracted colour seen from above: bottom search along R (eq. 4-5), or the plane offset.
vec3 owRefractedFromAbove(vec3 U, vec3 R, out vec4 debugHit)
{
    debugHit = vec4(0.0, 0.0, 0.0, -1.0);
    vec3 u1 = (osgWater_RefractionView * vec4(U, 1.0)).xyz;
    vec3 R1 = normalize(mat3(osgWater_RefractionView) * R); // unit in that eye space, scaled or not
#if defined(OSGWATER_REFRACTION) && OSGWATER_REFRACTION == OSGWATER_REFRACTION_PLANE
    // the refracted ray's hit on the plane below the level (a wave's trough under the plane: U)
    vec4 P = owPlanePoint(U, R, osgWater_Level - osgWater_LookupPlanes.y);
    vec3 p1 = (osgWater_RefractionView * vec4(P.w > 0.5 ? P.xyz : U, 1.0)).xyz;
    owBottomHit hit = owBottomHit(true, p1, p1, 0.0);
#elif defined(OSGWATER_REFRACTION) && OSGWATER_REFRACTION == OSGWATER_REFRACTION_ONE_STEP
    owBottomHit hit = owOneStepSearch(u1, R1, osgWater_OneStep.x, osgWater_OneStep.y);
#elif defined(OSGWATER_REFRACTION) && OSGWATER_REFRACTION == OSGWATER_REFRACTION_VIRTUAL_VERTICES
    // virtual vertices: the pass drew the underwater scene where it appears, from this view's eye;
    // U's own place in it holds what the refracted ray sees
    owBottomHit hit = owVirtualHit(u1);
#else
    owBottomHit hit = owRefractionSearch(u1, R1);
#endif
    float d = -1.0;
    vec3 col = osgWater_WaterColor;
    if (hit.valid) {
        vec2 tc;
        owRefractionTexCoord(hit.W, tc);
        col = texture(osgWater_RefractionTex, tc).rgb;
        d = length(mat3(osgWater_RefractionViewInverse) * (hit.A - u1)); // local metres
        debugHit = vec4((osgWater_RefractionViewInverse * vec4(hit.W, 1.0)).xyz, 2.0);
#if defined(OSGWATER_REFRACTION) && OSGWATER_REFRACTION == OSGWATER_REFRACTION_VIRTUAL_VERTICES
        d *= osgWater_IOR.y / osgWater_IOR.x; // the virtual point lies eta times as far (eq. 2.4)
#if defined(OSGWATER_DEBUG) && OSGWATER_DEBUG == OSGWATER_DEBUG_BOTTOM_HIT
        vec4 shown = texture(osgWater_RefractionTex, tc); // the true place drawn there (a float target)
        debugHit = shown.a > 0.5 ? vec4(shown.xyz, 4.0) : vec4(0.0, 0.0, 0.0, -1.0);
#endif
#endif
    }
    return osgWater_WaterColor + owAttenuation(osgWater_Extinction, d) * (col - osgWater_WaterColor);
}

// The refracted colour seen from below (thesis §7.5): what lies along R in the air, then the
// water between U and the eye (eq. 5 with d = |U - C1|).
vec3 owRefractedFromBelow(vec3 U, vec3 R, out vec4 debugHit)
{
    mat4 mvp = osgWater_RefractionProj * osgWater_RefractionView;
#if defined(OSGWATER_UNDERWATER) && OSGWATER_UNDERWATER == OSGWATER_UNDERWATER_THESIS
    debugHit = vec4(U + osgWater_UnderwaterScale * R, 2.0);
    vec3 col = owSampleProjected(osgWater_RefractionTex, mvp, vec4(U + osgWater_UnderwaterScale * R, 1.0),
                                 osgWater_WaterColor); // eq. 13
#else
    // the same search as from above, in the air; nothing found along R: the sky in R's direction
    vec3 u1 = (osgWater_RefractionView * vec4(U, 1.0)).xyz;
    owBottomHit hit = owRefractionSearch(u1, normalize(mat3(osgWater_RefractionView) * R));
    vec3 col;
    vec2 tc;
    if (hit.valid && owRefractionTexCoord(hit.W, tc)) {
        col = texture(osgWater_RefractionTex, tc).rgb;
        debugHit = vec4((osgWater_RefractionViewInverse * vec4(hit.W, 1.0)).xyz, 2.0);
    } else {
        bool fromEnvironment;
        col = owSampleOrEnvironment(osgWater_RefractionTex, mvp, vec4(R, 0.0), R, osgWater_WaterColor, vec2(0.0), fromEnvironment);
        debugHit = vec4(R, 3.0);
    }
#endif
    vec3 a = owAttenuation(osgWater_Extinction, length(osgWater_EyeLocal - U));
    return osgWater_WaterColor + a * (col - osgWater_WaterColor);
}

// The point whose colour the reflection pass shows for the reflected ray U + t Rr (a direction,
// w = 0, for a ray that meets nothing), by OSGWATER_REFLECTION (WaterSettings::ReflectionLookup):
// 2 the ray's hit searched in the reflection pass's depth texture, 1 its hit on the plane above
// (DeepWater, from above; under water the offset), 0 the thesis's U + c R.
vec4 owReflectionLookupPoint(vec3 U, vec3 Rr, bool below)
{
#if defined(OSGWATER_REFLECTION) && OSGWATER_REFLECTION == OSGWATER_REFLECTION_SEARCH && !defined(OSGWATER_NO_REFLECTION)
    vec3 u1 = (osgWater_ReflectionView * vec4(U, 1.0)).xyz;
    vec3 R1 = normalize(mat3(osgWater_ReflectionView) * Rr);
    // the floor: U's height, on the side the ray leaves to (eye space: the local z row, less U.z)
    mat4 toLocal = osgWater_ReflectionViewInverse;
    float side = Rr.z >= 0.0 ? 1.0 : -1.0;
    vec4 floorPlane = side * (vec4(toLocal[0].z, toLocal[1].z, toLocal[2].z, toLocal[3].z) - vec4(0.0, 0.0, 0.0, U.z))
                    + vec4(0.0, 0.0, 0.0, 1e-3);
    owDepthPass pass = owDepthPass(osgWater_ReflectionProj, floorPlane, true);
    owBottomHit hit = owMirrorSearch(osgWater_ReflectionDepth, pass, u1, R1, osgWater_SearchSteps,
                                     osgWater_ErrorBudget);
    return hit.valid ? vec4((osgWater_ReflectionViewInverse * vec4(hit.W, 1.0)).xyz, 1.0) : vec4(Rr, 0.0);
#else
#if defined(OSGWATER_REFLECTION) && OSGWATER_REFLECTION == OSGWATER_REFLECTION_PLANE
    if (!below) return owPlanePoint(U, Rr, osgWater_Level + osgWater_LookupPlanes.x);
#endif
    return vec4(U + (below ? osgWater_UnderwaterScale : osgWater_ReflectionScale) * Rr, 1.0);
#endif
}

// U: the surface point, Nup: its unit normal (up, into the air), E: unit vector towards the eye,
// roughness: the variance of the slopes below the pixel that Nup does not show (waves.glsl).
vec3 owShadeWater(vec3 U, vec3 Nup, vec3 E, float roughness, out vec4 debugOut)
{
    vec4 debugHit = vec4(0.0, 0.0, 0.0, -1.0);
#ifdef OSGWATER_EYE_BELOW
    const bool below = true;
#else
    const bool below = false;
#endif
    float n1 = below ? osgWater_IOR.y : osgWater_IOR.x; // eye side
    float n2 = below ? osgWater_IOR.x : osgWater_IOR.y;
    vec3 N = owFaceNormal(below ? -Nup : Nup, E, 1e-3);
    float cosE = clamp(dot(E, N), 0.0, 1.0);
    vec3 Rr = reflect(-E, N);
    vec3 R;
    bool tir = false;
    float F;
#ifndef OSGWATER_EYE_BELOW
    R = refract(-E, N, n1 / n2); // never zero from air into water
#ifdef OSGWATER_WIND
    vec4 lean = owFresnelAndLean(cosE, Rr.z, roughness, n1, n2, osgWater_FresnelQ); // the slopes below the pixel
    F = lean.x;
#else
    F = owFresnel(cosE, n1, n2, osgWater_FresnelQ); // the sum's waves are all drawn
#endif
#else
#if defined(OSGWATER_UNDERWATER) && OSGWATER_UNDERWATER == OSGWATER_UNDERWATER_THESIS
        R = (n1 / n2) * (N - E) - N; // eq. 12: never zero, no total internal reflection
        float r = (n1 - n2) / (n1 + n2);
        F = owFresnelSchlick(cosE, r * r, osgWater_FresnelQ);
#else
        R = refract(-E, N, n1 / n2); // zero beyond the critical angle
        tir = dot(R, R) < 0.5;
        float cosT = clamp(-dot(R, N), 0.0, 1.0);
#if defined(OSGWATER_FRESNEL) && OSGWATER_FRESNEL == OSGWATER_FRESNEL_EXACT
        F = tir ? 1.0 : owFresnel(cosE, n1, n2, osgWater_FresnelQ); // exact at the incident angle
#else
        F = tir ? 1.0 : owFresnel(cosT, n1, n2, osgWater_FresnelQ); // approximations: air-side angle
#endif
#endif
#endif

    // reflection, eq. 6 / 15 (under water the reflection pass already holds the water's tint),
    // read along the mirror ray of the facets the eye sees below the pixel (owFresnelAndLean: they
    // lean towards the eye), blurred by their spread. The debug lookup stays the normal's own mirror ray:
    // the benchmark measures the search on it; the image error measures what the tilt reads.
    vec3 Rseen = Rr;
    float slopes = sqrt(max(0.5 * roughness, 0.0));
    vec2 seenSlopes = vec2(slopes);
#if defined(OSGWATER_WIND) && !defined(OSGWATER_EYE_BELOW)
    vec3 towardsEye = E - cosE * N;
    float across = length(towardsEye);
    if (across > 1e-6) Rseen = reflect(-E, normalize(N + (lean.y / across) * towardsEye));
    seenSlopes.x = lean.z;
#endif
    int readsBefore = owDepthReads;
    vec4 reflP = owReflectionLookupPoint(U, Rseen, below);
    int reflectionReads = owDepthReads - readsBefore;
#if defined(OSGWATER_DEBUG) && OSGWATER_DEBUG == OSGWATER_DEBUG_REFLECTION_LOOKUP
    vec4 mirrorP = owReflectionLookupPoint(U, Rr, below); // reflP itself wherever Rseen is Rr
#else
    vec4 mirrorP = reflP;
#endif
    vec4 debugRefl = vec4(mirrorP.xyz, mirrorP.w > 0.5 ? 2.0 : 3.0);
    // the surroundings above the water, for reflections seen from above
#if defined(OSGWATER_ENVIRONMENT) && !defined(OSGWATER_EYE_BELOW)
    const bool environment = true;
#else
    const bool environment = false;
#endif
#ifdef OSGWATER_NO_REFLECTION
    vec3 reflCol = osgWater_WaterColor; // no fetch: the reflection pass did not run
#ifdef OSGWATER_ENVIRONMENT
    if (environment) { // every reflected ray reads the environment
        reflCol = texture(osgWater_EnvironmentTex, Rr).rgb;
        debugRefl = vec4(Rr, 3.0);
    } else
#endif
    F = tir ? 1.0 : 0.0;
#else
    bool fromEnvironment = false;
    vec2 spread = owReflectionSpread(U, reflP, Rseen, seenSlopes);
    vec3 reflCol = environment
        ? owSampleOrEnvironment(osgWater_ReflectionTex, osgWater_ReflectionMVP, reflP, Rseen, osgWater_WaterColor, spread, fromEnvironment)
        : owSampleProjectedSpread(osgWater_ReflectionTex, osgWater_ReflectionMVP, reflP, osgWater_WaterColor, spread);
    if (fromEnvironment) debugRefl = vec4(Rseen, 3.0); // the lookup became the ray's direction
#endif

    vec3 refrCol = osgWater_WaterColor;
#ifdef OSGWATER_NO_REFRACTION
    F = 1.0; // no search: the refraction pass did not run
#else
#ifdef OSGWATER_EYE_BELOW
    if (!tir) refrCol = owRefractedFromBelow(U, R, debugHit);
    else debugHit = vec4(0.0, 0.0, 0.0, -2.0);
#else
    refrCol = owRefractedFromAbove(U, R, debugHit);
#endif
#endif
#if defined(OSGWATER_DEBUG) && OSGWATER_DEBUG == OSGWATER_DEBUG_REFLECTION_LOOKUP
    debugOut = debugRefl;
#elif defined(OSGWATER_DEBUG) && OSGWATER_DEBUG == OSGWATER_DEBUG_FRESNEL
#if defined(OSGWATER_WIND) && !defined(OSGWATER_EYE_BELOW)
    debugOut = vec4(F, lean.yz, 2.0);
#else
    debugOut = vec4(F, 0.0, 0.0, 2.0);
#endif
#elif defined(OSGWATER_DEBUG) && OSGWATER_DEBUG == OSGWATER_DEBUG_WORK
    debugOut = vec4(float(owDepthReads - readsBefore - reflectionReads), float(reflectionReads), 0.0, 2.0);
#else
    debugOut = debugHit;
#endif
#if !defined(OSGWATER_EYE_BELOW) && !defined(OSGWATER_NO_REFRACTION)
    // a mirror ray the waves send back under the level, or that meets a wave ahead, meets the water
    // again, mostly to pass into it: its light is the water's own (the refracted colour here), not
    // the sky along its direction
#ifdef OSGWATER_WIND
    float escapes = lean.w;
#else
    float escapes = Rr.z < 0.0 ? 0.0 : 1.0; // the sum's waves are all drawn: the normal's own ray
#endif
    reflCol = mix(refrCol, reflCol, escapes);
#endif
    return refrCol + F * (reflCol - refrCol); // eq. 9
}

// What a fragment of the water writes at U (on the surface; `drawn`: the rasterised point it was
// found from; N, roughness: the upward normal and the roughness it was shaded with): its colour
// (linear light, encoded for display: the water is drawn in the view itself), or the debug output
// (OSGWATER_DEBUG 4: the analytic surface under U; 5: the drawn point; 6: the slopes of N and the
// roughness, as shaded; else what owShadeWater reported), the same for the surface and the cap
// (the work's b: the march's evaluations, waves.glsl's count).
vec4 owWaterFragment(vec3 U, vec3 drawn, vec3 N, float roughness, vec3 color, vec4 debugHit)
{
#if defined(OSGWATER_DEBUG) && OSGWATER_DEBUG == OSGWATER_DEBUG_SURFACE
#ifdef OSGWATER_GRID
    return vec4(U.xy, waterHeight(U.xy), 2.0);
#else
    return vec4(U, 2.0);
#endif
#elif defined(OSGWATER_DEBUG) && OSGWATER_DEBUG == OSGWATER_DEBUG_DRAWN_SURFACE
    return vec4(drawn, 2.0);
#elif defined(OSGWATER_DEBUG) && OSGWATER_DEBUG == OSGWATER_DEBUG_SLOPES
#ifdef OSGWATER_GRID
    // as shaded, from the reads N came from (U lies a last Newton step past them: read again there,
    // the short waves a pixel resolves give a neighbouring point's slopes)
    return vec4(-N.xy / N.z, roughness, 2.0);
#else
    return vec4(0.0, 0.0, 0.0, -1.0); // a user's mesh: its normals, no slopes of waves
#endif
#elif defined(OSGWATER_DEBUG) && OSGWATER_DEBUG == OSGWATER_DEBUG_WORK
    return vec4(debugHit.rg, float(waterHeightReads), 2.0);
#elif defined(OSGWATER_DEBUG)
    return debugHit;
#else
    return vec4(owDisplay(color), 1.0);
#endif
}
