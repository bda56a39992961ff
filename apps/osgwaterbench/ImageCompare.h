// A rendered view against its reference image as a person sees them: both as the display shows
// them (the reference exposed, through the tone curve and encoded, as the kit shows linear light),
// compared by CIEDE2000 per pixel and by the SSIM of their luma, over the reference's water pixels
// and over the whole frame; and the two side by side with a map of the difference.
#pragma once
#include <osgWater/WaterSettings>
#include <osg/Image>
#include <glm/vec3.hpp>
#include <limits>
#include <vector>

namespace bench {

struct ImageErrors {
    static constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
    double ssimWater = kNone, ssimFrame = kNone;           //!< luma SSIM (Wang et al. 2004)
    double deltaEMeanWater = kNone, deltaEP95Water = kNone; //!< CIEDE2000 over the water pixels
    double deltaEMeanFrame = kNone, deltaEP95Frame = kNone; //!< ... and over every pixel
    //! The reference image's own noise over the water: half the mean CIEDE2000 between two
    //! independent halves of its rays (referenceNoise), about the full image's mean difference from
    //! its converged self. Error below it is not the render's to remove.
    double referenceNoiseWater = kNone;
};

//! How the display shows linear light: exposed, through the tone curve, encoded (0..1).
struct DisplayTransform {
    float exposure = 1.0f;
    osgWater::WaterSettings::ToneCurve curve = osgWater::WaterSettings::TONE_CLIP;
};

//! `shown`: the render as the display holds it (float RGBA, display values, row 0 at the bottom);
//! `reference`: linear light per pixel, the same size; `water`: the pixels whose reference ray
//! meets the water first. NaN figures where there is nothing to measure (no water pixel, or the
//! images too small for SSIM's window). With `triplet`, also the render, the reference (as the
//! display shows it) and the CIEDE2000 difference (black 0, white 10 or more) side by side: an
//! 8-bit RGB image three views wide.
ImageErrors compareWithReference(const osg::Image& shown, const std::vector<glm::vec3>& reference,
                                 const DisplayTransform& display, const std::vector<bool>& water,
                                 osg::ref_ptr<osg::Image>* triplet = nullptr);

//! Half the mean CIEDE2000 over the water pixels between two independent estimates of one
//! reference image (ReferenceRenderer::render's halves), as the display shows them: the mean of
//! the two is off its converged value by about that much (for independent halves of one variance,
//! |mean - truth| is distributed as |a - b| / 2). NaN without halves or water pixels.
double referenceNoise(const std::vector<glm::vec3>& halfA, const std::vector<glm::vec3>& halfB,
                      const DisplayTransform& display, const std::vector<bool>& water);

}
