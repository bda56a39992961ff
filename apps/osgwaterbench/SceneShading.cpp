#include "SceneShading.h"
#include "SceneTriangles.h"
#include "optics/Srgb.h"
#include <glm/geometric.hpp>
#include <algorithm>
#include <cmath>

namespace bench {

namespace {

// A texel index under a wrap mode (GL's REPEAT, MIRRORED_REPEAT; every clamp as CLAMP_TO_EDGE:
// a border colour is not modelled)
int wrapIndex(int i, int size, osg::Texture::WrapMode mode)
{
    if (mode == osg::Texture::REPEAT) return ((i % size) + size) % size;
    if (mode == osg::Texture::MIRROR) {
        const int period = 2 * size;
        const int m = ((i % period) + period) % period;
        return m < size ? m : period - 1 - m;
    }
    return std::clamp(i, 0, size - 1);
}

// Barycentric weights of p (on the triangle's plane) for corners a, b, c
glm::dvec3 barycentric(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& p)
{
    const glm::dvec3 e0 = b - a, e1 = c - a, d = p - a;
    const double d00 = glm::dot(e0, e0), d01 = glm::dot(e0, e1), d11 = glm::dot(e1, e1);
    const double d20 = glm::dot(d, e0), d21 = glm::dot(d, e1);
    const double det = d00 * d11 - d01 * d01;
    if (!(std::fabs(det) > 0.0)) return glm::dvec3(1.0, 0.0, 0.0);
    const double v = (d11 * d20 - d01 * d21) / det, w = (d00 * d21 - d01 * d20) / det;
    return glm::dvec3(1.0 - v - w, v, w);
}

}

glm::dvec3 sampleNearest(const osg::Image& image, const glm::dvec2& st, osg::Texture::WrapMode wrapS,
                         osg::Texture::WrapMode wrapT)
{
    const int w = image.s(), h = image.t();
    if (w <= 0 || h <= 0) return glm::dvec3(1.0);
    const int s = wrapIndex(int(std::floor(st.x * w)), w, wrapS), t = wrapIndex(int(std::floor(st.y * h)), h, wrapT);
    const osg::Vec4 c = image.getColor(unsigned(s), unsigned(t));
    return glm::dvec3(c.r(), c.g(), c.b());
}

glm::dvec3 sampleBilinear(const osg::Image& image, const glm::dvec2& st, osg::Texture::WrapMode wrapS,
                          osg::Texture::WrapMode wrapT)
{
    const int w = image.s(), h = image.t();
    if (w <= 0 || h <= 0) return glm::dvec3(1.0);
    const double x = st.x * w - 0.5, y = st.y * h - 0.5;
    const double x0 = std::floor(x), y0 = std::floor(y);
    const double fx = x - x0, fy = y - y0;
    glm::dvec3 sum(0.0);
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) {
            const int s = wrapIndex(int(x0) + i, w, wrapS), t = wrapIndex(int(y0) + j, h, wrapT);
            const osg::Vec4 c = image.getColor(unsigned(s), unsigned(t));
            const double weight = (i ? fx : 1.0 - fx) * (j ? fy : 1.0 - fy);
            sum += weight * glm::dvec3(c.r(), c.g(), c.b());
        }
    return sum;
}

glm::dvec3 SceneShading::shade(const TriangleMesh& mesh, const Hit& hit, const glm::dvec3& dir, const SceneLight& light) const
{
    if (!hit.hit || hit.triangle >= triangles.size() || hit.triangle >= mesh.triangles.size()) return glm::dvec3(0.0);
    const TriangleLook& t = triangles[hit.triangle];
    const SurfaceLook& look = looks[t.look];
    const glm::uvec3 corner = mesh.triangles[hit.triangle];
    const glm::dvec3 a = mesh.vertices[corner.x], b = mesh.vertices[corner.y], c = mesh.vertices[corner.z];
    const glm::dvec3 weight = barycentric(a, b, c, hit.point);
    // GL's front face: counter-clockwise as seen, so the winding's normal faces the ray's origin
    const bool front = glm::dot(glm::cross(b - a, c - a), dir) < 0.0;
    // n.l per corner as scene.vert lights it (a corner without a normal is lit fully on both faces)
    double ndl = 0.0;
    for (int k = 0; k < 3; ++k) {
        const double l2 = glm::dot(t.normal[k], t.normal[k]);
        double lit = 1.0;
        if (l2 > 1e-20) {
            const double cosine = glm::dot(t.normal[k], light.towardsSun) / std::sqrt(l2);
            lit = std::max(front ? cosine : -cosine, 0.0);
        }
        ndl += weight[k] * lit;
    }
    const glm::dvec3 sun = light.sunShare ? light.sunShare(hit.point) * ndl : glm::dvec3(ndl);
    const glm::dvec3 lit = look.emission + look.ambient * light.ambient + look.diffuse * light.sunColor * sun;
    if (!look.texture) return lit;
    const glm::dvec2 st = weight.x * t.texCoord[0] + weight.y * t.texCoord[1] + weight.z * t.texCoord[2];
    const glm::dvec3 texel = look.nearest ? sampleNearest(*look.texture, st, look.wrapS, look.wrapT)
                                          : sampleBilinear(*look.texture, st, look.wrapS, look.wrapT);
    return lit * glm::dvec3(osgWater::optics::decodeSrgb(glm::vec3(texel)));
}

}
