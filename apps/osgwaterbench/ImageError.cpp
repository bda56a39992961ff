#include "ImageError.h"
#include "optics/Srgb.h"
#include <algorithm>
#include <cmath>
#include <limits>

namespace {

const double kPi = 3.14159265358979323846;

double radians(double degrees) { return degrees * kPi / 180.0; }

// sRGB's primaries and D65 white to CIE XYZ (the kit's, as its sky uses)
osg::Vec3d xyzFromLinearSrgb(const osg::Vec3d& c)
{
    const glm::dvec3 xyz = osgWater::optics::xyzFromLinearSrgb(glm::dvec3(c.x(), c.y(), c.z()));
    return osg::Vec3d(xyz.x, xyz.y, xyz.z);
}

// CIELAB's companding: a cube root, and a line through the dark end
double labCurve(double t)
{
    const double d = 6.0 / 29.0;
    return t > d * d * d ? std::cbrt(t) : t / (3.0 * d * d) + 4.0 / 29.0;
}

// the hue angle of (a, b) in degrees, [0, 360); 0 for a neutral colour
double hueDegrees(double a, double b)
{
    if (a == 0.0 && b == 0.0) return 0.0;
    const double h = std::atan2(b, a) * 180.0 / kPi;
    return h < 0.0 ? h + 360.0 : h;
}

} // namespace

bench::Lab bench::labFromLinearSrgb(const osg::Vec3d& rgb)
{
    const osg::Vec3d white = xyzFromLinearSrgb(osg::Vec3d(1.0, 1.0, 1.0)); // D65, as the primaries sum to it
    const osg::Vec3d xyz = xyzFromLinearSrgb(rgb);
    const double fx = labCurve(xyz.x() / white.x()), fy = labCurve(xyz.y() / white.y()), fz = labCurve(xyz.z() / white.z());
    Lab lab;
    lab.L = 116.0 * fy - 16.0;
    lab.a = 500.0 * (fx - fy);
    lab.b = 200.0 * (fy - fz);
    return lab;
}

double bench::deltaE2000(const Lab& x, const Lab& y)
{
    const double pow25to7 = 6103515625.0; // 25^7
    // a* is stretched for near-neutral colours, where the chroma is small
    const double chromaMean = 0.5 * (std::hypot(x.a, x.b) + std::hypot(y.a, y.b));
    const double c7 = std::pow(chromaMean, 7.0);
    const double g = 0.5 * (1.0 - std::sqrt(c7 / (c7 + pow25to7)));
    const double a1 = (1.0 + g) * x.a, a2 = (1.0 + g) * y.a;
    const double c1 = std::hypot(a1, x.b), c2 = std::hypot(a2, y.b);
    const double h1 = hueDegrees(a1, x.b), h2 = hueDegrees(a2, y.b);

    const double dL = y.L - x.L, dC = c2 - c1;
    double dh = 0.0;
    if (c1 * c2 != 0.0) {
        dh = h2 - h1;
        if (dh > 180.0) dh -= 360.0;
        else if (dh < -180.0) dh += 360.0;
    }
    const double dH = 2.0 * std::sqrt(c1 * c2) * std::sin(radians(dh) / 2.0);

    const double lMean = 0.5 * (x.L + y.L), cMean = 0.5 * (c1 + c2);
    double hMean = h1 + h2; // a neutral colour's hue does not count
    if (c1 * c2 != 0.0) {
        if (std::fabs(h1 - h2) <= 180.0) hMean = 0.5 * (h1 + h2);
        else hMean = h1 + h2 < 360.0 ? 0.5 * (h1 + h2 + 360.0) : 0.5 * (h1 + h2 - 360.0);
    }
    const double t = 1.0 - 0.17 * std::cos(radians(hMean - 30.0)) + 0.24 * std::cos(radians(2.0 * hMean)) +
                     0.32 * std::cos(radians(3.0 * hMean + 6.0)) - 0.20 * std::cos(radians(4.0 * hMean - 63.0));
    const double rotation = 30.0 * std::exp(-std::pow((hMean - 275.0) / 25.0, 2.0)); // the blue region's
    const double cMean7 = std::pow(cMean, 7.0);
    const double rC = 2.0 * std::sqrt(cMean7 / (cMean7 + pow25to7));
    const double l50 = (lMean - 50.0) * (lMean - 50.0);
    const double sL = 1.0 + 0.015 * l50 / std::sqrt(20.0 + l50);
    const double sC = 1.0 + 0.045 * cMean;
    const double sH = 1.0 + 0.015 * cMean * t;
    const double rT = -std::sin(radians(2.0 * rotation)) * rC;
    const double l = dL / sL, c = dC / sC, h = dH / sH;
    return std::sqrt(std::max(l * l + c * c + h * h + rT * c * h, 0.0));
}

double bench::ssim(const GreyImage& x, const GreyImage& y, const std::vector<bool>* mask)
{
    const double none = std::numeric_limits<double>::quiet_NaN();
    const int side = 11, half = side / 2;
    if (x.width != y.width || x.height != y.height || x.width < side || x.height < side) return none;
    if (x.value.size() != size_t(x.width) * x.height || y.value.size() != x.value.size()) return none;
    if (mask && mask->size() != x.value.size()) return none;
    // the window, normalised: exp(-r^2 / (2 sigma^2)), separable
    double w[side], sum = 0.0;
    for (int i = 0; i < side; ++i) sum += w[i] = std::exp(-double((i - half) * (i - half)) / (2.0 * 1.5 * 1.5));
    for (double& v : w) v /= sum;
    const double c1 = 0.01 * 0.01, c2 = 0.03 * 0.03;
    double total = 0.0;
    size_t windows = 0;
    for (int cy = half; cy < x.height - half; ++cy)
        for (int cx = half; cx < x.width - half; ++cx) {
            if (mask && !(*mask)[size_t(cy) * x.width + cx]) continue;
            double mx = 0.0, my = 0.0, xx = 0.0, yy = 0.0, xy = 0.0;
            for (int j = 0; j < side; ++j)
                for (int i = 0; i < side; ++i) {
                    const double k = w[i] * w[j], a = x.at(cx + i - half, cy + j - half), b = y.at(cx + i - half, cy + j - half);
                    mx += k * a;
                    my += k * b;
                    xx += k * a * a;
                    yy += k * b * b;
                    xy += k * a * b;
                }
            const double vx = xx - mx * mx, vy = yy - my * my, cov = xy - mx * my;
            total += (2.0 * mx * my + c1) * (2.0 * cov + c2) / ((mx * mx + my * my + c1) * (vx + vy + c2));
            ++windows;
        }
    return windows ? total / double(windows) : none;
}
