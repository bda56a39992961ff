// The image error's measures against published data: CIEDE2000 reproduces Sharma, Wu and Dalal's
// (2005) 34 test pairs to 1e-4, CIELAB of the sRGB primaries is the colour calculators', and SSIM
// is the reference implementation's (scikit-image set as Wang et al.'s code) within 1e-3. No GPU.
#include "ImageError.h"
#include <gtest/gtest.h>
#include <algorithm>
#include <cmath>

using namespace bench;

TEST(ImageError, CIEDE2000ReproducesSharmasTestData)
{
    // Sharma, Wu and Dalal, "The CIEDE2000 color-difference formula: implementation notes,
    // supplementary test data, and mathematical observations", Table 1: (L1, a1, b1), (L2, a2, b2), dE00
    const struct { Lab x, y; double dE; } pairs[] = {
        { { 50.0000, 2.6772, -79.7751 }, { 50.0000, 0.0000, -82.7485 }, 2.0425 },
        { { 50.0000, 3.1571, -77.2803 }, { 50.0000, 0.0000, -82.7485 }, 2.8615 },
        { { 50.0000, 2.8361, -74.0200 }, { 50.0000, 0.0000, -82.7485 }, 3.4412 },
        { { 50.0000, -1.3802, -84.2814 }, { 50.0000, 0.0000, -82.7485 }, 1.0000 },
        { { 50.0000, -1.1848, -84.8006 }, { 50.0000, 0.0000, -82.7485 }, 1.0000 },
        { { 50.0000, -0.9009, -85.5211 }, { 50.0000, 0.0000, -82.7485 }, 1.0000 },
        { { 50.0000, 0.0000, 0.0000 }, { 50.0000, -1.0000, 2.0000 }, 2.3669 },
        { { 50.0000, -1.0000, 2.0000 }, { 50.0000, 0.0000, 0.0000 }, 2.3669 },
        { { 50.0000, 2.4900, -0.0010 }, { 50.0000, -2.4900, 0.0009 }, 7.1792 },
        { { 50.0000, 2.4900, -0.0010 }, { 50.0000, -2.4900, 0.0010 }, 7.1792 },
        { { 50.0000, 2.4900, -0.0010 }, { 50.0000, -2.4900, 0.0011 }, 7.2195 },
        { { 50.0000, 2.4900, -0.0010 }, { 50.0000, -2.4900, 0.0012 }, 7.2195 },
        { { 50.0000, -0.0010, 2.4900 }, { 50.0000, 0.0009, -2.4900 }, 4.8045 },
        { { 50.0000, -0.0010, 2.4900 }, { 50.0000, 0.0010, -2.4900 }, 4.8045 },
        { { 50.0000, -0.0010, 2.4900 }, { 50.0000, 0.0011, -2.4900 }, 4.7461 },
        { { 50.0000, 2.5000, 0.0000 }, { 50.0000, 0.0000, -2.5000 }, 4.3065 },
        { { 50.0000, 2.5000, 0.0000 }, { 73.0000, 25.0000, -18.0000 }, 27.1492 },
        { { 50.0000, 2.5000, 0.0000 }, { 61.0000, -5.0000, 29.0000 }, 22.8977 },
        { { 50.0000, 2.5000, 0.0000 }, { 56.0000, -27.0000, -3.0000 }, 31.9030 },
        { { 50.0000, 2.5000, 0.0000 }, { 58.0000, 24.0000, 15.0000 }, 19.4535 },
        { { 50.0000, 2.5000, 0.0000 }, { 50.0000, 3.1736, 0.5854 }, 1.0000 },
        { { 50.0000, 2.5000, 0.0000 }, { 50.0000, 3.2972, 0.0000 }, 1.0000 },
        { { 50.0000, 2.5000, 0.0000 }, { 50.0000, 1.8634, 0.5757 }, 1.0000 },
        { { 50.0000, 2.5000, 0.0000 }, { 50.0000, 3.2592, 0.3350 }, 1.0000 },
        { { 60.2574, -34.0099, 36.2677 }, { 60.4626, -34.1751, 39.4387 }, 1.2644 },
        { { 63.0109, -31.0961, -5.8663 }, { 62.8187, -29.7946, -4.0864 }, 1.2630 },
        { { 61.2901, 3.7196, -5.3901 }, { 61.4292, 2.2480, -4.9620 }, 1.8731 },
        { { 35.0831, -44.1164, 3.7933 }, { 35.0232, -40.0716, 1.5901 }, 1.8645 },
        { { 22.7233, 20.0904, -46.6940 }, { 23.0331, 14.9730, -42.5619 }, 2.0373 },
        { { 36.4612, 47.8580, 18.3852 }, { 36.2715, 50.5065, 21.2231 }, 1.4146 },
        { { 90.8027, -2.0831, 1.4410 }, { 91.1528, -1.6435, 0.0447 }, 1.4441 },
        { { 90.9257, -0.5406, -0.9208 }, { 88.6381, -0.8985, -0.7239 }, 1.5381 },
        { { 6.7747, -0.2908, -2.4247 }, { 5.8714, -0.0985, -2.2286 }, 0.6377 },
        { { 2.0776, 0.0795, -1.1350 }, { 0.9033, -0.0636, -0.5514 }, 0.9082 },
    };
    int i = 1;
    for (const auto& p : pairs) {
        EXPECT_NEAR(deltaE2000(p.x, p.y), p.dE, 1e-4) << "pair " << i;
        EXPECT_NEAR(deltaE2000(p.y, p.x), p.dE, 1e-4) << "pair " << i << ", swapped";
        ++i;
    }
    EXPECT_EQ(deltaE2000({ 40.0, 10.0, -20.0 }, { 40.0, 10.0, -20.0 }), 0.0);
}

TEST(ImageError, CIELABOfTheSrgbPrimariesIsTheTablesWithD65White)
{
    // CIELAB of sRGB's white, primaries and a grey (D65 white): the values colour calculators give
    const struct { osg::Vec3d rgb; Lab lab; } colours[] = {
        { { 1, 1, 1 }, { 100.0, 0.0, 0.0 } },
        { { 1, 0, 0 }, { 53.2408, 80.0925, 67.2032 } },
        { { 0, 1, 0 }, { 87.7347, -86.1827, 83.1793 } },
        { { 0, 0, 1 }, { 32.2970, 79.1875, -107.8602 } },
        { { 0.18, 0.18, 0.18 }, { 49.4961, 0.0, 0.0 } }, // a photographer's 18% grey: 116 0.18^(1/3) - 16
        { { 0, 0, 0 }, { 0.0, 0.0, 0.0 } },
    };
    for (const auto& c : colours) {
        const Lab lab = labFromLinearSrgb(c.rgb);
        EXPECT_NEAR(lab.L, c.lab.L, 0.02) << c.rgb.x() << " " << c.rgb.y() << " " << c.rgb.z();
        EXPECT_NEAR(lab.a, c.lab.a, 0.02) << c.rgb.x() << " " << c.rgb.y() << " " << c.rgb.z();
        EXPECT_NEAR(lab.b, c.lab.b, 0.02) << c.rgb.x() << " " << c.rgb.y() << " " << c.rgb.z();
    }
}

namespace {
// test images by formula, so a reference implementation can make the same ones: smooth structure,
// and the same with a finer pattern added and the contrast lowered
GreyImage pattern(int width, int height, double detail, double contrast)
{
    GreyImage g;
    g.width = width;
    g.height = height;
    for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i) {
            const double v = 0.5 + contrast * std::sin(0.3 * i + 0.2 * j) * std::cos(0.17 * j) + detail * std::sin(1.1 * i) * std::sin(0.7 * j);
            g.value.push_back(std::min(std::max(v, 0.0), 1.0));
        }
    return g;
}
}

TEST(ImageError, SsimOfTheSameImageIsOneAndOfTwoFlatOnesTheLuminanceTerm)
{
    const GreyImage a = pattern(40, 30, 0.0, 0.4);
    EXPECT_NEAR(ssim(a, a), 1.0, 1e-12);
    // flat images: no variance, so SSIM is the luminance term (2 m1 m2 + C1) / (m1^2 + m2^2 + C1)
    GreyImage flat1 = pattern(20, 20, 0.0, 0.0), flat2 = flat1;
    for (double& v : flat1.value) v = 0.3;
    for (double& v : flat2.value) v = 0.7;
    const double c1 = 1e-4;
    EXPECT_NEAR(ssim(flat1, flat2), (2 * 0.3 * 0.7 + c1) / (0.3 * 0.3 + 0.7 * 0.7 + c1), 1e-12);
    // no answer for images of different sizes, smaller than the window, or a mask that keeps nothing
    EXPECT_TRUE(std::isnan(ssim(a, pattern(40, 31, 0.0, 0.4))));
    EXPECT_TRUE(std::isnan(ssim(pattern(10, 30, 0.0, 0.4), pattern(10, 30, 0.0, 0.4))));
    const std::vector<bool> nothing(a.value.size(), false);
    EXPECT_TRUE(std::isnan(ssim(a, a, &nothing)));
}

TEST(ImageError, SsimIsTheReferenceImplementations)
{
    // scikit-image 0.19's structural_similarity(x, y, gaussian_weights=True, sigma=1.5,
    // use_sample_covariance=False, data_range=1), the settings its documentation gives to match
    // Wang et al.'s code, on the same images made in Python (Debian's python3-skimage) by the same
    // formula:
    //   j, i = numpy.mgrid[0:h, 0:w].astype(float)
    //   v = numpy.clip(0.5 + contrast * sin(0.3 i + 0.2 j) cos(0.17 j) + detail * sin(1.1 i) sin(0.7 j), 0, 1)
    const GreyImage x = pattern(48, 32, 0.0, 0.4), y = pattern(48, 32, 0.1, 0.3), z = pattern(48, 32, 0.25, 0.2);
    EXPECT_NEAR(ssim(x, y), 0.809319, 1e-3);
    EXPECT_NEAR(ssim(x, z), 0.346848, 1e-3);
    // a mask of the left half: the windows whose centre lies there (scikit-image's map, full=True,
    // without its 5 border pixels, averaged over them: S[5:-5, 5:-5][left[5:-5, 5:-5]].mean())
    std::vector<bool> left(x.value.size());
    for (int j = 0; j < x.height; ++j)
        for (int i = 0; i < x.width; ++i) left[size_t(j) * x.width + i] = i < x.width / 2;
    EXPECT_NEAR(ssim(x, z, &left), 0.344775, 1e-3);
}
