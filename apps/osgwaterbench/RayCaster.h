// Exact ray casting (Embree) over one triangle mesh. Embree finds the triangle; the hit distance
// is then recomputed in double precision on that triangle, so points agree with closed forms far
// below a millimetre.
#pragma once
#include "SceneTriangles.h"
#include <embree3/rtcore.h>

namespace bench {

struct Hit {
    bool hit = false;
    double t = 0.0;
    unsigned int triangle = 0;
    glm::dvec3 point{ 0.0 };
    glm::dvec3 normal{ 0.0, 0.0, 1.0 }; //!< unit geometric normal (either orientation)
};

//! One Embree device shared by every caster (created on first use).
RTCDevice embreeDevice();

class RayCaster
{
public:
    explicit RayCaster(TriangleMesh mesh);
    ~RayCaster();
    RayCaster(const RayCaster&) = delete;
    RayCaster& operator=(const RayCaster&) = delete;

    //! Nearest hit of org + t dir with tnear <= t <= tfar (dir need not be unit; t is in its units).
    Hit intersect(const glm::dvec3& org, const glm::dvec3& dir, double tnear = 0.0, double tfar = 1e30) const;
    size_t size() const { return _mesh.triangles.size(); }
    const TriangleMesh& mesh() const { return _mesh; }

private:
    TriangleMesh _mesh;
    RTCScene _scene = nullptr;
};

}
