// Procedural caustics (Sanchez-Crespo 2003) at one bed point, shared by the paper's two variants:
// the texture-space one (procedural.frag, into the caustics texture) and the screen-space one (the
// scene program's fragments, caustics.glsl). From the bed point, up the direction the sun's light
// takes through flat water (the paper's vertical when the sun is overhead) to the waves above it;
// the ray refracted back into the air there by the waves' analytic normal; the sky's brightness in
// that direction from a sun-and-halo map. Calibrated so that flat water gives what the photons give,
// (1 - F) exp(-k d); aesthetic elsewhere (nothing conserves the light). The CPU mirror:
// osgWater/caustics/ProceduralCaustics.h (the same steps in double precision). Needs waves.glsl and optics.glsl
// (owFresnel) first; the includer lists OSGWATER_FRESNEL in its import_defines.
uniform vec2 osgWater_IOR;               // (air, water)
uniform float osgWater_PhotonExtinction; // the green channel's sun extinction (the thesis's k)
uniform float osgWater_FresnelQ;
uniform vec3 osgWater_TowardsSunLocal;
uniform vec3 osgWater_SunHalo;           // the disc's radius, the halo's radius (radians), the halo's level

const int kHeightSteps = 6; // fixed-point steps on the height, as the CPU mirror takes

// The sun-and-halo map: 1 on the disc, the halo falling from its level to 0 at its radius.
float owSunHalo(float angle)
{
    if (angle <= osgWater_SunHalo.x) return 1.0;
    if (angle >= osgWater_SunHalo.y) return 0.0;
    float x = 1.0 - (angle - osgWater_SunHalo.x) / (osgWater_SunHalo.y - osgWater_SunHalo.x);
    return osgWater_SunHalo.z * x * x;
}

// The light at bed point `bed` (water-local), in units of the sun's irradiance; `exitPoint`: where
// its backward ray leaves the water (for a shade test), valid where the light is not 0.
float owProceduralLight(vec3 bed, out vec3 exitPoint)
{
    exitPoint = bed;
    vec3 sun = normalize(osgWater_TowardsSunLocal);
    const vec3 up = vec3(0.0, 0.0, 1.0);
    vec3 back = -refract(-sun, up, osgWater_IOR.x / osgWater_IOR.y);
    if (!(sun.z > 0.0 && back.z > 0.0)) return 0.0;
    float tau = (osgWater_Level - bed.z) / back.z;
    for (int i = 0; i < kHeightSteps; ++i) {
        vec3 p = bed + tau * back;
        tau = (waterHeight(p.xy) - bed.z) / back.z;
    }
    if (!(tau > 0.0)) return 0.0;
    vec3 P = bed + tau * back;
    P.z = waterHeight(P.xy);
    exitPoint = P;
    vec3 exitRay = refract(back, -waterNormal(P.xy), osgWater_IOR.y / osgWater_IOR.x);
    if (!(dot(exitRay, exitRay) > 0.5)) return 0.0;
    vec3 e = normalize(exitRay);
    float angle = atan(length(cross(e, sun)), dot(e, sun)); // precise near 0, unlike acos
    float F = owFresnel(sun.z, osgWater_IOR.x, osgWater_IOR.y, osgWater_FresnelQ);
    return owSunHalo(angle) * (1.0 - F) * exp(-osgWater_PhotonExtinction * length(P - bed));
}
