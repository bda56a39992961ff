#include "ReferenceRenderer.h"
#include "optics/Srgb.h"
#include <osgWater/Sky>
#include <osgWater/WaterNode>
#include <glm/geometric.hpp>
#include <algorithm>
#include <cmath>
#include <cstring>

namespace bench {

namespace {

glm::dvec3 toGlm(const osg::Vec3& v) { return glm::dvec3(v.x(), v.y(), v.z()); }

// Seen through `length` metres of water: towards the body colour by each channel's extinction
glm::dvec3 throughWater(const glm::dvec3& c, double length, const ImageSetup& s)
{
    const glm::dvec3 a(std::exp(-s.extinction.x * length), std::exp(-s.extinction.y * length), std::exp(-s.extinction.z * length));
    return s.body + a * (c - s.body);
}

// splitmix64's finaliser: the seed's bits spread over all 64
std::uint64_t mix(std::uint64_t z)
{
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

// a ray's own bits and how many water meetings came before on its path, as one seed
std::uint64_t raySeed(const glm::dvec3& org, const glm::dvec3& dir, int waterHits)
{
    std::uint64_t h = mix(std::uint64_t(waterHits) + 0x9e3779b97f4a7c15ull);
    for (double v : { org.x, org.y, org.z, dir.x, dir.y, dir.z }) {
        std::uint64_t bits;
        std::memcpy(&bits, &v, sizeof bits);
        h = mix(h ^ bits);
    }
    return h;
}

// N's slopes plus a draw of an isotropic Gaussian of total variance `variance` (each axis half),
// a function of `seed` alone
glm::dvec3 subgridNormal(const glm::dvec3& N, double variance, std::uint64_t seed)
{
    if (!(variance > 0.0) || !(N.z > 1e-9)) return N;
    // two uniforms in (0, 1) from the seed's halves, then Box-Muller
    const double u1 = (double(mix(seed) >> 11) + 0.5) * 0x1.0p-53, u2 = (double(mix(~seed) >> 11) + 0.5) * 0x1.0p-53;
    const double r = std::sqrt(-2.0 * std::log(u1)) * std::sqrt(0.5 * variance), a = 6.283185307179586 * u2;
    const glm::dvec2 slope = -glm::dvec2(N.x, N.y) / N.z + r * glm::dvec2(std::cos(a), std::sin(a));
    return glm::normalize(glm::dvec3(-slope.x, -slope.y, 1.0));
}

}

FacetDraw drawFacet(const glm::dvec3& waves, double variance, const glm::dvec3& dir, std::uint64_t seed)
{
    if (!(variance > 0.0) || !(waves.z > 1e-9)) return { waves, true };
    // the area a facet of slopes s shows the ray per unit area of the level, dir . (s, -1) from above
    // (the other way from below): linear in s, so over the draws a Gaussian of the mean slopes' value
    // and sigma |dir.xy| sqrt(variance / 2), of which a facet turned away (below 0) shows nothing.
    // Facets are kept in proportion to it (rejection, the area bounded at 4 sigma over the mean): a
    // weight per facet instead left many rays of a grazing pixel with nothing, and the image noisy.
    const double side = glm::dot(waves, dir) < 0.0 ? 1.0 : -1.0;
    auto shown = [&](const glm::dvec3& n) { return -side * glm::dot(dir, n / n.z); };
    const double bound = shown(waves) + 4.0 * glm::length(glm::dvec2(dir.x, dir.y)) * std::sqrt(0.5 * variance);
    if (!(bound > 0.0)) return { waves, false };
    for (std::uint64_t k = 0; k < 256; ++k) {
        const std::uint64_t draw = mix(seed + k * 0x9e3779b97f4a7c15ull);
        const glm::dvec3 N = subgridNormal(waves, variance, draw);
        const double keep = (double(mix(draw ^ 0x5851f42d4c957f2dull) >> 11) + 0.5) * 0x1.0p-53;
        if (shown(N) > keep * bound) return { N, true };
    }
    return { waves, false }; // a ray this close to the level's plane is not met
}

ImageSetup imageSetup(const osgWater::WaterNode& water, const osg::Vec4& clearColour)
{
    ImageSetup s;
    const osgWater::WaterSettings& settings = *water.getSettings();
    s.light.towardsSun = glm::normalize(toGlm(settings.getSunDirection()));
    s.light.sunColor = toGlm(settings.getSunColor());
    s.light.ambient = toGlm(settings.getAmbientColor());
    s.body = toGlm(settings.getBodyColor());
    s.extinction = toGlm(settings.getViewExtinction());
    osg::ref_ptr<const osgWater::Sky> sky;
    for (unsigned int i = 0; i < water.getNumChildren() && !sky; ++i)
        sky = dynamic_cast<const osgWater::Sky*>(water.getChild(i));
    if (sky) {
        s.sky = [sky](const glm::dvec3& d) { return toGlm(sky->getRadiance(osg::Vec3(float(d.x), float(d.y), float(d.z)))); };
    } else {
        const glm::dvec3 clear(osgWater::optics::decodeSrgb(glm::vec3(clearColour.r(), clearColour.g(), clearColour.b())));
        s.sky = [clear](const glm::dvec3&) { return clear; };
    }
    return s;
}

ReferenceRenderer::ReferenceRenderer(const Reference& ref, const SceneShading& shading, ImageSetup setup)
    : _ref(ref), _shading(shading), _setup(std::move(setup))
{
}

glm::dvec3 ReferenceRenderer::radiance(const glm::dvec3& org, const glm::dvec3& dir, bool inWater) const
{
    return follow(org, dir, inWater, 0);
}

glm::dvec3 ReferenceRenderer::follow(const glm::dvec3& org, const glm::dvec3& dir, bool inWater, int waterHits) const
{
    // a ray that leaves a surface it met starts a little along, clear of that surface; the eye's
    // own rays start at the eye (one a hair above the water meets it micrometres away)
    const double eps = waterHits == 0 ? 0.0 : 1e-6 * (1.0 + glm::length(org));
    const Hit w = waterHits < _setup.maxWaterHits ? _ref.water().intersect(org, dir, eps) : Hit{};
    const Hit s = _ref.scene().intersect(org, dir, eps, w.hit ? w.t : 1e30);
    glm::dvec3 c;
    double length = 0.0; // of this stretch
    if (s.hit && (!w.hit || s.t < w.t)) {
        c = _shading.shade(_ref.scene().mesh(), s, dir, _setup.light);
        length = s.t;
    } else if (w.hit) {
        const Media& m = _ref.media();
        const double n1 = inWater ? m.water : m.air, n2 = inWater ? m.air : m.water;
        // the met facet: the waves' normal tilted by a slope drawn from the roughness there, in
        // proportion to the area it shows the ray (drawFacet)
        const glm::dvec3 waves = _ref.normalAt(w);
        const bool fromAbove = glm::dot(waves, dir) < 0.0;
        const FacetDraw facet = drawFacet(waves, _ref.roughnessAt(w), dir, raySeed(org, dir, waterHits));
        glm::dvec3 N = facet.normal;
        if (!fromAbove) N = -N; // facing the ray, whichever side it comes from
        const double F = fresnelExact(-glm::dot(dir, N), n1, n2);
        c = glm::dvec3(0.0);
        if (facet.met) {
            c = F * follow(w.point, glm::reflect(dir, N), inWater, waterHits + 1);
            glm::dvec3 R;
            if (F < 1.0 && snell(dir, N, n1, n2, R)) c += (1.0 - F) * follow(w.point, R, !inWater, waterHits + 1);
        }
        length = w.t;
    } else {
        if (!inWater) return _setup.sky(dir);
        return _setup.body; // an endless stretch of water
    }
    return inWater ? throughWater(c, length, _setup) : c;
}

std::vector<glm::vec3> ReferenceRenderer::render(const osg::Matrixd& viewMatrix, const osg::Matrixd& projection,
                                                  int width, int height, RenderExtras* extras) const
{
    const osg::Vec3d eyePoint = osg::Matrixd::inverse(viewMatrix).getTrans();
    const bool eyeBelow = _ref.eyeBelow(glm::dvec3(eyePoint.x(), eyePoint.y(), eyePoint.z())); // one eye for every ray
    const size_t pixels = size_t(width) * height;
    // each half's sum and ray count per pixel
    std::vector<glm::dvec3> sum[2] = { std::vector<glm::dvec3>(pixels, glm::dvec3(0.0)),
                                       std::vector<glm::dvec3>(pixels, glm::dvec3(0.0)) };
    std::vector<int> count[2] = { std::vector<int>(pixels, 0), std::vector<int>(pixels, 0) };
    // n x n rays through the cell centres of a grid over each pixel taken (`take`: all, or some)
    auto grid = [&](int n, const std::vector<char>* take) {
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const int half = (i + j) % 2;
                forEachPixelRay(viewMatrix, projection, width, height,
                                [&](int x, int y, const glm::dvec3& eye, const glm::dvec3& dir) {
                                    const size_t k = size_t(y) * width + x;
                                    if (take && !(*take)[k]) return;
                                    sum[half][k] += radiance(eye, dir, eyeBelow);
                                    ++count[half][k];
                                },
                                glm::dvec2((i + 0.5) / n, (j + 0.5) / n));
            }
    };
    auto halfMean = [&](int h, size_t k) { return count[h][k] ? sum[h][k] / double(count[h][k]) : glm::dvec3(0.0); };
    const int n = std::max(1, _setup.samplesPerAxis);
    grid(n, nullptr);
    size_t refined = 0;
    if (n >= 2 && _setup.refineSamplesPerAxis > 0) {
        std::vector<char> noisy(pixels, 0);
        for (size_t k = 0; k < pixels; ++k) {
            const glm::dvec3 d = glm::abs(halfMean(0, k) - halfMean(1, k));
            noisy[k] = std::max({ d.x, d.y, d.z }) > _setup.refineAbove;
            refined += size_t(noisy[k]);
        }
        if (refined) grid(_setup.refineSamplesPerAxis, &noisy);
    }
    std::vector<glm::vec3> image(pixels);
    for (size_t k = 0; k < pixels; ++k) image[k] = glm::vec3((sum[0][k] + sum[1][k]) / double(count[0][k] + count[1][k]));
    if (extras) {
        extras->refinedPixels = refined;
        for (int h = 0; h < 2; ++h) {
            extras->halves[h].assign(n >= 2 ? pixels : 0, glm::vec3(0.0f));
            for (size_t k = 0; n >= 2 && k < pixels; ++k) extras->halves[h][k] = glm::vec3(halfMean(h, k));
        }
    }
    return image;
}

}
