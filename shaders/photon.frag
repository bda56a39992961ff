#version 130
#pragma import_defines(OSGWATER_GRID, OSGWATER_FRESNEL, OSGWATER_SEARCH_STEPS, OSGWATER_REFLECTED_PHOTONS, OSGWATER_TILED_PHOTONS)
// Caustics pass 2: one photon per fragment. The sun ray through this texel is refracted at the
// surface, its hit on the bed is found by the same depth-texture search as the refraction
// (here in the sun's depth map, orthographic rays), and the photon is written as
// (u, v, energy, 1): u, v its hit in the sun's texture space, energy = (1 - F) exp(-k d) (k: green) the
// Fresnel-transmitted, attenuated share of the sun irradiance on this texel (thesis §9.2).
// Over the built-in grid the photon starts where the sun's ray through this texel meets the
// analytic waves, with their normal there (the grid's chords would move the waterline on a shore
// by the waves' height over the shore's slope). A photon whose water the sun cannot reach (the
// grid runs on under the dry shore, or a pier stands above it: the sun's shade map shows the scene
// in front of it) is dark: energy 0, not dropped.
// OSGWATER_REFLECTED_PHOTONS (reflective caustics): the sun ray reflected instead, mirrored in the
// water plane so it runs down through the mirrored scene above the water (the depth map's), with
// the reflected share F and no water on its way.
// OSGWATER_TILED_PHOTONS (tileable caustics): the camera looks straight down on one tile of the
// surface; the refracted ray meets a flat bed (a plane) and the photon is (u, v) its hit in tile
// units (beyond [0, 1] when it lands in a neighbouring tile), its energy the share of the sun on
// this texel's piece of surface: (1 - F) (N.L) / (N.z L.z), per area seen from the sun, not yet
// faded (the scene program fades it by each fragment's depth).
#define OSGWATER_ORTHO_DEPTH 1
#pragma include "waves.glsl"
#pragma include "optics.glsl"

uniform vec2 osgWater_IOR;              // (air, water)
uniform float osgWater_PhotonExtinction; // the green channel's sun extinction (the thesis's k)
uniform float osgWater_FresnelQ;
uniform int osgWater_SearchSteps;
uniform float osgWater_ErrorBudget;
#ifdef OSGWATER_REFLECTED_PHOTONS
uniform mat4 osgWater_MirrorEye; // the mirror in the water plane, in this camera's eye space
#endif
#ifdef OSGWATER_TILED_PHOTONS
uniform vec3 osgWater_TileSun;   // towards the sun, in this (straight-down) camera's eye space
uniform vec4 osgWater_TileBed;   // the flat bed in eye space: dot(xyz, p) + w = 0, xyz up
uniform mat4 osgWater_EyeToTile; // eye space -> tile units (x, y)
#endif

in vec3 vLocal;
in vec3 vMeshNormal;
in vec3 vEye;
in float vDrawnError;

#if !defined(OSGWATER_TILED_PHOTONS) && !defined(OSGWATER_REFLECTED_PHOTONS)
#pragma include "sunshade.glsl"
#endif

void main()
{
#ifdef OSGWATER_GRID
    // where the sun's ray through this texel meets the waves, not the grid's chord across them:
    // the waterline on a shore moves with the waves' height
    vec3 towardsSunLocal = normalize(transpose(gl_NormalMatrix) * vec3(0.0, 0.0, 1.0));
    vec3 Nl;
    vec3 U = waterOnSteepLine(vLocal, towardsSunLocal, vDrawnError, Nl);
    vec3 surfaceEye = (gl_ModelViewMatrix * vec4(U, 1.0)).xyz;
#else
    vec3 Nl = owSafeNormalize(vMeshNormal, vec3(0.0, 0.0, 1.0));
    vec3 surfaceEye = vEye;
#endif
#ifdef OSGWATER_TILED_PHOTONS
    vec3 L = osgWater_TileSun;
    const vec3 up = vec3(0.0, 0.0, 1.0); // the surface's up, seen straight down
    vec3 N = owSafeNormalize(gl_NormalMatrix * Nl, up);
    float cosL = dot(N, L);
    vec3 T = refract(-L, N, osgWater_IOR.x / osgWater_IOR.y);
    vec4 photon = vec4(0.0);             // alpha 0: no photon
    float towardsBed = dot(osgWater_TileBed.xyz, T);
    float d = towardsBed < -1e-6 ? -(dot(osgWater_TileBed.xyz, surfaceEye) + osgWater_TileBed.w) / towardsBed : -1.0;
    if (cosL > 0.0 && dot(T, T) > 0.5 && d >= 0.0) {
        float F = owFresnel(cosL, osgWater_IOR.x, osgWater_IOR.y, osgWater_FresnelQ);
        vec2 tc = (osgWater_EyeToTile * vec4(surfaceEye + d * T, 1.0)).xy;
        float share = cosL / max(N.z * L.z, 1e-4); // this texel's surface over its sun-facing area
        // no fade here: the bed under a tile lies at any depth, and the scene program fades the
        // light by the fragment's own (CausticsLighting::channelExtinction)
        photon = vec4(tc, (1.0 - F) * share, 1.0);
    }
#else
    const vec3 L = vec3(0.0, 0.0, 1.0);  // towards the sun, in the sun camera's eye space
    vec3 N = owFaceNormal(owSafeNormalize(gl_NormalMatrix * Nl, L), L, 1e-3);
    float cosL = clamp(dot(N, L), 0.0, 1.0);
#ifdef OSGWATER_REFLECTED_PHOTONS
    vec3 start = (osgWater_MirrorEye * vec4(surfaceEye, 1.0)).xyz;
    vec3 T = mat3(osgWater_MirrorEye) * reflect(-L, N);
#else
    vec3 start = surfaceEye;
    vec3 T = refract(-L, N, osgWater_IOR.x / osgWater_IOR.y);
#endif
    vec4 photon = vec4(0.0);              // alpha 0: no photon
    owBottomHit hit = owIterativeSearch(start, T, osgWater_SearchSteps, osgWater_ErrorBudget);
    vec2 tc;
    if (dot(T, T) > 0.5 && hit.valid && owRefractionTexCoord(hit.W, tc)) {
        float F = owFresnel(cosL, osgWater_IOR.x, osgWater_IOR.y, osgWater_FresnelQ);
#ifdef OSGWATER_REFLECTED_PHOTONS
        photon = vec4(tc, F, 1.0);
#else
        float d = length(hit.A - start);
        // the sun's ray meets the scene before this piece of water (the water's mesh runs on under
        // the shore, or a pier stands above it): a dark photon, kept so that the mesh's triangles
        // fade to the waterline and to the shadow's edge
        photon = vec4(tc, owSunReaches(start) ? (1.0 - F) * exp(-osgWater_PhotonExtinction * d) : 0.0, 1.0);
#endif
    }
#endif
    gl_FragColor = photon;
}
