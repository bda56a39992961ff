// The image a view should show, by Whitted ray tracing with the kit's shading model, on the exact
// machinery of the reference (the waves in double precision, Embree over the scene's triangles):
// - at the water, the facet the ray meets is the waves' normal tilted by a slope drawn from the
//   roughness there (Reference::roughnessAt: what the kit shades as roughness at a point, the slopes
//   the interpolation between the wind's texels and its cascades do not show; 0 for the sum of
//   waves), so that many rays a pixel see the spread the kit's shading integrates;
// - there the ray splits by exact unpolarised Fresnel into its mirror ray and Snell's
//   refracted ray (none under total internal reflection), each followed on, through further
//   meetings with the water, up to a limit of water hits per path (past it the ray goes on as if
//   the water were not there);
// - a scene point has the scene program's colour (SceneShading);
// - a stretch under water is seen through the water as the kit sees it: blended towards its body
//   colour by the per-channel extinction over its length (eq. 10), the body colour itself where the
//   ray meets nothing;
// - a ray in the air that meets nothing has the sky's light: the WaterNode's osgWater::Sky, else
//   the view's clear colour.
// All in linear light; the view shows it exposed, through the tone curve, encoded.
// The water is met where WaterSurface::intersect meets it: its steps cannot pass a crossing by the
// waves' slope and curvature bounds, so a ray that clips a crest meets it.
#pragma once
#include "Reference.h"
#include "SceneShading.h"
#include <osg/Vec4>
#include <cstdint>
#include <functional>
#include <vector>

namespace osgWater { class WaterNode; }

namespace bench {

//! What the reference image is made with, besides the geometry.
struct ImageSetup {
    SceneLight light;
    glm::dvec3 body{ 0.0 };       //!< the water's body colour, linear (WaterSettings::getBodyColor)
    glm::dvec3 extinction{ 0.0 }; //!< per metre, per channel (WaterSettings::getViewExtinction)
    std::function<glm::dvec3(const glm::dvec3&)> sky; //!< linear light along a ray in the air that meets nothing
    int maxWaterHits = 8;         //!< water meetings followed per path
    int samplesPerAxis = 1;       //!< a pixel's light: the mean over n x n rays through a grid's cell centres
    //! Where a pixel's two halves of rays (see render) differ by more than refineAbove in a channel
    //! (linear light), m x m more rays through another grid's cell centres (0: none): the far
    //! water's sub-pixel waves, not the image's smooth parts, take the extra rays.
    int refineSamplesPerAxis = 0;
    double refineAbove = 0.01;
};

//! A facet a ray meets where the waves' unit upward normal is `waves` and the slopes below it have
//! `variance` (each axis half of it, Gaussian): its normal, drawn in proportion to the area it shows
//! the ray (never one turned away), so that the mean over many draws is the mean over the facets as
//! the ray sees them: what the kit's shading integrates (owFresnelAndLean). The draw is a function of
//! `seed` alone (a ray's own bits: the image does not depend on which thread traced it). `met` is
//! false only for a ray that grazes the level so closely that no facet shows; `waves` itself without
//! roughness.
struct FacetDraw {
    glm::dvec3 normal;
    bool met;
};
FacetDraw drawFacet(const glm::dvec3& waves, double variance, const glm::dvec3& dir, std::uint64_t seed);

//! What render can say besides the image.
struct RenderExtras {
    //! The mean of each half of every pixel's rays, the grids' cells split as a checkerboard's: two
    //! independent estimates whose difference measures the image's own noise (2 x 2 rays or more).
    std::vector<glm::vec3> halves[2];
    size_t refinedPixels = 0; //!< pixels that took the refining rays
};

//! The setup of a water node's scene: its sun, ambient and water, and its sky (an osgWater::Sky
//! child, else `clearColour`, a display value, decoded).
ImageSetup imageSetup(const osgWater::WaterNode& water, const osg::Vec4& clearColour);

class ReferenceRenderer
{
public:
    //! `shading` was collected with the scene's triangles `ref` casts against.
    ReferenceRenderer(const Reference& ref, const SceneShading& shading, ImageSetup setup);
    //! The linear light arriving at `org` along unit `dir`, the ray starting in the water or not.
    glm::dvec3 radiance(const glm::dvec3& org, const glm::dvec3& dir, bool inWater) const;
    //! Every pixel of a view (row 0 at the bottom): the mean light of samplesPerAxis^2 rays through it,
    //! linear (single precision: a view's worth is kept per view for every technique); the eye's
    //! medium from the wave at its place; the noisy pixels refined (ImageSetup::refineSamplesPerAxis).
    std::vector<glm::vec3> render(const osg::Matrixd& viewMatrix, const osg::Matrixd& projection, int width,
                                   int height, RenderExtras* extras = nullptr) const;

private:
    glm::dvec3 follow(const glm::dvec3& org, const glm::dvec3& dir, bool inWater, int waterHits) const;
    const Reference& _ref;
    const SceneShading& _shading;
    ImageSetup _setup;
};

}
