#version 130
#pragma import_defines(OSGWATER_FOG, OSGWATER_CAUSTICS_CHANNELS)
// Fixed-function look of the OBJ loader's geometry: material * texture, one sun + ambient.
// Under water, where caustics are on, the direct sun is the caustic irradiance of the photon pass
// (thesis ch. 8), and zero where the sun's depth map shows something between the fragment and the
// surface (underwater shadows). With the eye under water everything is seen through water: its
// colour is blended towards the water colour by the distance from this pass's eye (eq. 10).
#pragma include "caustics.glsl"
uniform sampler2D osgWater_BaseTexture; // unit 0; a white texel when the geometry has none
uniform vec3 osgWater_SunEye;           // towards the sun, in this pass's eye space
uniform vec3 osgWater_SunColor;
uniform vec3 osgWater_Ambient;
uniform vec3 osgWater_FogColor;         // the water's body colour ...
uniform vec3 osgWater_FogExtinction;    // ... and its extinction per channel; 0: no water between eye and fragment
uniform float osgWater_EyeUnit;         // local metres per eye-space unit (1 unless the water is scaled)

in vec3 vNormalEye;
in vec2 vTexCoord;
in vec3 vEyePos;

void main()
{
    vec4 tex = texture(osgWater_BaseTexture, vTexCoord);
    float l2 = dot(vNormalEye, vNormalEye);
    vec3 n = l2 > 1e-20 ? vNormalEye * inversesqrt(l2) : osgWater_SunEye;
    if (!gl_FrontFacing) n = -n;
    float ndl = max(dot(n, osgWater_SunEye), 0.0);
    vec3 sun = owUnderwaterSun(ndl);
    vec3 c = gl_FrontMaterial.emission.rgb
           + gl_FrontMaterial.ambient.rgb * osgWater_Ambient
           + gl_FrontMaterial.diffuse.rgb * osgWater_SunColor * (ndl * sun);
    c *= tex.rgb;
#ifdef OSGWATER_FOG
    vec3 a = exp(-osgWater_FogExtinction * (length(vEyePos) * osgWater_EyeUnit)); // eq. 4 with d = |A - C|, per channel
    c = osgWater_FogColor + a * (c - osgWater_FogColor);     // eq. 10
#endif
    gl_FragColor = vec4(c, gl_FrontMaterial.diffuse.a * tex.a);
}
