#version 130
// Glow passes 2 and 3: one axis of a separable Gaussian (weights from GlowPasses::blurWeights).
uniform sampler2D osgWater_GlowInput;
uniform vec2 osgWater_GlowStep;        // one texel along the blurred axis
uniform float osgWater_GlowWeights[33];
uniform int osgWater_GlowTaps;

in vec2 vTex;

void main()
{
    vec3 s = osgWater_GlowWeights[0] * texture(osgWater_GlowInput, vTex).rgb;
    for (int i = 1; i <= 32; ++i) {
        if (i > osgWater_GlowTaps) break;
        vec2 o = float(i) * osgWater_GlowStep;
        s += osgWater_GlowWeights[i] * (texture(osgWater_GlowInput, vTex + o).rgb
                                        + texture(osgWater_GlowInput, vTex - o).rgb);
    }
    gl_FragColor = vec4(s, 1.0);
}
