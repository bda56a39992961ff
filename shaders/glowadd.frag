#version 130
// Glow pass 4: the blurred highlight added to the view (blend ONE, ONE).
uniform sampler2D osgWater_GlowTex;
uniform float osgWater_GlowIntensity;

in vec2 vTex;

void main()
{
    gl_FragColor = vec4(osgWater_GlowIntensity * texture(osgWater_GlowTex, vTex).rgb, 0.0);
}
