#version 130
#pragma import_defines(OSGWATER_SPLAT_TEXTURE, OSGWATER_AREA_MESH)
// Caustics pass 3 (thesis §8.1, GPU approach), drawn with additive blending into the caustics
// texture. The photon (u, v, energy, valid) is either the vertex itself (the photon target copied
// into a vertex buffer) or read from the photon texture here (OSGWATER_SPLAT_TEXTURE, the vertex
// then holds the photon's texel). Either one point per photon (a tent splat, mirrored by
// osgWater::splatPhotons) or, OSGWATER_AREA_MESH, one vertex of the area-ratio mesh per photon
// (mirrored by osgWater::meshPhotons).
uniform float osgWater_PhotonWeight;   // caustics texels per photon texel: (size_c / size_p)^2
uniform float osgWater_CausticsSize;   // caustics texture size in texels
uniform float osgWater_PhotonGrid;     // photon target size in texels
uniform vec3 osgWater_GatherShift;     // this pass's shift (x, y caustics texels) and energy weight (2x2 supersampling)
uniform float osgWater_SampleSpacing;  // the mesh: caustics texels between neighbouring surface samples
#ifdef OSGWATER_SPLAT_TEXTURE
uniform sampler2D osgWater_Photons;
#endif

#ifdef OSGWATER_AREA_MESH
noperspective out vec2 vSource;  // where the sample sits on the surface, in caustics texels (up to a shift)
noperspective out float vEnergy;
noperspective out float vDropped; // 0 at a photon, huge at a dropped one: any triangle with one is discarded
#else
flat out vec3 vPhoton; // (x, y in caustics pixels, energy)
#endif

void main()
{
#ifdef OSGWATER_SPLAT_TEXTURE
    vec2 texel = gl_Vertex.xy;
    vec4 p = texelFetch(osgWater_Photons, ivec2(texel), 0);
#else
    int grid = int(osgWater_PhotonGrid);
    vec2 texel = vec2(gl_VertexID % grid, gl_VertexID / grid); // the index drawn: the photon's texel
    vec4 p = gl_Vertex;
#endif
    // NaN fails every comparison: such a photon is dropped like a missing one; one that landed on
    // a neighbouring tile is kept (the tiled gather shifts it in), and so is a dark one (energy 0:
    // the sun meets the scene before its water), so that the mesh's triangles fade to it
    bool ok = p.w > 0.5 && p.z >= 0.0 && p.x > -1.01 && p.x < 2.01 && p.y > -1.01 && p.y < 2.01;
#ifdef OSGWATER_AREA_MESH
    vec2 straightDown = (texel + 0.5) / osgWater_PhotonGrid; // where the sun ray lands unrefracted
    vSource = texel * osgWater_SampleSpacing;
    vEnergy = ok ? p.z * osgWater_GatherShift.z : 0.0;
    vDropped = ok ? 0.0 : 1e7;
    // a dropped vertex stays near its neighbours, so that its triangles cost few discarded fragments
    vec2 at = (ok ? p.xy : straightDown) + osgWater_GatherShift.xy / osgWater_CausticsSize;
    gl_Position = vec4(at * 2.0 - 1.0, 0.0, 1.0);
#else
    vec2 at = p.xy + osgWater_GatherShift.xy / osgWater_CausticsSize;
    vPhoton = vec3(at * osgWater_CausticsSize, p.z * osgWater_PhotonWeight * osgWater_GatherShift.z);
    // a dark photon adds nothing to a splat: it is not drawn
    gl_Position = ok && p.z > 0.0 ? vec4(at * 2.0 - 1.0, 0.0, 1.0) : vec4(2.0, 2.0, 2.0, 1.0);
#endif
}
