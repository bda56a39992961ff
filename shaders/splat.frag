#version 130
#pragma import_defines(OSGWATER_AREA_MESH)
#ifdef OSGWATER_AREA_MESH
// The area-ratio mesh (DeepWater): a caustic triangle receives the energy its surface triangle
// transmits, spread over its own area, so each texel it covers gains energy * area(surface) /
// area(caustic). The screen derivatives of the surface position give that ratio exactly (it is
// linear over the triangle): |det d(source)/d(pixel)|; a fold (a flipped triangle) counts by its
// absolute area. Capped like osgWater::meshPhotons (kMaxCausticConcentration).
uniform float osgWater_PhotonWeight;
uniform float osgWater_CausticsSize;
uniform float osgWater_PhotonGrid;
noperspective in vec2 vSource;
noperspective in float vEnergy;
noperspective in float vDropped;

void main()
{
    // derivatives first: after a discard they are undefined in the 2x2 quad
    vec2 dx = dFdx(vSource), dy = dFdy(vSource);
    if (vDropped > 0.0) discard;
    float ratio = abs(dx.x * dy.y - dx.y * dy.x);
    ratio = ratio < 64.0 ? ratio : 64.0; // NaN and Inf capped too
    // the stored value's scale (16-bit targets): the photon weight over its area factor
    float cell = osgWater_CausticsSize / osgWater_PhotonGrid;
    gl_FragColor = vec4(vEnergy * ratio * osgWater_PhotonWeight / (cell * cell), 0.0, 0.0, 1.0);
}
#else
// Bilinear (tent) splat: a 2x2-pixel point covers exactly the four texels around the photon, and
// their weights sum to one, so energy is conserved and a uniform photon lattice gives a uniform
// texture.
flat in vec3 vPhoton;

void main()
{
    vec2 w = max(vec2(1.0) - abs(gl_FragCoord.xy - vPhoton.xy), vec2(0.0));
    gl_FragColor = vec4(vPhoton.z * w.x * w.y, 0.0, 0.0, 1.0);
}
#endif
