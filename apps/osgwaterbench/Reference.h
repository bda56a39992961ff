// The exact reference of one view (thesis and DESIGN §5): per pixel, the eye ray's hit on the
// water, Snell's refracted ray and its hit, the mirror ray and its hit, exact unpolarised Fresnel
// and the path length under water; from below with the indices swapped and total internal
// reflection. Everything in the water's local frame, in double precision per ray.
#pragma once
#include "WaterCaster.h"
#include <osg/Matrixd>
#include <glm/mat2x3.hpp>
#include <glm/vec2.hpp>
#include <cstdint>
#include <functional>

namespace osgWater { class WaterSurface; }

namespace bench {

//! Indices of refraction of the two media.
struct Media {
    double air = 1.0, water = 1.333;
};

//! Snell's refracted direction of unit d at unit normal n facing against d (dot(d, n) < 0), from
//! index n1 into n2; false under total internal reflection.
bool snell(const glm::dvec3& d, const glm::dvec3& n, double n1, double n2, glm::dvec3& out);
//! Exact unpolarised Fresnel reflectance for incidence cosine cosI from n1 into n2 (1 under TIR).
double fresnelExact(double cosI, double n1, double n2);

//! One pixel's reference, in double precision.
struct PixelTrace {
    bool water = false;      //!< the eye ray meets the water surface before anything else
    bool below = false;      //!< the eye is under water
    bool tir = false;        //!< total internal reflection (from below)
    glm::dvec3 U{ 0.0 }, N{ 0.0 }; //!< surface point, unit normal facing the eye
    glm::dvec3 R{ 0.0 }, Rr{ 0.0 }; //!< refracted and mirrored directions
    Hit refracted, reflected;
    double fresnel = 0.0;
    double underwaterPath = 0.0; //!< from above: |X - U|; from below: |eye - U|
    bool reflectionShown = false; //!< the reflection pass can show the mirror ray's hit (reflectionPassShows)
};

//! Whether the reflection pass (the eye mirrored in the water's level, drawing the eye's side of it:
//! above it, or below for an eye `below` the water) has in view the hit of a mirror ray along Rr
//! (`reflected`; on a miss the sky along Rr): the hit lies on that side and is the first thing on
//! the mirrored eye's line of sight there. Where it is not, no lookup in the reflection texture can
//! find it (hidden behind a shore, or a ray sent back under the level).
bool reflectionPassShows(const RayCaster& scene, double level, const glm::dvec3& eye, bool below, const Hit& reflected,
                         const glm::dvec3& Rr);

class Reference;

//! Where a pixel's own rays, through the centres of its four quarters, lead. Over waves shorter
//! than the pixel they fan out, and no single lookup can be nearer all of them than the fan is wide.
struct PixelFan {
    //! The largest angle (radians) between the quarters' mirror sights (Reference::mirrorSight); pi
    //! where some of them miss the water.
    double mirrorSpread = 3.141592653589793;
    //! Every quarter meets the water and its refracted ray meets the scene: X holds those hits.
    bool refracted = false;
    glm::dvec3 X[4];
};
PixelFan pixelFan(const Reference& ref, const glm::dvec3& eye, const glm::dvec3 quarterDirs[4]);

class Reference
{
public:
    Reference(const RayCaster& scene, const WaterCaster& water, const osgWater::WaterSurface& surface, double t,
              Media media);
    //! Whether an eye at this point is under the water (the wave height at its own x, y).
    bool eyeBelow(const glm::dvec3& eye) const;
    //! The reference for the ray eye + s dir (dir unit).
    PixelTrace trace(const glm::dvec3& eye, const glm::dvec3& dir) const;
    const RayCaster& scene() const { return _scene; }
    const WaterCaster& water() const { return _water; }
    const Media& media() const { return _media; }
    //! The water's unit normal at a hit of water(), facing up (over the waves the analytic one).
    glm::dvec3 normalAt(const Hit& h) const;
    //! The slopes' variance at a hit of water() that normalAt does not show: the wind's
    //! (SpectralWaves::Sampler::roughness, what the kit shades as roughness for a footprint under a
    //! texel); 0 for the sum of waves or a user's mesh, whose normals are all there is.
    double roughnessAt(const Hit& h) const;
    //! Where the reflection pass shows the mirror ray of a trace from `eye` that met the water: the
    //! unit direction from the eye mirrored in the level to the mirror ray's hit, or the mirror ray's
    //! own direction where it meets nothing (the pass's camera sits at the mirrored eye).
    glm::dvec3 mirrorSight(const glm::dvec3& eye, const PixelTrace& p) const;

private:
    //! The eye ray's hit on the water where nothing in the scene lies before it (else no hit).
    Hit waterFirst(const glm::dvec3& eye, const glm::dvec3& dir) const;
    //! The eye mirrored in the level: where the reflection pass's camera sits.
    glm::dvec3 mirroredEye(const glm::dvec3& eye) const;
    const RayCaster& _scene;
    const WaterCaster& _water;
    const osgWater::WaterSurface& _surface;
    double _t;
    Media _media;
};

//! A view's reference, compact, per pixel (row 0 at the bottom, as GL reads back).
struct PixelRef {
    enum : uint8_t { WATER = 1, BELOW = 2, TIR = 4, REFRACTED_HIT = 8, REFLECTED_HIT = 16, JACOBIAN = 32,
                     REFLECTION_SHOWN = 64 };
    uint8_t flags = 0;
    glm::vec3 U{ 0.0f }, X{ 0.0f }, Y{ 0.0f }; //!< Y: the mirror ray's hit, or its direction on a miss
    float fresnel = 0.0f;
    glm::mat2x3 pixelsPerMetre{ 0.0f };       //!< least-squares inverse of dX/d(pixel): metres -> pixels
    float mirrorSpread = 0.0f;                //!< radians: the fan of the pixel's own mirror rays (PixelFan)
    //! Screen pixels (through pixelsPerMetre): how far apart the widest two of the pixel's own five
    //! rays' refracted hits lie (its centre's and its quarters', PixelFan); about 0.7 (a quarter's
    //! diagonal) over smooth water, unbounded (1e9) where some of them do not refract into the
    //! scene. Set with JACOBIAN.
    float refractionFan = 0.0f;
};

struct ReferenceImage {
    int width = 0, height = 0;
    std::vector<PixelRef> pixels;
    size_t waterPixels = 0;
    const PixelRef& at(int x, int y) const { return pixels[size_t(y) * width + x]; }
};

//! The unit rays of a width x height view (viewMatrix, projection: local frame -> clip) from its
//! eye, local frame.
class ViewRays
{
public:
    ViewRays(const osg::Matrixd& viewMatrix, const osg::Matrixd& projection, int width, int height);
    //! Through the view's point (x, y) in pixels from its lower left corner (pixel (i, j)'s centre:
    //! i + 0.5, j + 0.5).
    glm::dvec3 through(double x, double y) const;
    const glm::dvec3 eye;

private:
    osg::Matrixd _inverse;
    int _width, _height;
};

//! Calls `pixel(x, y, eye, dir)` for every pixel of a width x height view (row 0 at the bottom),
//! from a few threads, each with its own rows: the unit ray through the pixel's point `offset`
//! (0..1 across it; the centre by default), local frame.
void forEachPixelRay(const osg::Matrixd& viewMatrix, const osg::Matrixd& projection, int width, int height,
                     const std::function<void(int, int, const glm::dvec3&, const glm::dvec3&)>& pixel,
                     const glm::dvec2& offset = glm::dvec2(0.5));

//! Traces every pixel centre of a width x height view (viewMatrix, projection: local frame -> clip).
ReferenceImage traceView(const Reference& ref, const osg::Matrixd& viewMatrix, const osg::Matrixd& projection,
                         int width, int height);

}
