#version 130
#pragma import_defines(OSGWATER_GRID, OSGWATER_ONE_STEP, OSGWATER_FRESNEL, OSGWATER_NO_REFLECTION, OSGWATER_NO_REFRACTION, OSGWATER_DEBUG_HIT)
// Water shading, thesis ch. 7 and §9.1: refraction by bottom search in the refraction pass's
// depth texture, reflection lookup W = U + c R, depth attenuation, Fresnel, final mix (eq. 9).
// Everything is in the WaterNode's local frame (z up) unless it says eye space.
#pragma include "waves.glsl"
#pragma include "optics.glsl"

uniform sampler2D osgWater_ReflectionTex;   // unit 1
uniform sampler2D osgWater_RefractionTex;   // unit 2
uniform vec3 osgWater_EyeLocal;
uniform float osgWater_EyeBelow;            // 1.0 when the eye is under the water plane
uniform mat4 osgWater_ReflectionMVP;        // local -> reflection pass clip space
uniform mat4 osgWater_RefractionView;       // local -> refraction pass eye space
uniform mat4 osgWater_RefractionViewInverse;

uniform vec2 osgWater_IOR;                  // (air, water)
uniform vec3 osgWater_WaterColor;
uniform float osgWater_Attenuation;         // k
uniform float osgWater_FresnelQ;            // q
uniform float osgWater_ReflectionScale;     // c
uniform int osgWater_SearchSteps;
uniform float osgWater_SearchTolerance;    // metres
uniform vec2 osgWater_OneStep;              // (dv scale, dv max)
uniform float osgWater_UnderwaterScale;     // m of eq. 13, 15

in vec3 vLocal;
in vec3 vMeshNormal;

vec3 sampleProjected(sampler2D tex, mat4 mvp, vec3 P, vec3 fallback)
{
    vec4 c = mvp * vec4(P, 1.0);
    if (!(c.w > 1e-6)) return fallback;
    return texture(tex, c.xy / c.w * 0.5 + 0.5).rgb;
}

void main()
{
    vec3 U = vLocal;
    vec3 E = owSafeNormalize(osgWater_EyeLocal - U, vec3(0.0, 0.0, 1.0));
#ifdef OSGWATER_GRID
    vec3 N = waterNormal(U.xy);
#else
    vec3 N = owSafeNormalize(vMeshNormal, vec3(0.0, 0.0, 1.0));
#endif
    bool below = osgWater_EyeBelow > 0.5;
    float n1 = below ? osgWater_IOR.y : osgWater_IOR.x; // eye side
    float n2 = below ? osgWater_IOR.x : osgWater_IOR.y;
    if (below) N = -N;
    N = owFaceNormal(N, E, 1e-3);
    float cosE = clamp(dot(E, N), 0.0, 1.0);
    vec3 R = refract(-E, N, n1 / n2);      // zero under total internal reflection
    bool tir = dot(R, R) < 0.5;
    vec3 Rr = reflect(-E, N);

    // reflection, eq. 6
    float c = below ? osgWater_UnderwaterScale : osgWater_ReflectionScale;
#ifdef OSGWATER_NO_REFLECTION
    vec3 reflCol = osgWater_WaterColor; // no fetch: the reflection pass did not run
#else
    vec3 reflCol = sampleProjected(osgWater_ReflectionTex, osgWater_ReflectionMVP, U + c * Rr, osgWater_WaterColor);
#endif

    // refraction, eq. 4-5
    vec3 refrCol = osgWater_WaterColor;
    vec4 debugHit = vec4(0.0);
#ifndef OSGWATER_NO_REFRACTION // no search when the refraction pass did not run
    if (!tir) {
        if (!below) {
            vec3 u1 = (osgWater_RefractionView * vec4(U, 1.0)).xyz;
            vec3 R1 = mat3(osgWater_RefractionView) * R;
#ifdef OSGWATER_ONE_STEP
            owBottomHit hit = owOneStepSearch(u1, R1, osgWater_OneStep.x, osgWater_OneStep.y);
#else
            owBottomHit hit = owIterativeSearch(u1, R1, osgWater_SearchSteps, osgWater_SearchTolerance);
#endif
            float d = -1.0;
            vec3 col = osgWater_WaterColor;
            if (hit.valid) {
                vec2 tc;
                owRefractionTexCoord(hit.W, tc);
                col = texture(osgWater_RefractionTex, tc).rgb;
                d = length(hit.A - u1);
                debugHit = vec4((osgWater_RefractionViewInverse * vec4(hit.W, 1.0)).xyz, 1.0);
            }
            refrCol = osgWater_WaterColor + owAttenuation(osgWater_Attenuation, d) * (col - osgWater_WaterColor);
        } else {
            // thesis §7.5: eye under water, W1 = U + m R1, attenuation along |U - C1|
            vec3 col = sampleProjected(osgWater_RefractionTex, osgWater_RefractionProj * osgWater_RefractionView,
                                       U + osgWater_UnderwaterScale * R, osgWater_WaterColor);
            float a = owAttenuation(osgWater_Attenuation, length(osgWater_EyeLocal - U));
            refrCol = osgWater_WaterColor + a * (col - osgWater_WaterColor);
        }
    }
#endif

    float F = tir ? 1.0 : owFresnel(cosE, n1, n2, osgWater_FresnelQ);
#ifdef OSGWATER_NO_REFLECTION
    F = tir ? 1.0 : 0.0;
#endif
#ifdef OSGWATER_NO_REFRACTION
    F = 1.0;
#endif
    vec3 color = refrCol + F * (reflCol - refrCol); // eq. 9
#ifdef OSGWATER_DEBUG_HIT
    gl_FragColor = debugHit;
#else
    gl_FragColor = vec4(color, 1.0);
#endif
}
