#version 130
#pragma import_defines(OSGWATER_GRID)
// Caustics pass 2 (thesis §8.1, §9.2): the water surface seen from the sun's orthographic camera.
#pragma include "waves.glsl"

out vec3 vLocal;
out vec3 vMeshNormal;
out vec3 vEye; // the sun camera's eye space
out float vDrawnError; // how far the drawn grid can lie from the analytic surface here, metres
#ifdef OSGWATER_GRID
uniform float osgWater_GridCell; // the uniform grid's spacing, metres
#endif

void main()
{
    vec4 v = gl_Vertex;
#ifdef OSGWATER_GRID
    v.z = waterHeight(v.xy);
    vDrawnError = waterDrawnErrorBound(osgWater_GridCell, false);
#else
    vDrawnError = 0.0;
#endif
    vLocal = v.xyz;
    vMeshNormal = gl_Normal;
    vEye = (gl_ModelViewMatrix * v).xyz;
    gl_Position = gl_ProjectionMatrix * vec4(vEye, 1.0);
}
