#version 130
#pragma import_defines(OSGWATER_FOG, OSGWATER_CAUSTICS, OSGWATER_CAUSTICS_TILED, OSGWATER_REFLECTED_CAUSTICS, OSGWATER_CAUSTICS_PROCEDURAL, OSGWATER_VIRTUAL_VERTICES, OSGWATER_TRUE_POSITIONS)
// The kit's program for the water's scene (the WaterNode's children): textured, lit by one sun,
// and clipped by the pass plane so the reflection and refraction passes split the scene.
// The material's colours are sRGB display values (as OBJ/MTL files write them), decoded here: the
// lighting is summed in linear light (srgb.glsl).
// Lit per vertex like the fixed-function pipeline the OBJ loader's materials are made for: with
// the water out of view this program must cost what fixed function costs, and a software
// rasteriser pays for every fragment instruction. Both faces are lit (the fragment picks one).
// OSGWATER_VIRTUAL_VERTICES (the refraction pass from above, WaterSettings::VIRTUAL_VERTICES):
// each vertex is drawn at its virtual vertex, where it appears through the waves; everything else
// (lighting, caustics, clipping) follows its true place. OSGWATER_TRUE_POSITIONS with it: the
// fragment writes its true place (local frame) instead of a colour, for the debug output.
#pragma include "srgb.glsl"
uniform vec4 osgWater_ClipPlane;  // eye space; only active where GL_CLIP_DISTANCE0 is enabled
uniform vec3 osgWater_SunEye;     // towards the sun, in this pass's eye space
uniform vec3 osgWater_SunColor;
uniform vec3 osgWater_Ambient;

out vec2 vTexCoord;
out vec4 vUnlit;    // emission + ambient; alpha: the material's
out vec3 vSunLit;   // diffuse * sun colour: the direct sun's share before n.l
out vec2 vNdl;      // n.l of the front face and of the back face
#if defined(OSGWATER_CAUSTICS) || defined(OSGWATER_REFLECTED_CAUSTICS)
uniform vec4 osgWater_WaterPlane; // the mean water plane in eye space, > 0 above the water
out float vAboveWater;
#endif
#ifdef OSGWATER_CAUSTICS
uniform mat4 osgWater_EyeToSun;   // eye space -> the sun camera's texture space (caustics, shadows)
out vec3 vSun;
#endif
#ifdef OSGWATER_CAUSTICS_TILED
uniform mat4 osgWater_EyeToTile;  // eye space -> tile units (tileable caustics; the texture wraps)
out vec2 vTile;
#endif
#if defined(OSGWATER_CAUSTICS_PROCEDURAL) || defined(OSGWATER_VIRTUAL_VERTICES)
uniform mat4 osgWater_EyeToLocal; // this pass's eye space -> the water's local frame
#endif
#ifdef OSGWATER_CAUSTICS_PROCEDURAL
out vec3 vLocal;                  // the fragment's place for the procedural caustics
#endif
#ifdef OSGWATER_REFLECTED_CAUSTICS
uniform mat4 osgWater_EyeToReflectedSun; // eye space -> mirrored in the water plane -> the reflected sun's texture space
uniform vec3 osgWater_ReflectedSunEye;   // towards the sun's mirror image under the water, eye space
out vec3 vSunR;
out vec2 vNdlR;   // n.l of the front and back faces for the reflected sun
#endif
#ifdef OSGWATER_FOG
out vec3 vEyePos;
#endif
#ifdef OSGWATER_VIRTUAL_VERTICES
#pragma include "virtualvertex.glsl"
#endif
#ifdef OSGWATER_TRUE_POSITIONS
out vec3 vTrueLocal;
#endif

void main()
{
    vec4 eye = gl_ModelViewMatrix * gl_Vertex;
    vec3 n = gl_NormalMatrix * gl_Normal;
    float l2 = dot(n, n);
    float ndl = l2 > 1e-20 ? dot(n, osgWater_SunEye) * inversesqrt(l2) : 1.0; // no normal: lit fully
    vNdl = vec2(max(ndl, 0.0), l2 > 1e-20 ? max(-ndl, 0.0) : 1.0);
    vUnlit = vec4(owDecodeSrgb(gl_FrontMaterial.emission.rgb) + owDecodeSrgb(gl_FrontMaterial.ambient.rgb) * osgWater_Ambient,
                  gl_FrontMaterial.diffuse.a);
    vSunLit = owDecodeSrgb(gl_FrontMaterial.diffuse.rgb) * osgWater_SunColor;
    vTexCoord = (gl_TextureMatrix[0] * gl_MultiTexCoord0).st;
#if defined(OSGWATER_CAUSTICS) || defined(OSGWATER_REFLECTED_CAUSTICS)
    vAboveWater = dot(osgWater_WaterPlane, eye);
#endif
#ifdef OSGWATER_CAUSTICS
    vSun = (osgWater_EyeToSun * eye).xyz; // orthographic: w stays 1
#endif
#ifdef OSGWATER_CAUSTICS_TILED
    vTile = (osgWater_EyeToTile * eye).xy;
#endif
#ifdef OSGWATER_CAUSTICS_PROCEDURAL
    vLocal = (osgWater_EyeToLocal * eye).xyz;
#endif
#ifdef OSGWATER_REFLECTED_CAUSTICS
    float ndlR = l2 > 1e-20 ? dot(n, osgWater_ReflectedSunEye) * inversesqrt(l2) : 0.0;
    vNdlR = vec2(max(ndlR, 0.0), max(-ndlR, 0.0));
    vSunR = (osgWater_EyeToReflectedSun * eye).xyz;
#endif
#ifdef OSGWATER_FOG
    vEyePos = eye.xyz / eye.w;
#endif
    gl_ClipDistance[0] = dot(osgWater_ClipPlane, eye);
#ifdef OSGWATER_VIRTUAL_VERTICES
    vec3 trueLocal = (osgWater_EyeToLocal * eye).xyz;
    vec3 eyeLocal = osgWater_EyeToLocal[3].xyz;
    gl_Position = gl_ProjectionMatrix * (osgWater_LocalToEye * vec4(vvVirtualVertex(eyeLocal, trueLocal), 1.0));
#ifdef OSGWATER_TRUE_POSITIONS
    vTrueLocal = trueLocal;
#endif
#else
    gl_Position = gl_ProjectionMatrix * eye;
#endif
}
