#version 130
#pragma import_defines(OSGWATER_GLOW_TAPS, OSGWATER_GLOW_CUT)
// Glow passes 2 and 3: one axis of a separable Gaussian (weights from GlowPasses::blurWeights).
// The number of taps per side is a define, not a uniform: a software rasteriser runs a loop to
// its static bound whatever a uniform says.
// OSGWATER_GLOW_CUT (the last blur, drawn as the composite's bands under occlusion queries, see
// passes/GlowBands): a texel too faint to show once added is left at the cleared zero, so its band
// counts no fragment and the composite skips it.
uniform sampler2D osgWater_GlowInput;
uniform vec2 osgWater_GlowStep;        // one texel along the blurred axis
uniform float osgWater_GlowWeights[33];

#ifdef OSGWATER_GLOW_CUT
uniform float osgWater_GlowCut;
#endif

in vec2 vTex;

#ifndef OSGWATER_GLOW_TAPS
#define OSGWATER_GLOW_TAPS 0
#endif

void main()
{
    vec3 s = osgWater_GlowWeights[0] * texture(osgWater_GlowInput, vTex).rgb;
    for (int i = 1; i <= OSGWATER_GLOW_TAPS; ++i) {
        vec2 o = float(i) * osgWater_GlowStep;
        s += osgWater_GlowWeights[i] * (texture(osgWater_GlowInput, vTex + o).rgb
                                        + texture(osgWater_GlowInput, vTex - o).rgb);
    }
#ifdef OSGWATER_GLOW_CUT
    if (max(s.r, max(s.g, s.b)) < osgWater_GlowCut) discard;
#endif
    gl_FragColor = vec4(s, 1.0);
}
