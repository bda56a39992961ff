#include "RayCaster.h"
#include <glm/geometric.hpp>
#include <cmath>
#include <limits>
#include <mutex>
#include <stdexcept>

namespace bench {

RTCDevice embreeDevice()
{
    static RTCDevice device = nullptr;
    static std::once_flag once;
    std::call_once(once, [] {
        device = rtcNewDevice(nullptr);
        if (!device) throw std::runtime_error("Embree: cannot create a device");
    });
    return device;
}

RayCaster::RayCaster(TriangleMesh mesh) : _mesh(std::move(mesh))
{
    _scene = rtcNewScene(embreeDevice());
    rtcSetSceneBuildQuality(_scene, RTC_BUILD_QUALITY_HIGH);
    if (!_mesh.triangles.empty()) {
        RTCGeometry g = rtcNewGeometry(embreeDevice(), RTC_GEOMETRY_TYPE_TRIANGLE);
        float* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                               3 * sizeof(float), _mesh.vertices.size()));
        for (size_t i = 0; i < _mesh.vertices.size(); ++i)
            for (int c = 0; c < 3; ++c) v[3 * i + c] = float(_mesh.vertices[i][c]);
        unsigned* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                       3 * sizeof(unsigned), _mesh.triangles.size()));
        for (size_t i = 0; i < _mesh.triangles.size(); ++i)
            for (int c = 0; c < 3; ++c) idx[3 * i + c] = _mesh.triangles[i][c];
        rtcCommitGeometry(g);
        rtcAttachGeometry(_scene, g);
        rtcReleaseGeometry(g);
    }
    rtcCommitScene(_scene);
}

RayCaster::~RayCaster()
{
    rtcReleaseScene(_scene);
}

Hit RayCaster::intersect(const glm::dvec3& org, const glm::dvec3& dir, double tnear, double tfar) const
{
    Hit h;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh{};
    rh.ray.org_x = float(org.x); rh.ray.org_y = float(org.y); rh.ray.org_z = float(org.z);
    rh.ray.dir_x = float(dir.x); rh.ray.dir_y = float(dir.y); rh.ray.dir_z = float(dir.z);
    rh.ray.tnear = float(tnear);
    rh.ray.tfar = float(std::min(tfar, double(std::numeric_limits<float>::max())));
    rh.ray.mask = 0xffffffffu;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(_scene, &context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return h;
    h.hit = true;
    h.triangle = rh.hit.primID;
    // the same triangle in double precision (plane intersection; Embree's float t is the fallback)
    const glm::uvec3 tri = _mesh.triangles[h.triangle];
    const glm::dvec3 a = _mesh.vertices[tri.x], b = _mesh.vertices[tri.y], c = _mesh.vertices[tri.z];
    glm::dvec3 n = glm::cross(b - a, c - a);
    const double len = glm::length(n);
    h.t = rh.ray.tfar;
    if (len > 0.0) {
        n /= len;
        const double denom = glm::dot(n, dir);
        if (std::fabs(denom) > 1e-12 * glm::length(dir)) {
            const double t = glm::dot(n, a - org) / denom;
            if (std::isfinite(t) && std::fabs(t - h.t) <= 1e-3 * (1.0 + std::fabs(h.t))) h.t = t;
        }
        h.normal = n;
    }
    h.point = org + h.t * dir;
    return h;
}

}
