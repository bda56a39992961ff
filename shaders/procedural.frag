#version 130
#pragma import_defines(OSGWATER_FRESNEL, OSGWATER_PROCEDURAL_SHADE)
// Procedural caustics drawn into the caustics texture (the paper's texture-space variant), no
// photons: each texel of the sun's window takes the bed point the sun's depth map shows there (the
// underwater scene) and the construction of procedural.glsl, dark where the sun cannot reach the
// water above it (the shade map: a pier, the shore).
#define OSGWATER_ORTHO_DEPTH 1
#pragma include "waves.glsl"
#pragma include "optics.glsl"
#pragma include "procedural.glsl"
#ifdef OSGWATER_PROCEDURAL_SHADE
#pragma include "sunshade.glsl"
#endif

uniform sampler2D osgWater_SunBedDepth; // the underwater scene's depth seen from the sun
uniform mat4 osgWater_SunTexToLocal;    // the sun's texture space (u, v, depth) -> water-local
uniform mat4 osgWater_SunView;          // water-local -> the sun camera's eye space
uniform float osgWater_ProceduralScale; // stored texel = value * scale

in vec2 vTex;

void main()
{
    float value = 0.0;
    float depth = owDepthBetweenTexels(osgWater_SunBedDepth, vTex);
    if (depth < 1.0) {
        vec4 b = osgWater_SunTexToLocal * vec4(vTex, depth, 1.0);
        vec3 exitPoint;
        value = owProceduralLight(b.xyz / b.w, exitPoint);
#ifdef OSGWATER_PROCEDURAL_SHADE
        // the sun's ray meets the scene before this water (a pier above it, the shore): dark
        if (value > 0.0 && !owSunReaches((osgWater_SunView * vec4(exitPoint, 1.0)).xyz)) value = 0.0;
#endif
    }
    gl_FragColor = vec4(value * osgWater_ProceduralScale);
}
