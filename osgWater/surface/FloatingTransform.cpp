#include <osgWater/FloatingTransform>
#include <osgWater/WaterNode>
#include "settings/Clamp.h"
#include <osg/NodeVisitor>
#include <osg/FrameStamp>
#include <cmath>

using namespace osgWater;

FloatingTransform::FloatingTransform()
{
    // its matrix follows the waves every frame
    setDataVariance(osg::Object::DYNAMIC);
    setNumChildrenRequiringUpdateTraversal(getNumChildrenRequiringUpdateTraversal() + 1);
}

FloatingTransform::FloatingTransform(const FloatingTransform& o, const osg::CopyOp& copyop)
    : osg::MatrixTransform(o, copyop), _water(o._water), _x(o._x), _y(o._y), _heading(o._heading), _draft(o._draft),
      _damping(o._damping), _tilt(o._tilt)
{
    setNumChildrenRequiringUpdateTraversal(getNumChildrenRequiringUpdateTraversal() + 1);
}

void FloatingTransform::setWater(WaterNode* water)
{
    _water = water;
}

WaterNode* FloatingTransform::getWater() const
{
    osg::ref_ptr<WaterNode> w;
    _water.lock(w);
    return w.get();
}

namespace {
const char* kOwner = "osgWater::FloatingTransform";
}

void FloatingTransform::setPosition(const osg::Vec2d& xy)
{
    setPositionX(xy.x());
    setPositionY(xy.y());
}

void FloatingTransform::setPositionX(double x) { _x = detail::clampTo(kOwner, "positionX", x, -1.0e7, 1.0e7, 0.0); }
void FloatingTransform::setPositionY(double y) { _y = detail::clampTo(kOwner, "positionY", y, -1.0e7, 1.0e7, 0.0); }
void FloatingTransform::setHeading(double r) { _heading = detail::clampTo(kOwner, "heading", r, -1.0e6, 1.0e6, 0.0); }
void FloatingTransform::setDraft(double d) { _draft = detail::clampTo(kOwner, "draft", d, -1.0e4, 1.0e4, 0.0); }
void FloatingTransform::setDamping(double s) { _damping = detail::clampTo(kOwner, "damping", s, 0.0, 1.0e6, 0.0); }

WaterNode* FloatingTransform::findWater(osg::NodeVisitor& nv)
{
    if (WaterNode* w = getWater()) return w;
    const osg::NodePath& path = nv.getNodePath();
    for (auto it = path.rbegin(); it != path.rend(); ++it)
        if (WaterNode* w = dynamic_cast<WaterNode*>(*it)) {
            _water = w;
            return w;
        }
    return nullptr;
}

void FloatingTransform::traverse(osg::NodeVisitor& nv)
{
    WaterNode* water = nv.getVisitorType() == osg::NodeVisitor::UPDATE_VISITOR && nv.getFrameStamp() ? findWater(nv) : nullptr;
    if (water) {
        const double t = nv.getFrameStamp()->getSimulationTime();
        osg::Vec3d n;
        const double z = water->getSurfaceHeightAt(_x, _y, t, &n) - _draft;
        const osg::Vec3d up = _tilt ? n : osg::Vec3d(0.0, 0.0, 1.0);
        if (!_started || _damping <= 0.0) { // follows exactly
            _z = z;
            _up = up;
        } else if (t > _time) {             // a first-order lag with time constant _damping
            const double follow = 1.0 - std::exp(-(t - _time) / _damping);
            _z += (z - _z) * follow;
            _up += (up - _up) * follow;
            _up.normalize();
        }
        _started = true;
        _time = t;
        setMatrix(osg::Matrixd::rotate(_heading, osg::Vec3d(0.0, 0.0, 1.0))
                  * osg::Matrixd::rotate(osg::Vec3d(0.0, 0.0, 1.0), _up) * osg::Matrixd::translate(_x, _y, _z));
    }
    osg::MatrixTransform::traverse(nv);
}
