#version 130
#pragma import_defines(OSGWATER_SPLAT_TEXTURE)
// Caustics pass 3 (thesis §8.1, GPU approach): one point per photon, drawn with additive blending
// into the caustics texture. The photon (u, v, energy, valid) is either the vertex itself (the photon
// target copied into a vertex buffer) or read from the photon texture here (OSGWATER_SPLAT_TEXTURE,
// the vertex then holds the photon's texel). Mirrored by osgWater::splatPhotons.
uniform float osgWater_PhotonWeight;   // caustics texels per photon texel: (size_c / size_p)^2
uniform float osgWater_CausticsSize;   // caustics texture size in texels
#ifdef OSGWATER_SPLAT_TEXTURE
uniform sampler2D osgWater_Photons;
#endif

flat out vec3 vPhoton; // (x, y in caustics pixels, energy)

void main()
{
#ifdef OSGWATER_SPLAT_TEXTURE
    vec4 p = texelFetch(osgWater_Photons, ivec2(gl_Vertex.xy), 0);
#else
    vec4 p = gl_Vertex;
#endif
    // NaN fails every comparison: such a photon is dropped like a missing one
    bool ok = p.w > 0.5 && p.z > 0.0 && p.x > -0.01 && p.x < 1.01 && p.y > -0.01 && p.y < 1.01;
    vPhoton = vec3(p.xy * osgWater_CausticsSize, p.z * osgWater_PhotonWeight);
    gl_Position = ok ? vec4(p.xy * 2.0 - 1.0, 0.0, 1.0) : vec4(2.0, 2.0, 2.0, 1.0);
}
