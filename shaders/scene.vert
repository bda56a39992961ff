#version 130
#pragma import_defines(OSGWATER_FOG, OSGWATER_CAUSTICS)
// The kit's program for the water's scene (the WaterNode's children): textured, lit by one sun,
// and clipped by the pass plane so the reflection and refraction passes split the scene.
// Lit per vertex like the fixed-function pipeline the OBJ loader's materials are made for: with
// the water out of view this program must cost what fixed function costs, and a software
// rasteriser pays for every fragment instruction. Both faces are lit (the fragment picks one).
uniform vec4 osgWater_ClipPlane;  // eye space; only active where GL_CLIP_DISTANCE0 is enabled
uniform vec3 osgWater_SunEye;     // towards the sun, in this pass's eye space
uniform vec3 osgWater_SunColor;
uniform vec3 osgWater_Ambient;

out vec2 vTexCoord;
out vec4 vUnlit;    // emission + ambient; alpha: the material's
out vec3 vSunLit;   // diffuse * sun colour: the direct sun's share before n.l
out vec2 vNdl;      // n.l of the front face and of the back face
#ifdef OSGWATER_CAUSTICS
uniform vec4 osgWater_WaterPlane; // the mean water plane in eye space, > 0 above the water
uniform mat4 osgWater_EyeToSun;   // eye space -> the sun camera's texture space (caustics, shadows)
out vec3 vSun;
out float vAboveWater;
#endif
#ifdef OSGWATER_FOG
out vec3 vEyePos;
#endif

void main()
{
    vec4 eye = gl_ModelViewMatrix * gl_Vertex;
    vec3 n = gl_NormalMatrix * gl_Normal;
    float l2 = dot(n, n);
    float ndl = l2 > 1e-20 ? dot(n, osgWater_SunEye) * inversesqrt(l2) : 1.0; // no normal: lit fully
    vNdl = vec2(max(ndl, 0.0), l2 > 1e-20 ? max(-ndl, 0.0) : 1.0);
    vUnlit = vec4(gl_FrontMaterial.emission.rgb + gl_FrontMaterial.ambient.rgb * osgWater_Ambient,
                  gl_FrontMaterial.diffuse.a);
    vSunLit = gl_FrontMaterial.diffuse.rgb * osgWater_SunColor;
    vTexCoord = (gl_TextureMatrix[0] * gl_MultiTexCoord0).st;
#ifdef OSGWATER_CAUSTICS
    vSun = (osgWater_EyeToSun * eye).xyz; // orthographic: w stays 1
    vAboveWater = dot(osgWater_WaterPlane, eye);
#endif
#ifdef OSGWATER_FOG
    vEyePos = eye.xyz / eye.w;
#endif
    gl_ClipDistance[0] = dot(osgWater_ClipPlane, eye);
    gl_Position = gl_ProjectionMatrix * eye;
}
