// How far a rendered image is from its reference as a person would see it: the colour difference
// of each pixel (CIEDE2000 on CIELAB) and the images' structural similarity (SSIM), as rendering
// papers report them.
#pragma once
#include <osg/Vec3d>
#include <vector>

namespace bench {

//! CIELAB: L* in [0, 100] and the a*, b* opponent axes.
struct Lab {
    double L = 0.0, a = 0.0, b = 0.0;
};

//! The CIELAB colour, relative to D65 white, of a display's sRGB primaries driven with linear light
//! `rgb` (IEC 61966-2-1: its primaries and white; 1 is the display's white, L* = 100).
Lab labFromLinearSrgb(const osg::Vec3d& rgb);

//! The CIEDE2000 colour difference (CIE 142-2001) with the parametric factors kL = kC = kH = 1, as
//! Sharma, Wu and Dalal (2005) spell it out: about 1 is a just-noticeable difference.
double deltaE2000(const Lab& x, const Lab& y);

//! A single-channel image, row-major, values in [0, 1].
struct GreyImage {
    int width = 0, height = 0;
    std::vector<double> value;
    double at(int x, int y) const { return value[size_t(y) * width + x]; }
};

//! The structural similarity of two images of the same size (Wang, Bovik, Sheikh and Simoncelli
//! 2004), as their reference code computes it: an 11 x 11 Gaussian window of sigma 1.5 at every
//! position where it fits inside the images, K1 = 0.01, K2 = 0.03, a dynamic range of 1; the mean
//! of the map over the windows whose centre pixel `mask` keeps (every window without a mask). NaN
//! when the images differ in size, are smaller than the window or the mask keeps no window.
double ssim(const GreyImage& x, const GreyImage& y, const std::vector<bool>* mask = nullptr);

} // namespace bench
