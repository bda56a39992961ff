#include "ImageCompare.h"
#include "ImageError.h"
#include "optics/Srgb.h"
#include <algorithm>
#include <cmath>

namespace bench {

namespace {

glm::vec3 clamp01(const glm::vec3& c)
{
    auto one = [](float v) { return std::isfinite(v) ? std::min(std::max(v, 0.0f), 1.0f) : 0.0f; };
    return glm::vec3(one(c.x), one(c.y), one(c.z));
}

// Linear light as the display shows it, 0..1
glm::vec3 shownAs(const glm::vec3& linear, const DisplayTransform& d)
{
    return clamp01(osgWater::optics::display(linear, d.exposure, d.curve));
}

// Both images as the display shows them, 0..1, row-major from the bottom
struct DisplayPair {
    int width = 0, height = 0;
    std::vector<glm::vec3> shown, reference;
    DisplayPair(const osg::Image& image, const std::vector<glm::vec3>& linear, const DisplayTransform& d)
        : width(image.s()), height(image.t())
    {
        const size_t n = size_t(width) * height;
        shown.resize(n);
        reference.resize(n);
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                const size_t i = size_t(y) * width + x;
                const osg::Vec4 c = image.getColor(unsigned(x), unsigned(y));
                shown[i] = clamp01(glm::vec3(c.r(), c.g(), c.b()));
                reference[i] = i < linear.size() ? shownAs(linear[i], d) : glm::vec3(0.0f);
            }
    }
};

double deltaE(const glm::vec3& displayA, const glm::vec3& displayB)
{
    const glm::vec3 a = osgWater::optics::decodeSrgb(displayA), b = osgWater::optics::decodeSrgb(displayB);
    return deltaE2000(labFromLinearSrgb(osg::Vec3d(a.x, a.y, a.z)), labFromLinearSrgb(osg::Vec3d(b.x, b.y, b.z)));
}

// Rec. 709's luma of display values: what SSIM is usually taken on
double luma(const glm::vec3& c) { return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z; }

void meanAndP95(std::vector<double> v, double& mean, double& p95)
{
    if (v.empty()) return;
    double sum = 0.0;
    for (double x : v) sum += x;
    mean = sum / double(v.size());
    const size_t k = std::min(v.size() - 1, size_t(std::ceil(0.95 * double(v.size()))) - 1);
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(k), v.end());
    p95 = v[k];
}

}

ImageErrors compareWithReference(const osg::Image& shown, const std::vector<glm::vec3>& reference,
                                 const DisplayTransform& display, const std::vector<bool>& water,
                                 osg::ref_ptr<osg::Image>* triplet)
{
    ImageErrors e;
    const DisplayPair p(shown, reference, display);
    const size_t n = size_t(p.width) * p.height;
    if (!n || reference.size() != n || water.size() != n) return e;
    std::vector<double> all(n), inWater;
    GreyImage a, b;
    a.width = b.width = p.width;
    a.height = b.height = p.height;
    a.value.resize(n);
    b.value.resize(n);
    for (size_t i = 0; i < n; ++i) {
        all[i] = deltaE(p.shown[i], p.reference[i]);
        if (water[i]) inWater.push_back(all[i]);
        a.value[i] = luma(p.shown[i]);
        b.value[i] = luma(p.reference[i]);
    }
    if (triplet) {
        osg::ref_ptr<osg::Image> out = new osg::Image;
        out->allocateImage(3 * p.width, p.height, 1, GL_RGB, GL_UNSIGNED_BYTE);
        auto put = [&](int x, int y, const glm::vec3& c) {
            unsigned char* d = out->data(unsigned(x), unsigned(y));
            for (int k = 0; k < 3; ++k) d[k] = (unsigned char)std::lround(255.0f * std::min(std::max(c[k], 0.0f), 1.0f));
        };
        for (int y = 0; y < p.height; ++y)
            for (int x = 0; x < p.width; ++x) {
                const size_t i = size_t(y) * p.width + x;
                put(x, y, p.shown[i]);
                put(p.width + x, y, p.reference[i]);
                put(2 * p.width + x, y, glm::vec3(float(std::min(all[i] / 10.0, 1.0))));
            }
        *triplet = out;
    }
    meanAndP95(std::move(all), e.deltaEMeanFrame, e.deltaEP95Frame);
    meanAndP95(std::move(inWater), e.deltaEMeanWater, e.deltaEP95Water);
    e.ssimFrame = ssim(a, b);
    if (std::isfinite(e.deltaEMeanWater)) e.ssimWater = ssim(a, b, &water); // some water to measure
    return e;
}

double referenceNoise(const std::vector<glm::vec3>& halfA, const std::vector<glm::vec3>& halfB,
                      const DisplayTransform& display, const std::vector<bool>& water)
{
    if (halfA.empty() || halfA.size() != halfB.size() || water.size() != halfA.size()) return ImageErrors::kNone;
    double sum = 0.0;
    size_t n = 0;
    for (size_t i = 0; i < halfA.size(); ++i) {
        if (!water[i]) continue;
        sum += deltaE(shownAs(halfA[i], display), shownAs(halfB[i], display));
        ++n;
    }
    return n ? 0.5 * sum / double(n) : ImageErrors::kNone;
}

}
