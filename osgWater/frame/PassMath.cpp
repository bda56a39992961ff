#include "frame/PassMath.h"
#include <limits>
#include <osg/Quat>
#include <algorithm>
#include <cmath>

namespace osgWater {

osg::Matrixd mirrorMatrix(double level)
{
    return osg::Matrixd::scale(1.0, 1.0, -1.0) * osg::Matrixd::translate(0.0, 0.0, 2.0 * level);
}

osg::Matrixd extendFov(const osg::Matrixd& projection, double ext)
{
    const double s = 1.0 / std::max(ext, 1.0e-6);
    return projection * osg::Matrixd::scale(s, s, 1.0);
}

osg::Matrixd withNearFar(const osg::Matrixd& projection, double zNear, double zFar)
{
    double l, r, b, t, n, f;
    const bool perspective = projection(3, 3) == 0.0;
    if (perspective && projection.getFrustum(l, r, b, t, n, f)) {
        const double s = zNear / n;
        return osg::Matrixd::frustum(l * s, r * s, b * s, t * s, zNear, zFar);
    }
    if (!perspective && projection.getOrtho(l, r, b, t, n, f))
        return osg::Matrixd::ortho(l, r, b, t, zNear, zFar);
    return projection;
}

osg::Vec3d axisScales(const osg::Matrixd& view)
{
    // the view's rotation keeps lengths: the local axes' lengths in eye space are the scales
    return osg::Vec3d(osg::Vec3d(view(0, 0), view(0, 1), view(0, 2)).length(),
                      osg::Vec3d(view(1, 0), view(1, 1), view(1, 2)).length(),
                      osg::Vec3d(view(2, 0), view(2, 1), view(2, 2)).length());
}

double localLengthPerEyeLength(const osg::Matrixd& view)
{
    // the geometric mean of the axes' scales: exact for a uniform scale, a fair mean otherwise
    const osg::Vec3d s = axisScales(view);
    const double volume = s.x() * s.y() * s.z();
    return volume > 0.0 && std::isfinite(volume) ? 1.0 / std::cbrt(volume) : 1.0;
}

bool nearFarForBound(const osg::Matrixd& view, const osg::BoundingSphere& bound, double& zNear, double& zFar)
{
    if (!bound.valid()) return false;
    const double depth = -(osg::Vec3d(bound.center()) * view).z(); // distance along -Z
    const double radius = bound.radius() / localLengthPerEyeLength(view); // in eye-space units
    zFar = depth + radius;
    if (zFar <= 0.0) return false;
    // 1e-4 of far keeps a 24-bit depth buffer meaningful when the eye is inside the bound
    zNear = std::max(depth - radius, zFar * 1.0e-4);
    zFar *= 1.001;
    return true;
}

osg::Matrixd rotatedRefractionView(const osg::Matrixd& view, const osg::Matrixd& projection, double level, double eta,
                                   double distanceScale)
{
    const osg::Matrixd inv = osg::Matrixd::inverse(view * projection);
    // the ray through the bottom-centre of the screen, in the local frame
    const osg::Vec3d pn = osg::Vec3d(0.0, -1.0, -1.0) * inv;
    const osg::Vec3d pf = osg::Vec3d(0.0, -1.0, 1.0) * inv;
    const osg::Vec3d C1 = eyePosition(view);
    osg::Vec3d I = pf - pn;
    if (I.normalize() == 0.0 || I.z() >= -1.0e-6) return view;
    // eq. 1: O = C1 - (N.(C1 - V)) / (N.J) J, with N = +z and V on the plane; an eye at or under
    // the level (above a trough) turns about itself: switching the rotation off there made a
    // visible jump in the refraction image as the eye came down to the water
    const double t = std::max(0.0, (C1.z() - level) / -I.z());
    const osg::Vec3d O = C1 + I * t;
    // eq. 2 with N facing the incoming ray
    const osg::Vec3d N(0.0, 0.0, 1.0);
    const double d = N * I;
    const double k = 1.0 - eta * eta * (1.0 - d * d);
    if (k < 0.0) return view;
    osg::Vec3d R = I * eta - N * (eta * d + std::sqrt(k));
    R.normalize();
    osg::Quat q;
    q.makeRotate(I, R);
    // rotate the camera (its camera-to-local transform) about O, then move it along the refracted
    // ray: the rotation took it to O - |C1 - O| R
    const osg::Matrixd cameraToLocal = osg::Matrixd::inverse(view);
    const osg::Matrixd about = osg::Matrixd::translate(-O) * osg::Matrixd::rotate(q) * osg::Matrixd::translate(O);
    const double scale = std::isfinite(distanceScale) && distanceScale > 0.0 ? distanceScale : 1.0;
    const osg::Matrixd back = osg::Matrixd::translate(-R * ((scale - 1.0) * (C1 - O).length()));
    return osg::Matrixd::inverse(cameraToLocal * about * back);
}

osg::Vec4d planeToEye(const osg::Vec4d& p, const osg::Matrixd& view)
{
    // p . x_local = p . (x_eye * V^-1) = (V^-1 p) . x_eye
    return osg::Matrixd::inverse(view).postMult(p);
}

osg::Vec3d eyePosition(const osg::Matrixd& view)
{
    return osg::Vec3d(0.0, 0.0, 0.0) * osg::Matrixd::inverse(view);
}

osg::Vec3d projectToTexture(const osg::Vec3d& local, const osg::Matrixd& view, const osg::Matrixd& projection)
{
    const osg::Vec4d c = osg::Vec4d(local, 1.0) * view * projection;
    const double w = std::fabs(c.w()) > 1.0e-300 ? c.w() : 1.0e-300;
    return osg::Vec3d(c.x() / w * 0.5 + 0.5, c.y() / w * 0.5 + 0.5, c.z() / w * 0.5 + 0.5);
}

osg::Matrixd sunView(const osg::Vec3d& towardsSun, const osg::BoundingBox& box)
{
    osg::Vec3d L = towardsSun;
    if (!(L.length2() > 1e-24)) L.set(0.0, 0.0, 1.0);
    L.normalize();
    osg::Vec3d up(0.0, 1.0, 0.0);
    if (std::fabs(L * up) > 0.999) up.set(1.0, 0.0, 0.0);
    up = up - L * (L * up);
    up.normalize();
    const osg::Vec3d c = box.valid() ? osg::Vec3d(box.center()) : osg::Vec3d();
    const double r = box.valid() ? box.radius() : 1.0;
    return osg::Matrixd::lookAt(c + L * (2.0 * r + 1.0), c, up);
}

osg::Matrixd sunProjection(const osg::Matrixd& view, const osg::BoundingBox& box)
{
    if (!box.valid()) return osg::Matrixd::ortho(-1.0, 1.0, -1.0, 1.0, 0.1, 10.0);
    osg::BoundingBoxd e;
    for (unsigned int i = 0; i < 8; ++i) e.expandBy(osg::Vec3d(box.corner(i)) * view);
    // a degenerate extent (flat box seen edge-on) still needs a non-singular matrix
    const double pad = 1e-3 * std::max(1.0, e.radius());
    return osg::Matrixd::ortho(e.xMin() - pad, e.xMax() + pad, e.yMin() - pad, e.yMax() + pad,
                               -e.zMax() - pad, -e.zMin() + pad);
}

osg::Matrixd clipToTexture()
{
    return osg::Matrixd::translate(1.0, 1.0, 1.0) * osg::Matrixd::scale(0.5, 0.5, 0.5);
}

bool boxInsidePlanes(const osg::BoundingBox& box, const std::vector<osg::Plane>& planes)
{
    if (!box.valid()) return false;
    // a corner inside every plane: done (also covers a frustum wholly inside the box's faces' reach)
    for (unsigned int i = 0; i < 8; ++i) {
        bool inside = true;
        for (const osg::Plane& p : planes) inside = inside && p.distance(box.corner(i)) >= 0.0;
        if (inside) return true;
    }
    // otherwise some face must cross the frustum: clip each face polygon by every plane
    static const int faces[6][4] = { { 0, 1, 3, 2 }, { 4, 5, 7, 6 }, { 0, 1, 5, 4 },
                                     { 2, 3, 7, 6 }, { 0, 2, 6, 4 }, { 1, 3, 7, 5 } };
    for (const auto& f : faces) {
        std::vector<osg::Vec3d> poly = { box.corner(f[0]), box.corner(f[1]), box.corner(f[2]), box.corner(f[3]) };
        for (const osg::Plane& p : planes) {
            std::vector<osg::Vec3d> out;
            for (size_t i = 0; i < poly.size(); ++i) {
                const osg::Vec3d& a = poly[i];
                const osg::Vec3d& b = poly[(i + 1) % poly.size()];
                const double da = p.distance(a), db = p.distance(b);
                if (da >= 0.0) out.push_back(a);
                if ((da >= 0.0) != (db >= 0.0)) out.push_back(a + (b - a) * (da / (da - db)));
            }
            poly.swap(out);
            if (poly.empty()) break;
        }
        if (!poly.empty()) return true;
    }
    // the frustum wholly inside the box (no corner in it, no face crossing it): its apex is inside
    return false;
}

osg::Vec2i passTargetSize(double viewportWidth, double viewportHeight, double scale, int fixedSize)
{
    if (!(scale > 0.0) || !(viewportWidth >= 1.0) || !(viewportHeight >= 1.0)) return osg::Vec2i(fixedSize, fixedSize);
    auto side = [scale](double v) { return int(std::lround(std::min(std::max(v * scale, 16.0), 4096.0))); };
    return osg::Vec2i(side(viewportWidth), side(viewportHeight));
}

bool nearPlaneReachesWater(const osg::Matrixd& modelView, const osg::Matrixd& projection, double level, double waveBound)
{
    const double top = level + waveBound, bottom = level - waveBound;
    const double eyeZ = eyePosition(modelView).z();
    if (!std::isfinite(eyeZ) || (eyeZ <= top && eyeZ >= bottom)) return true; // in the band: anything goes
    osg::Matrixd clipToLocal;
    if (!clipToLocal.invert(modelView * projection)) return true;
    // the near plane is a flat rectangle: its height range is its corners'
    double lo = std::numeric_limits<double>::max(), hi = -lo;
    for (double x : { -1.0, 1.0 })
        for (double y : { -1.0, 1.0 }) {
            const osg::Vec4d c = osg::Vec4d(x, y, -1.0, 1.0) * clipToLocal;
            if (!(std::abs(c.w()) > 1e-300)) return true;
            const double z = c.z() / c.w();
            if (!std::isfinite(z)) return true;
            lo = std::min(lo, z);
            hi = std::max(hi, z);
        }
    return eyeZ > top ? lo <= top : hi >= bottom;
}

}

int osgWater::focusedCount(int count, double ratio)
{
    const int floor = std::min(count, 32);
    if (!(ratio > 0.0)) return floor; // also NaN
    if (ratio >= 1.0) return count;
    const int scaled = int(std::ceil(count * ratio / 8.0)) * 8;
    return std::max(floor, std::min(count, scaled));
}
