#version 130
#pragma import_defines(OSGWATER_FRESNEL, OSGWATER_FOG)
// A water met inside another water's pass (its reflection, refraction, sun depth or glow) has no
// passes of its own there: no recursion, nearly no cost. It shows the deep water's body colour
// and, by the Fresnel share, the sky's light (the scene's ambient) it reflects; the host pass's
// fog (eq. 10, the host's eye under water) on top, as on the host's scene.
#pragma include "optics.glsl"
uniform vec3 osgWater_WaterColor;    // this water's body colour
uniform vec2 osgWater_IOR;           // (air, water)
uniform float osgWater_FresnelQ;
uniform vec3 osgWater_Ambient;       // the sky's light, as the scene program uses it
uniform vec3 osgWater_FogColor;      // the host pass's
uniform vec3 osgWater_FogExtinction;
uniform float osgWater_EyeUnit;      // local metres per eye-space unit of the host pass

in vec3 vNormalEye;
in vec3 vEyePos;

void main()
{
    vec3 E = owSafeNormalize(-vEyePos, vec3(0.0, 0.0, 1.0));
    vec3 N = owSafeNormalize(vNormalEye, E);
    // either side alike (a host's mirrored camera sees it from below): no passes, no Snell window
    float F = owFresnel(abs(dot(E, N)), osgWater_IOR.x, osgWater_IOR.y, osgWater_FresnelQ);
    vec3 c = osgWater_WaterColor + F * (osgWater_Ambient - osgWater_WaterColor);
#ifdef OSGWATER_FOG
    vec3 a = exp(-osgWater_FogExtinction * (length(vEyePos) * osgWater_EyeUnit));
    c = osgWater_FogColor + a * (c - osgWater_FogColor);
#endif
    gl_FragColor = vec4(c, 1.0);
}
