// Error of the renderer's per-pixel estimates (debug outputs read back from float targets)
// against the exact reference, and of its caustics texture against photon tracing.
#pragma once
#include "PhotonTracer.h"
#include "Reference.h"
#include <osg/Image>
#include <osg/Matrixd>
#include <osgWater/WaterSurface>
#include <limits>
#include <vector>

namespace bench {

struct Quantiles {
    size_t n = 0;
    double median = std::numeric_limits<double>::quiet_NaN(), p95 = median, p99 = median, max = median;
    double over2 = median; //!< share of values above 2
};
//! Quantiles of v (sorted in place); NaN fields when v is empty.
Quantiles quantiles(std::vector<float>& v);

//! The per-pixel loops' work over the render's water (DEBUG_WORK), counted by the shader, not timed:
//! what a GPU would pay whatever this machine's load. Means per water pixel; NaN without pixels.
struct WorkCounts {
    size_t pixels = 0;
    double refractionReads = std::numeric_limits<double>::quiet_NaN(); //!< the refraction search's depth reads
    double reflectionReads = refractionReads;                         //!< the reflection search's
    double marchHeights = refractionReads;                            //!< the wave heights the march evaluated
    //! The means over both sets' pixels together.
    WorkCounts pooledWith(const WorkCounts& o) const;
};
//! The counts of a DEBUG_WORK image (its water pixels: alpha 2).
WorkCounts countWork(const osg::Image* work);

//! What the renderer estimated for one view (read back after a frame of each debug output).
struct Estimate {
    osg::ref_ptr<osg::Image> color, bottom, reflection, fresnel; //!< float RGBA, the view's size
    osg::ref_ptr<osg::Image> drawn;    //!< the drawn mesh's point under each water pixel (DEBUG_DRAWN_SURFACE)
    osg::ref_ptr<osg::Image> shaded;   //!< the surface point each water pixel shades (DEBUG_SURFACE)
    osg::ref_ptr<osg::Image> work;     //!< the loops' work at each water pixel (DEBUG_WORK)
    osg::ref_ptr<osg::Image> slopes;   //!< the normal's slopes and roughness each pixel shades with (DEBUG_SLOPES)
    double airIOR = 1.0, waterIOR = 1.333; //!< the render's media
    osg::Vec3d eye;                    //!< the view's eye, local frame
    osg::Matrixd view, projection;     //!< the view's camera (local frame -> clip): its pixels' rays
    double pixelsPerRadian = 0.0;      //!< the view's focal length in pixels (at the centre of the view)
    osg::Matrixd refractionView;       //!< local -> refraction pass eye space
    osg::Vec3d refractionEye;          //!< the refraction camera's position, local frame
    bool eyeBelow = false;
    double level = 0.0, clearance = 0.0; //!< the refraction pass keeps z <= level + clearance (above) or >= level - clearance
    osg::Matrixd reflectionMVP;        //!< local -> reflection pass clip space
    int reflectionSize = 512;
};

//! Why the refraction shows a pixel more than 2 px off: no farther than the pixel's own rays'
//! refracted hits lie apart (PixelRef::refractionFan: waves shorter than the pixel, where one ray's
//! hit is one sample of many), the render shades another point of the surface (its refracted ray
//! starts elsewhere), the exact hit is hidden from the refraction pass's eye (no single depth layer
//! holds it), or the search settled on a point the pass shows in front of the exact hit (an
//! occluder, the near side of an edge) or behind it.
enum RefractionCause { CAUSE_WITHIN_FAN, CAUSE_SHADED_POINT, CAUSE_HIDDEN, CAUSE_IN_FRONT, CAUSE_BEHIND, CAUSE_COUNT };

struct ViewErrors {
    std::vector<float> refractionPx;     //!< apparent-position error of the refracted point, screen pixels
    std::vector<float> refractionM;      //!< the same in metres
    //! Per pixel of refractionPx, the fan of its own rays' refracted hits (PixelRef::refractionFan)
    //! and how far the shown point lies beyond it: max(0, error - fan), screen pixels.
    std::vector<float> refractionFanPx, refractionBeyondFanPx;
    std::vector<float> reflectionTexels; //!< reflection lookup vs the mirror ray's hit, reflection texels
    std::vector<float> reflectionShownTexels; //!< the same where the reflection pass has the hit in view
    size_t reflectionNotShown = 0;       //!< pixels measured whose hit the reflection pass cannot show
    //! Per shown pixel, the fan of its own rays' mirror rays in texels (PixelRef::mirrorSpread), and
    //! how far its lookup lies beyond that fan: max(0, error - fan). Over waves shorter than a pixel
    //! the mirror rays fan out, and no single lookup is nearer all of them than the fan is wide.
    std::vector<float> reflectionFanTexels, reflectionBeyondFanTexels;
    std::vector<float> fresnel;          //!< |F - exact|
    size_t waterPixels = 0;              //!< reference: pixels whose eye ray meets the water first
    size_t misses = 0;                   //!< reference refracted ray hits, the renderer found nothing
    size_t tirMismatch = 0;              //!< total internal reflection in one and not the other
    size_t coverageMismatch = 0;         //!< water in one of the reference and the render, not in the other
    std::vector<float> drawnSurfacePx;   //!< the drawn mesh's height error, screen pixels (drawnSurfaceError)
    std::vector<float> shadedPointCm;    //!< the point the render shades against the exact crossing, centimetres
    size_t refractionCauses[CAUSE_COUNT] = {}; //!< the refraction's pixels over 2 px, by cause
    //! Along the render's own rays: the mirror and refracted rays of each pixel's shaded point at the
    //! normal it shades with (DEBUG_SURFACE, DEBUG_SLOPES), traced exactly. Their lookups' errors are
    //! the passes' and searches' alone, whatever the pixel's filtering chose: the refraction's in
    //! screen pixels (the reference's metres-to-pixels) with its pixels over 2 px by cause (hidden,
    //! in front, behind), the reflection's in texels where its pass shows the hit, how many of the
    //! rays rising from the level it cannot show, and how many the waves send back under the level
    //! (their light is the shading's rule for the light the waves take back, no lookup's).
    std::vector<float> refractionOwnPx, reflectionOwnShownTexels;
    size_t reflectionOwnNotShown = 0, reflectionOwnSentUnder = 0;
    size_t refractionOwnCauses[CAUSE_COUNT] = {};
    size_t nanPixels = 0;                //!< pixels with a NaN or Inf in any read-back output
};

//! The scene point the refraction texture shows for a debug estimate (a = 2 a point, 3 a
//! direction): the refraction camera's ray through it, beyond the pass's clip plane.
bool shownPoint(const osg::Vec4f& estimate, const Estimate& e, const RayCaster& scene, glm::dvec3& out);

ViewErrors measureView(const ReferenceImage& ref, const Estimate& e, const RayCaster& scene);
//! The cause of one pixel's refraction error (`exact`: the exact hit, `shown`: the point the pass
//! shows there, `errPx` its error in screen pixels, `fanPx` the pixel's own rays' fan (0: none);
//! `shadedOffM`: how far the pixel's shaded point lies from the exact crossing, negative if unknown).
RefractionCause refractionCause(const Estimate& e, const RayCaster& scene, const glm::dvec3& exact,
                                const glm::dvec3& shown, float errPx, float fanPx, float shadedOffM);
//! Per pixel of the render's water drawn by the built-in mesh: the rasterised point V against the
//! analytic surface under it, (V.x, V.y, h(V.x, V.y)): the angle between them at the eye, in pixels
//! (the focal length's: exact at the view's centre, up to 1 / cos^2 of the half field of view
//! more than the window's pixels at its edge). How far on screen the drawn surface lies from the
//! exact one there; an angle stays finite where a projection would not, beside an eye on the
//! water. Empty over a user mesh.
std::vector<float> drawnSurfaceError(const Estimate& e, const osgWater::WaterSurface& surface, double t);
size_t countNonFinite(const osg::Image* img);

struct CausticsErrors {
    bool valid = false;
    double relativeRmse = std::numeric_limits<double>::quiet_NaN();
    double referenceNoise = relativeRmse; //!< the reference's own relative RMSE, from its two halves (NaN without them)
    double meanReference = relativeRmse, meanRendered = relativeRmse;
};
//! Both images summed over blocks x blocks texels, RMSE over blocks that either lights, / mean reference.
//! The side of the blocks the caustics are compared on, in metres on the sun's window: about
//! 4 texels of the default lake's caustics (1.2 m; its texels are 0.29 m).
constexpr double kCausticsBlockMetres = 1.2;
CausticsErrors measureCaustics(const PhotonImage& reference, const osg::Image* rendered, int block);

}
