// The public face of the water: every call forwards to the private implementation (WaterNodeImpl),
// so that the passes, caches and states behind it can change without breaking users.
#include "node/WaterNodeImpl.h"
#include <osgWater/Version>

using namespace osgWater;

WaterNode::WaterNode() : _impl(new WaterNodeImpl(*this))
{
    setNumChildrenRequiringUpdateTraversal(getNumChildrenRequiringUpdateTraversal() + 1);
}

WaterNode::WaterNode(const WaterNode& o, const osg::CopyOp& copyop)
    : osg::Group(o, copyop), _impl(new WaterNodeImpl(*this, *o._impl, copyop))
{
    setNumChildrenRequiringUpdateTraversal(getNumChildrenRequiringUpdateTraversal() + 1);
}

WaterNode::~WaterNode() = default;

void WaterNode::setSettings(WaterSettings* s) { _impl->setSettings(s); }
WaterSettings* WaterNode::getSettings() { return _impl->_settings.get(); }
const WaterSettings* WaterNode::getSettings() const { return _impl->_settings.get(); }

void WaterNode::setSurface(WaterSurface* s) { _impl->setSurface(s); }
WaterSurface* WaterNode::getSurface() { return _impl->_surface.get(); }
const WaterSurface* WaterNode::getSurface() const { return _impl->_surface.get(); }

void WaterNode::setDebugOutput(DebugOutput d) { _impl->setDebugOutput(d); }
DebugOutput WaterNode::getDebugOutput() const { return _impl->_debug; }

void WaterNode::setPassTimingEnabled(bool on) { _impl->setPassTimingEnabled(on); }
bool WaterNode::getPassTimingEnabled() const { return _impl->_passTiming; }
double WaterNode::getPassMilliseconds(osg::Camera* camera, PassId pass) const
{
    return _impl->getPassMeasure(camera, pass).milliseconds;
}
ViewReport WaterNode::getViewReport(osg::Camera* camera) const { return _impl->getViewReport(camera); }
size_t WaterNode::getNumViews() const { return _impl->_views.size(); }

void WaterNode::setSkippingEnabled(bool on) { _impl->setSkippingEnabled(on); }
bool WaterNode::getSkippingEnabled() const { return _impl->_skipping; }

double WaterNode::getCausticsHoldTime() const { return _impl->getCausticsHoldTime(); }
WaterSettings::CausticsGather WaterNode::getActiveCausticsGather() const { return _impl->getActiveCausticsGather(); }
osg::Vec2f WaterNode::getLookupPlanes() const { return _impl->_lookupPlanes; }

void WaterNode::setEnvironmentMap(osg::TextureCubeMap* map) { _impl->setEnvironmentMap(map); }
osg::TextureCubeMap* WaterNode::getEnvironmentMap() const { return _impl->getEnvironmentMap(); }
void WaterNode::dirtyEnvironmentMap() { _impl->dirtyEnvironmentMap(); }

double WaterNode::eyeHeightAboveSurface(const osg::Vec3d& eye, double t) const
{
    return _impl->eyeHeightAboveSurface(eye, t);
}
double WaterNode::getSurfaceHeightAt(double x, double y, osg::Vec3d* normal) const
{
    return _impl->getSurfaceHeightAt(x, y, getSimulationTime(), normal);
}
double WaterNode::getSurfaceHeightAt(double x, double y, double t, osg::Vec3d* normal) const
{
    return _impl->getSurfaceHeightAt(x, y, t, normal);
}
double WaterNode::getSimulationTime() const { return _impl->_simulationTime.load(); }

void WaterNode::traverse(osg::NodeVisitor& nv) { _impl->traverse(nv); }

osg::BoundingSphere WaterNode::computeBound() const
{
    osg::BoundingSphere bs = osg::Group::computeBound();
    if (_impl && _impl->_surface.valid()) bs.expandBy(_impl->_surface->getBound());
    return bs;
}

void WaterNode::resizeGLObjectBuffers(unsigned int maxSize) { _impl->resizeGLObjectBuffers(maxSize); }
void WaterNode::releaseGLObjects(osg::State* state) const { _impl->releaseGLObjects(state); }

const char* osgWater::getVersion()
{
#define OSGWATER_STRING2(x) #x
#define OSGWATER_STRING(x) OSGWATER_STRING2(x)
    return OSGWATER_STRING(OSGWATER_VERSION_MAJOR) "." OSGWATER_STRING(OSGWATER_VERSION_MINOR) "." OSGWATER_STRING(
        OSGWATER_VERSION_PATCH);
}
