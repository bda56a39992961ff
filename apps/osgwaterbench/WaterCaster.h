// The water surface the reference traces. Over the built-in mesh, whatever layout the renderer
// draws: the analytic waves themselves (WaterSurface::intersect, double precision), so the drawn
// mesh's own error is measured, not shared. Over a user mesh: its triangles, as drawn (Embree).
#pragma once
#include "RayCaster.h"
#include <memory>

namespace osgWater { class WaterSurface; }

namespace bench {

class WaterCaster
{
public:
    WaterCaster(const osgWater::WaterSurface& surface, double t);
    //! Nearest crossing of org + t dir with tnear <= t <= tfar (dir need not be unit). The normal is
    //! the geometric one (either orientation); over the waves the analytic normal.
    Hit intersect(const glm::dvec3& org, const glm::dvec3& dir, double tnear = 0.0, double tfar = 1e30) const;
    //! What it traces, for the log.
    std::string describe() const;

private:
    const osgWater::WaterSurface& _surface;
    double _t;
    std::unique_ptr<RayCaster> _mesh; //!< a user mesh's triangles
};

}
