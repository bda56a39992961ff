#version 130
// Full-screen triangle (vertices (-1,-1), (3,-1), (-1,3) at NDC depth gl_Vertex.z) for the screen
// passes (the near-plane cap, the underwater backdrop, the glow blur and composite) and the sky. vNear/vFar are
// the pixel's points on the near and far planes in the current model frame (the water's local
// frame), homogeneous: w = 1 at every vertex, so screen-linear interpolation is exact.
out vec4 vNear;
out vec4 vFar;
out vec2 vTex;

void main()
{
    vec2 p = gl_Vertex.xy;
    vNear = gl_ModelViewProjectionMatrixInverse * vec4(p, -1.0, 1.0);
    vFar = gl_ModelViewProjectionMatrixInverse * vec4(p, 1.0, 1.0);
    vTex = p * 0.5 + 0.5;
    gl_Position = vec4(p, gl_Vertex.z, 1.0);
    // never clipped where a pass clips the scene at the water (the sky in the reflection pass)
    gl_ClipDistance[0] = 1.0;
}
