#version 130
#pragma import_defines(OSGWATER_DISPLAY, OSGWATER_FOG, OSGWATER_CAUSTICS, OSGWATER_CAUSTICS_CHANNELS, OSGWATER_CAUSTICS_TILED, OSGWATER_CAUSTICS_PROCEDURAL, OSGWATER_PROCEDURAL_SHADE, OSGWATER_FRESNEL, OSGWATER_REFLECTED_CAUSTICS, OSGWATER_TRUE_POSITIONS)
// Fixed-function look of the OBJ loader's geometry: material * texture, one sun + ambient, lit per
// vertex (scene.vert). Variants by pass, never branches (a software rasteriser runs both sides):
// - OSGWATER_CAUSTICS, where the pass can see below the water and caustics are on: under water the
//   direct sun is the caustic irradiance of the photon pass (thesis ch. 8), and zero where the
//   sun's depth map shows something between the fragment and the surface (underwater shadows);
//   OSGWATER_CAUSTICS_TILED: the caustics of one tile, repeated (the depth map where it reaches);
//   OSGWATER_CAUSTICS_PROCEDURAL: the procedural caustics made here, per fragment (procedural.glsl);
// - OSGWATER_REFLECTED_CAUSTICS, where the pass sees above the water and reflective caustics are
//   on: above the water the sun reflected off it adds its irradiance from the sun's mirror image;
// - OSGWATER_FOG, where the pass's eye is under water: everything is seen through water, its
//   colour blended towards the water colour by the distance from this pass's eye (eq. 10);
// - OSGWATER_TRUE_POSITIONS, the refraction pass drawing virtual vertices for the debug output:
//   the fragment's true place in the water's local frame (a float target), alpha 1;
// - OSGWATER_DISPLAY, the view itself: the linear light is encoded for display (srgb.glsl); every
//   other pass (reflection, refraction, environment) keeps it linear for the water to sum.
// The texture's texels are sRGB display values, decoded after filtering.
#pragma include "srgb.glsl"
uniform sampler2D osgWater_BaseTexture; // a white texel when the geometry has none

in vec2 vTexCoord;
in vec4 vUnlit;
in vec3 vSunLit;
in vec2 vNdl;
#ifdef OSGWATER_TRUE_POSITIONS
in vec3 vTrueLocal;
#endif

#ifdef OSGWATER_CAUSTICS_PROCEDURAL
#define OSGWATER_ORTHO_DEPTH 1
#pragma include "waves.glsl"
#pragma include "optics.glsl"
#pragma include "procedural.glsl"
#ifdef OSGWATER_PROCEDURAL_SHADE
#pragma include "sunshade.glsl"
#endif
#endif
#if defined(OSGWATER_CAUSTICS) || defined(OSGWATER_REFLECTED_CAUSTICS)
#pragma include "caustics.glsl"
#endif
#ifdef OSGWATER_FOG
uniform vec3 osgWater_FogColor;      // the water's body colour ...
uniform vec3 osgWater_FogExtinction; // ... and its extinction per channel
uniform float osgWater_EyeUnit;      // local metres per eye-space unit (1 unless the water is scaled)
in vec3 vEyePos;
#endif

void main()
{
    vec4 tex = texture(osgWater_BaseTexture, vTexCoord);
    float ndl = gl_FrontFacing ? vNdl.x : vNdl.y;
#ifdef OSGWATER_CAUSTICS
    vec3 c = vUnlit.rgb + vSunLit * (ndl * owUnderwaterSun(ndl));
#else
    vec3 c = vUnlit.rgb + vSunLit * ndl;
#endif
#ifdef OSGWATER_REFLECTED_CAUSTICS
    float ndlR = gl_FrontFacing ? vNdlR.x : vNdlR.y;
    c += vSunLit * (ndlR * owReflectedSun(ndlR));
#endif
    c *= owDecodeSrgb(tex.rgb);
#ifdef OSGWATER_FOG
    vec3 a = exp(-osgWater_FogExtinction * (length(vEyePos) * osgWater_EyeUnit)); // eq. 4 with d = |A - C|, per channel
    c = osgWater_FogColor + a * (c - osgWater_FogColor);     // eq. 10
#endif
#ifdef OSGWATER_TRUE_POSITIONS
    gl_FragColor = vec4(vTrueLocal, 1.0);
#elif defined(OSGWATER_DISPLAY)
    gl_FragColor = vec4(owDisplay(c), vUnlit.a * tex.a);
#else
    gl_FragColor = vec4(c, vUnlit.a * tex.a);
#endif
}
