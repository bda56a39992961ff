#version 130
#pragma import_defines(OSGWATER_GRID)
// The water surface, in the WaterNode's local frame (z up).
#pragma include "waves.glsl"

out vec3 vLocal;
out vec3 vMeshNormal;

void main()
{
    vec4 v = gl_Vertex;
#ifdef OSGWATER_GRID
    v.z = waterHeight(v.xy);
#endif
    vLocal = v.xyz;
    vMeshNormal = gl_Normal;
    gl_Position = gl_ModelViewProjectionMatrix * v;
}
