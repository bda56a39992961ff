#version 130
// The kit's program for the water's scene (the WaterNode's children): textured, lit by one sun,
// and clipped by the pass plane so the reflection and refraction passes split the scene.
uniform vec4 osgWater_ClipPlane;  // eye space; only active where GL_CLIP_DISTANCE0 is enabled
uniform vec4 osgWater_WaterPlane; // the mean water plane in eye space, > 0 above the water
uniform mat4 osgWater_EyeToSun;   // eye space -> the sun camera's texture space (caustics, shadows)

out vec3 vNormalEye;
out vec2 vTexCoord;
out vec3 vSun;
out float vAboveWater;
out vec3 vEyePos;

void main()
{
    vec4 eye = gl_ModelViewMatrix * gl_Vertex;
    vNormalEye = gl_NormalMatrix * gl_Normal;
    vTexCoord = (gl_TextureMatrix[0] * gl_MultiTexCoord0).st;
    vEyePos = eye.xyz / eye.w;
    vSun = (osgWater_EyeToSun * eye).xyz; // orthographic: w stays 1
    vAboveWater = dot(osgWater_WaterPlane, eye);
    gl_ClipDistance[0] = dot(osgWater_ClipPlane, eye);
    gl_Position = gl_ProjectionMatrix * eye;
}
