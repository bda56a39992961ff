#version 130
// The water surface (thesis ch. 7, §9.1): shaded by watershade.glsl where the fragment's line of
// sight meets the surface (the analytic waves over the built-in mesh, the mesh itself otherwise).
// Everything is in the WaterNode's local frame (z up) unless it says eye space.
#pragma include "waves.glsl"
#pragma include "watershade.glsl"

in vec3 vLocal;
in vec3 vMeshNormal;
in float vDrawnError;

void main()
{
#ifdef OSGWATER_GRID
    vec3 N;
#ifdef OSGWATER_EYE_BELOW
    const float eyeSide = -1.0;
#else
    const float eyeSide = 1.0;
#endif
#ifdef OSGWATER_WIND
    // the wind's cascades read at the pixel's footprint on the water
    waterFootprint = waterFootprintOf(dFdx(vLocal.xy), dFdy(vLocal.xy));
#endif
    float roughness;
    vec3 U = waterOnSightRay(osgWater_EyeLocal, vLocal, vDrawnError, eyeSide, N, roughness);
#else
    const float roughness = 0.0; // a user's mesh: its normals are what there is
    vec3 U = vLocal;
    vec3 N = owSafeNormalize(vMeshNormal, vec3(0.0, 0.0, 1.0));
#endif
    vec3 E = owSafeNormalize(osgWater_EyeLocal - U, vec3(0.0, 0.0, 1.0));
    vec4 debugHit;
    vec3 color = owShadeWater(U, N, E, roughness, debugHit);
    gl_FragColor = owWaterFragment(U, vLocal, N, roughness, color, debugHit);
}
