#version 130
// Bilinear (tent) splat: a 2x2-pixel point covers exactly the four texels around the photon, and
// their weights sum to one, so energy is conserved and a uniform photon lattice gives a uniform
// texture.
flat in vec3 vPhoton;

void main()
{
    vec2 w = max(vec2(1.0) - abs(gl_FragCoord.xy - vPhoton.xy), vec2(0.0));
    gl_FragColor = vec4(vPhoton.z * w.x * w.y, 0.0, 0.0, 1.0);
}
