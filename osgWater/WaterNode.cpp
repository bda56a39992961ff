#include <osgWater/WaterNode>
#include <osgWater/PassMath>
#include <osgUtil/CullVisitor>
#include <osg/ComputeBoundsVisitor>
#include <OpenThreads/ScopedLock>
#include <algorithm>
#include <cmath>

using namespace osgWater;

WaterNode::WaterNode()
    : _settings(new WaterSettings), _surface(new WaterSurface), _debug(DEBUG_NONE),
      _settingsRevision(~0u), _surfaceRevision(~0u), _appliedSettings(nullptr), _appliedSurface(nullptr)
{
    setNumChildrenRequiringUpdateTraversal(getNumChildrenRequiringUpdateTraversal() + 1);
    _underwater = new UnderwaterView;
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
    _underwater = new UnderwaterView;
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
    if (_caustics.valid()) _caustics->releaseGLObjects(state);
    _underwater->getCap()->releaseGLObjects(state);
    _underwater->getBackdrop()->releaseGLObjects(state);
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

double WaterNode::eyeHeightAboveSurface(const osg::Vec3d& eye, double t) const
{
    // a grid follows the waves; a user mesh is drawn as it is, about the level
    const double h = _surface->usesGrid() ? _surface->height(eye.x(), eye.y(), t) : _surface->getLevel();
    return eye.z() - h;
}

void WaterNode::cull(osgUtil::CullVisitor& cv)
{
    osg::StateSet* sceneState = _states.getSceneStateSet();
    osg::Camera* camera = cv.getCurrentCamera();
    const WaterSettings& s = *_settings;
    const double t = cv.getFrameStamp() ? cv.getFrameStamp()->getSimulationTime() : 0.0;

    // 1. where is the eye, and is the water in view? Neither under water nor in view: the passes
    //    cannot change the image, draw the scene only
    const osg::Matrixd view = *cv.getModelViewMatrix();
    const double eyeHeight = eyeHeightAboveSurface(eyePosition(view), t);
    const bool eyeBelow = eyeHeight < 0.0;
    // the surface's box, not its sphere: a flat lake's sphere reaches far above and below it
    const bool waterVisible = camera && !cv.isCulled(_surface->getBoundingBox()) &&
                              (eyeBelow || _surface->getBoundingBox().contains(eyePosition(view)) ||
                               boxInsidePlanes(_surface->getBoundingBox(),
                                                           cv.getCurrentCullingSet().getFrustum().getPlaneList()));
    if (!camera || (!waterVisible && !eyeBelow)) {
        cv.pushStateSet(sceneState);
        cv.pushStateSet(_states.getNoCausticsStateSet());
        osg::Group::traverse(cv);
        cv.popStateSet();
        cv.popStateSet();
        return;
    }

    // 2. this view's passes
    const CausticsSupport sup = support(cv.getState() ? cv.getState()->getContextID() : 0u);
    ViewPasses* passes = _views.get(camera, this, sceneState, fitTexture("reflectionTextureSize", s.getReflectionTextureSize(), sup),
                                    fitTexture("refractionTextureSize", s.getRefractionTextureSize(), sup));

    // 3. frame context, in the water's local frame
    PassContext ctx;
    ctx.view = view;
    ctx.projection = *cv.getProjectionMatrix();
    ctx.scene = osg::Group::computeBound();
    ctx.level = _surface->getLevel();
    ctx.clearance = _surface->getMaxAmplitude() + s.getClipOffset();
    ctx.eyeBelow = eyeBelow;
    ctx.fovExtension = s.fovExtensionAt(eyeHeight);
    ctx.clearColor = camera->getClearColor();
    ctx.settings = &s;
    // 3b. caustics: the sun's passes, once per frame for all views (before this view's passes)
    ctx.caustics = cullCaustics(cv, ctx.scene);
    const bool reflection = waterVisible && s.getReflectionEnabled();
    const bool refraction = waterVisible && s.getRefractionEnabled();
    passes->setTimingEnabled(_passTiming);
    passes->update(ctx, reflection, refraction);

    // 4. the passes (pre-render stages of this view)
    if (reflection) passes->getReflectionCamera()->accept(cv);
    if (refraction) passes->getRefractionCamera()->accept(cv);

    // 5. the scene, the water surface, the near-plane cap and the underwater backdrop
    cv.pushStateSet(sceneState);
    cv.pushStateSet(passes->getStateSet());
    osg::Group::traverse(cv);
    cv.pushStateSet(_states.getWaterStateSet());
    if (waterVisible) _surface->accept(cv);
    _underwater->cull(cv, waterVisible, eyeBelow);
    cv.popStateSet();
    cv.popStateSet();
    cv.popStateSet();

    // 6. glow of the sun's highlight, when it can be in view (never over debug outputs: they are
    //    data, and the glow would add light to coordinates)
    if (waterVisible && _debug == DEBUG_NONE) cullGlow(cv, passes, ctx, sup);
    else passes->setGlowDrawn(false);
}

void WaterNode::cullGlow(osgUtil::CullVisitor& cv, ViewPasses* passes, const PassContext& ctx,
                         const CausticsSupport& sup)
{
    const osg::Viewport* vp = cv.getViewport();
    if (!vp || !GlowPasses::highlightInView(ctx, *_surface)) {
        passes->setGlowDrawn(false);
        return;
    }
    const double f = _settings->getGlowResolution();
    const int w = fitTexture("glow target width", std::max(1, int(std::lround(vp->width() * f))), sup);
    const int h = fitTexture("glow target height", std::max(1, int(std::lround(vp->height() * f))), sup);
    GlowPasses* glow = passes->getOrCreateGlow(w, h, sup.floatTargets, this, _states.getSceneStateSet(),
                                               _states.getWaterStateSet());
    glow->update(ctx, _surface.get());
    glow->cull(cv);
    passes->setGlowDrawn(true);
}

CausticsSupport WaterNode::support(unsigned int context)
{
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_supportMutex);
    auto known = _support.find(context);
    if (known == _support.end()) known = _support.emplace(context, CausticsSupport::detect(context)).first;
    return known->second;
}

int WaterNode::fitTexture(const char* what, int size, const CausticsSupport& support)
{
    if (size <= support.maxTextureSize) return size;
    const std::string key = std::string(what) + std::to_string(size);
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_supportMutex); // views may cull in parallel
    if (_fitWarnings.insert(key).second)
        OSG_WARN << "osgWater: " << what << " " << size << " exceeds this context's GL_MAX_TEXTURE_SIZE, using "
                 << support.maxTextureSize << std::endl;
    return support.maxTextureSize;
}

const osg::BoundingBox& WaterNode::sceneBox(const osg::BoundingSphere& bs)
{
    if (bs.center() != _sceneBoxKey.center() || bs.radius() != _sceneBoxKey.radius()) {
        _sceneBoxKey = bs;
        osg::ComputeBoundsVisitor cbv;
        for (unsigned int i = 0; i < getNumChildren(); ++i) getChild(i)->accept(cbv);
        _sceneBox = cbv.getBoundingBox();
    }
    return _sceneBox;
}

const CausticsLighting* WaterNode::cullCaustics(osgUtil::CullVisitor& cv, const osg::BoundingSphere& sceneBound)
{
    const WaterSettings& s = *_settings;
    if (!s.getCausticsEnabled()) return nullptr;
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_causticsMutex);
    CausticsCamera::Frame f;
    f.towardsSun = s.getSunDirection();
    f.water = _surface->getBoundingBox();
    f.scene = sceneBox(sceneBound);
    f.level = _surface->getLevel();
    f.clearance = _surface->getMaxAmplitude() + s.getClipOffset();
    f.surface = _surface.get();
    f.settings = &s;
    if (!CausticsCamera::needed(f)) return nullptr;

    const unsigned int context = cv.getState() ? cv.getState()->getContextID() : 0u;
    const unsigned int frame = cv.getFrameStamp() ? cv.getFrameStamp()->getFrameNumber() : 0u;
    auto done = _causticsFrame.find(context);
    if (_caustics.valid() && done != _causticsFrame.end() && done->second == frame)
        return &_caustics->getLighting(); // another view already rendered them this frame

    const CausticsSupport support = this->support(context);
    const int resolution = fitTexture("causticsResolution", s.getCausticsResolution(), support);
    const int grid = fitTexture("photonGridSize", s.getPhotonGridSize(), support);
    if (!_caustics.valid() || !_caustics->matches(resolution, grid, support.floatTargets))
        _caustics = new CausticsCamera(this, _states.getSceneStateSet(), _states.getWaterStateSet(),
                                       resolution, grid, support.floatTargets);
    f.gather = s.getCausticsGather() == WaterSettings::GATHER_AUTO ? _caustics->autoGather(support)
                                                                  : support.resolve(s.getCausticsGather());
    if (f.gather != _activeGather) {
        if (s.getCausticsGather() != WaterSettings::GATHER_AUTO && f.gather != s.getCausticsGather())
            OSG_WARN << "osgWater: caustics gather " << CausticsCamera::gatherName(s.getCausticsGather())
                     << " is not supported by this context, using " << CausticsCamera::gatherName(f.gather) << std::endl;
        if (!support.floatTargets)
            OSG_WARN << "osgWater: no float render targets, caustics fall back to the CPU gather" << std::endl;
        OSG_DEBUG << "osgWater: caustics gather: " << CausticsCamera::gatherName(f.gather) << std::endl;
        _activeGather = f.gather;
    }
    _caustics->update(f);
    _caustics->cullPasses(cv);
    _causticsFrame[context] = frame;
    return &_caustics->getLighting();
}
