#version 130
#pragma import_defines(OSGWATER_FRESNEL, OSGWATER_PROCEDURAL_SHADE)
// Procedural caustics (Sanchez-Crespo 2003) drawn into the caustics texture, no photons. Each texel
// of the sun's window takes the bed point the sun's depth map shows there (the underwater scene), and
// traces back up the direction the sun's light takes through flat water (the paper's vertical when
// the sun is overhead) to the waves above it; the ray is refracted back into the air there, by the
// waves' analytic normal, and the sky's brightness in that direction is read from a sun-and-halo map.
// Where the exit ray points at the sun the bed is lit. Calibrated so that flat water gives what the
// photons give, (1 - F) exp(-k d); aesthetic elsewhere (nothing conserves the light). The CPU mirror:
// osgWater/ProceduralCaustics (the same steps in double precision).
#define OSGWATER_ORTHO_DEPTH 1
#pragma include "waves.glsl"
#pragma include "optics.glsl"
#ifdef OSGWATER_PROCEDURAL_SHADE
#pragma include "sunshade.glsl"
#endif

uniform vec2 osgWater_IOR;              // (air, water)
uniform float osgWater_PhotonExtinction; // the green channel's sun extinction (the thesis's k)
uniform float osgWater_FresnelQ;
uniform sampler2D osgWater_SunBedDepth; // the underwater scene's depth seen from the sun
uniform mat4 osgWater_SunTexToLocal;    // the sun's texture space (u, v, depth) -> water-local
uniform mat4 osgWater_SunView;          // water-local -> the sun camera's eye space
uniform vec3 osgWater_TowardsSunLocal;
uniform vec3 osgWater_SunHalo;          // the disc's radius, the halo's radius (radians), the halo's level
uniform float osgWater_ProceduralScale; // stored texel = value * scale

in vec2 vTex;

const int kHeightSteps = 6; // fixed-point steps on the height, as the CPU mirror takes

// The sun-and-halo map: 1 on the disc, the halo falling from its level to 0 at its radius.
float owSunHalo(float angle)
{
    if (angle <= osgWater_SunHalo.x) return 1.0;
    if (angle >= osgWater_SunHalo.y) return 0.0;
    float x = 1.0 - (angle - osgWater_SunHalo.x) / (osgWater_SunHalo.y - osgWater_SunHalo.x);
    return osgWater_SunHalo.z * x * x;
}

void main()
{
    float value = 0.0;
    float depth = owDepthBetweenTexels(osgWater_SunBedDepth, vTex);
    vec3 sun = normalize(osgWater_TowardsSunLocal);
    const vec3 up = vec3(0.0, 0.0, 1.0);
    vec3 down = refract(-sun, up, osgWater_IOR.x / osgWater_IOR.y);
    vec3 back = -down;
    if (depth < 1.0 && sun.z > 0.0 && back.z > 0.0) {
        vec4 b = osgWater_SunTexToLocal * vec4(vTex, depth, 1.0);
        vec3 bed = b.xyz / b.w;
        float tau = (osgWater_Level - bed.z) / back.z;
        for (int i = 0; i < kHeightSteps; ++i) {
            vec3 p = bed + tau * back;
            tau = (waterHeight(p.xy) - bed.z) / back.z;
        }
        if (tau > 0.0) {
            vec3 P = bed + tau * back;
            P.z = waterHeight(P.xy);
            vec3 N = waterNormal(P.xy);
            vec3 exitRay = refract(back, -N, osgWater_IOR.y / osgWater_IOR.x);
            if (dot(exitRay, exitRay) > 0.5) {
                vec3 e = normalize(exitRay);
                float angle = atan(length(cross(e, sun)), dot(e, sun)); // precise near 0, unlike acos
                float F = owFresnel(sun.z, osgWater_IOR.x, osgWater_IOR.y, osgWater_FresnelQ);
                value = owSunHalo(angle) * (1.0 - F) * exp(-osgWater_PhotonExtinction * length(P - bed));
#ifdef OSGWATER_PROCEDURAL_SHADE
                // the sun's ray meets the scene before this water (a pier above it, the shore): dark
                if (!owSunReaches((osgWater_SunView * vec4(P, 1.0)).xyz)) value = 0.0;
#endif
            }
        }
    }
    gl_FragColor = vec4(value * osgWater_ProceduralScale);
}
