#include <osgWater/WaterNode>
#include <osgWater/PassMath>
#include <osgUtil/CullVisitor>

using namespace osgWater;

WaterNode::WaterNode()
    : _settings(new WaterSettings), _surface(new WaterSurface), _debug(DEBUG_NONE),
      _settingsRevision(~0u), _surfaceRevision(~0u), _appliedSettings(nullptr), _appliedSurface(nullptr)
{
    setNumChildrenRequiringUpdateTraversal(getNumChildrenRequiringUpdateTraversal() + 1);
    refreshStates();
}

WaterNode::WaterNode(const WaterNode& o, const osg::CopyOp& copyop)
    : osg::Group(o, copyop),
      _settings(o._settings.valid() ? osg::clone(o._settings.get(), copyop) : new WaterSettings),
      _surface(o._surface.valid() ? osg::clone(o._surface.get(), copyop) : new WaterSurface),
      _debug(o._debug),
      _settingsRevision(~0u), _surfaceRevision(~0u), _appliedSettings(nullptr), _appliedSurface(nullptr)
{
    setNumChildrenRequiringUpdateTraversal(getNumChildrenRequiringUpdateTraversal() + 1);
    refreshStates();
}

void WaterNode::setSettings(WaterSettings* s)
{
    _settings = s ? s : new WaterSettings;
    refreshStates();
}

void WaterNode::setSurface(WaterSurface* s)
{
    _surface = s ? s : new WaterSurface;
    refreshStates();
    dirtyBound();
}

void WaterNode::setDebugOutput(DebugOutput d)
{
    _debug = d;
    _settingsRevision = ~0u;
    refreshStates();
}

void WaterNode::refreshStates()
{
    if (_appliedSettings == _settings.get() && _settingsRevision == _settings->getRevision()
        && _appliedSurface == _surface.get() && _surfaceRevision == _surface->getRevision())
        return;
    if (_appliedSurface != _surface.get() || _surfaceRevision != _surface->getRevision()) dirtyBound();
    _states.applySettings(*_settings, *_surface, _debug);
    _appliedSettings = _settings.get();
    _appliedSurface = _surface.get();
    _settingsRevision = _settings->getRevision();
    _surfaceRevision = _surface->getRevision();
}

osg::BoundingSphere WaterNode::computeBound() const
{
    osg::BoundingSphere bs = osg::Group::computeBound();
    if (_surface.valid()) bs.expandBy(_surface->getBound());
    return bs;
}

void WaterNode::releaseGLObjects(osg::State* state) const
{
    osg::Group::releaseGLObjects(state);
    if (_surface.valid()) _surface->releaseGLObjects(state);
    _states.getSceneStateSet()->releaseGLObjects(state);
    _states.getWaterStateSet()->releaseGLObjects(state);
}

void WaterNode::traverse(osg::NodeVisitor& nv)
{
    if (nv.getVisitorType() == osg::NodeVisitor::UPDATE_VISITOR) {
        refreshStates();
        if (nv.getFrameStamp()) _states.applyTime(*_surface, nv.getFrameStamp()->getSimulationTime());
        osg::Group::traverse(nv);
        return;
    }
    if (osgUtil::CullVisitor* cv = nv.asCullVisitor()) {
        cull(*cv);
        return;
    }
    osg::Group::traverse(nv);
    // intersections, statistics and the like: the surface takes part like a child
    _surface->accept(nv);
}

void WaterNode::cull(osgUtil::CullVisitor& cv)
{
    osg::StateSet* sceneState = _states.getSceneStateSet();
    osg::Camera* camera = cv.getCurrentCamera();
    const WaterSettings& s = *_settings;

    // 1. is the water visible at all? If not, the passes cannot change the image: draw the scene only
    const bool waterVisible = camera && !cv.isCulled(_surface->getBound());
    const bool wantReflection = s.getReflectionEnabled();
    const bool wantRefraction = s.getRefractionEnabled();
    if (!waterVisible) {
        cv.pushStateSet(sceneState);
        osg::Group::traverse(cv);
        cv.popStateSet();
        return;
    }

    // 2. this view's passes
    ViewPasses* passes = _views.get(camera, this, sceneState, s.getReflectionTextureSize(), s.getRefractionTextureSize());

    // 3. frame context, in the water's local frame
    PassContext ctx;
    ctx.view = *cv.getModelViewMatrix();
    ctx.projection = *cv.getProjectionMatrix();
    ctx.scene = osg::Group::computeBound();
    ctx.level = _surface->getLevel();
    ctx.clearance = _surface->getMaxAmplitude() + s.getClipOffset();
    const double eyeHeight = eyePosition(ctx.view).z() - ctx.level;
    ctx.eyeBelow = eyeHeight < 0.0;
    ctx.fovExtension = s.fovExtensionAt(eyeHeight);
    ctx.clearColor = camera->getClearColor();
    ctx.settings = &s;
    passes->setTimingEnabled(_passTiming);
    passes->update(ctx, wantReflection, wantRefraction);

    // 4. the passes (pre-render stages of this view)
    if (wantReflection) passes->getReflectionCamera()->accept(cv);
    if (wantRefraction) passes->getRefractionCamera()->accept(cv);

    // 5. the scene and the water surface in the main view
    cv.pushStateSet(sceneState);
    cv.pushStateSet(passes->getStateSet());
    osg::Group::traverse(cv);
    cv.pushStateSet(_states.getWaterStateSet());
    _surface->accept(cv);
    cv.popStateSet();
    cv.popStateSet();
    cv.popStateSet();
}
