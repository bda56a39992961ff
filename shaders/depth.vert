#version 130
// Depth-only passes (the sun's depth map): the scene's positions exactly as scene.vert computes
// them, clipped by the pass plane; nothing is shaded.
uniform vec4 osgWater_ClipPlane; // eye space

void main()
{
    vec4 eye = gl_ModelViewMatrix * gl_Vertex;
    gl_ClipDistance[0] = dot(osgWater_ClipPlane, eye);
    gl_Position = gl_ProjectionMatrix * eye;
}
