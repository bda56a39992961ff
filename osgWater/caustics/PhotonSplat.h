/* osgWater - natural water for OpenSceneGraph */
#ifndef OSGWATER_PHOTONSPLAT
#define OSGWATER_PHOTONSPLAT 1

#include <osgWater/Export>
#include <cstddef>
#include <vector>

namespace osgWater {

//! One pass of a gather: the photons moved by (x, y) caustics texels, their energy scaled by
//! `weight`. One unshifted pass, or the 2x2 supersampling's four (kSupersampleShifts).
struct GatherShift {
    float x = 0.0f, y = 0.0f, weight = 1.0f;
};
//! DeepWater's 2x2 supersampling: four passes jittered by a quarter texel each way, each with a
//! quarter of the energy: every caustics texel is sampled at four points instead of its centre.
const GatherShift kSupersampleShifts[4] = { { -0.25f, -0.25f, 0.25f }, { 0.25f, -0.25f, 0.25f },
                                            { -0.25f, 0.25f, 0.25f }, { 0.25f, 0.25f, 0.25f } };
//! A gather's passes for a caustics texture of `size` texels: one unshifted; the supersampling's
//! four; tiled, each of those nine times, moved by a whole tile (`size` texels) each way, so that
//! light landing in a neighbouring tile wraps into this one (DeepWater's nine blits).
OSGWATER_EXPORT std::vector<GatherShift> gatherPasses(bool supersampled, bool tiled, int size);

//! CPU gather of the photon splatting (thesis §8.1, CPU approach), and the mirror of the GPU splat
//! (shaders/splat.vert, splat.frag): each photon (u, v, energy, valid) adds energy * weight to the
//! four texels around (u, v) * size with bilinear (tent) weights that sum to one.
//! `photons` holds count RGBA floats; `caustics` holds size * size floats, row by row (v up), and
//! is accumulated into (clear it first). Photons that are invalid, non-finite or farther than a
//! texture's width off it are dropped (the tiled gather shifts its neighbours' photons in). `shift`: one pass of a supersampled gather.
OSGWATER_EXPORT void splatPhotons(const float* photons, std::size_t count, float weight,
                                  float* caustics, int size, const GatherShift& shift = GatherShift());

//! Concentration cap of the area-ratio mesh: a caustic triangle lit at most this many times the
//! irradiance its surface triangle receives. It guards nearly degenerate triangles (whose area
//! ratio grows without bound) and costs almost no energy: such a triangle covers a texel centre
//! with a probability its area gives.
const float kMaxCausticConcentration = 64.0f;

//! CPU gather of the area-ratio mesh (DeepWater) and the mirror of its GPU path (shaders/splat.*
//! with OSGWATER_AREA_MESH): the photon texels of a `grid` x `grid` target are the vertices of a
//! mesh, two triangles per cell ((i,j) (i+1,j) (i+1,j+1) and (i,j) (i+1,j+1) (i,j+1)), each
//! vertex placed where its photon lands. Every caustics texel whose centre a triangle covers
//! gains the photons' energy interpolated there times the triangle's area ratio, surface over
//! caustic (folded triangles count by their absolute area; triangles of no area are skipped),
//! capped at kMaxCausticConcentration, over `valueScale` (16-bit targets store value / scale).
//! A triangle with a photon that splatPhotons would drop is dropped; a dark photon (energy 0,
//! valid: the sun's ray meets the scene before its water) is kept, and its triangles fade to it.
//! Accumulates into caustics.
//! `shift`: one pass of a supersampled gather. `spacing`: caustics texels between neighbouring
//! samples on the surface (0: size / grid, the photon texels' own; a tile samples its two edges,
//! size / (grid - 1)).
OSGWATER_EXPORT void meshPhotons(const float* photons, int grid, float valueScale, float* caustics, int size,
                                 const GatherShift& shift = GatherShift(), float spacing = 0.0f);

}

#endif
