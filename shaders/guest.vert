#version 130
#pragma import_defines(OSGWATER_GRID)
// A water met inside another water's pass (see guest.frag): its surface in the host pass's eye
// space, clipped by the host pass's plane like the host's scene.
#pragma include "waves.glsl"
uniform vec4 osgWater_ClipPlane; // the host pass's, eye space; active where GL_CLIP_DISTANCE0 is enabled

out vec3 vNormalEye;
out vec3 vEyePos;

void main()
{
    vec4 v = gl_Vertex;
    vec3 n = gl_Normal;
#ifdef OSGWATER_GRID
    v.z = waterHeight(v.xy);
    n = waterNormal(v.xy);
#endif
    vec4 eye = gl_ModelViewMatrix * v;
    vEyePos = eye.xyz / eye.w;
    vNormalEye = gl_NormalMatrix * n;
    gl_ClipDistance[0] = dot(osgWater_ClipPlane, eye);
    gl_Position = gl_ProjectionMatrix * eye;
}
