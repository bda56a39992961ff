#include "node/WaterNodeImpl.h"
#include "frame/PassMath.h"
#include "frame/DrawNodes.h"
#include "optics/Srgb.h"
#include <osgUtil/CullVisitor>
#include <osgUtil/IntersectionVisitor>
#include <osgUtil/LineSegmentIntersector>
#include <OpenThreads/ScopedLock>
#include <algorithm>
#include <cmath>
#include <limits>

using namespace osgWater;

WaterNodeImpl::WaterNodeImpl(WaterNode& node)
    : _node(node), _settings(new WaterSettings), _surface(new WaterSurface), _debug(DEBUG_NONE),
      _settingsRevision(~0u), _surfaceRevision(~0u), _appliedSettings(nullptr), _appliedSurface(nullptr),
      _caustics(node, _states)
{
    _underwater = new UnderwaterView(_states.getPrograms());
    _surfaceMeter = new PassMeter;
    _surfaceMeter->setEnabled(false);
    refreshStates();
}

WaterNodeImpl::WaterNodeImpl(WaterNode& node, const WaterNodeImpl& o, const osg::CopyOp& copyop)
    : _node(node),
      _settings(o._settings.valid() ? osg::clone(o._settings.get(), copyop) : new WaterSettings),
      _surface(o._surface.valid() ? osg::clone(o._surface.get(), copyop) : new WaterSurface),
      _debug(o._debug),
      _settingsRevision(~0u), _surfaceRevision(~0u), _appliedSettings(nullptr), _appliedSurface(nullptr),
      _caustics(node, _states)
{
    _underwater = new UnderwaterView(_states.getPrograms());
    _surfaceMeter = new PassMeter;
    setSkippingEnabled(o._skipping);
    setPassTimingEnabled(o._passTiming);
    _userEnvironment = o._userEnvironment; // the user's texture, shared like a child's
    refreshStates();
}

void WaterNodeImpl::setSettings(WaterSettings* s)
{
    _settings = s ? s : new WaterSettings;
    refreshStates();
}

void WaterNodeImpl::setSurface(WaterSurface* s)
{
    _surface = s ? s : new WaterSurface;
    refreshStates();
    _node.dirtyBound();
}

void WaterNodeImpl::setDebugOutput(DebugOutput d)
{
    _debug = d;
    _settingsRevision = ~0u;
    refreshStates();
}

void WaterNodeImpl::setPassTimingEnabled(bool on)
{
    _passTiming = on;
    _surfaceMeter->setEnabled(on);
    _underwater->setTimingEnabled(on);
    _caustics.setTimingEnabled(on);
}

PassMeasure WaterNodeImpl::getPassMeasure(osg::Camera* camera, PassId pass) const
{
    const ViewPasses* p = _views.find(camera);
    const GlowPasses* glow = p ? p->getGlow() : nullptr;
    switch (pass) {
    case PASS_SUN_DEPTH:
    case PASS_PHOTONS: return _passTiming ? _caustics.getMeasure(pass) : PassMeasure();
    case PASS_REFLECTION: return p ? p->getReflectionMeasure() : PassMeasure();
    case PASS_REFRACTION: return p ? p->getRefractionMeasure() : PassMeasure();
    case PASS_GLOW_HIGHLIGHT: return glow ? glow->getHighlightMeasure() : PassMeasure();
    case PASS_GLOW_BLUR_H: return glow ? glow->getBlurMeasure() : PassMeasure();
    case PASS_GLOW_COMPOSITE: return glow ? glow->getCompositeMeasure() : PassMeasure();
    case PASS_SURFACE: return _surfaceMeter->getMeasure();
    case PASS_CAP: return _underwater->getCapMeasure();
    case PASS_BACKDROP: return _underwater->getBackdropMeasure();
    default: return PassMeasure();
    }
}

ViewReport WaterNodeImpl::getViewReport(osg::Camera* camera) const
{
    ViewReport r;
    _views.report(camera, r); // the plan, the view's own passes, under the map's lock
    for (int i = 0; i < PASS_COUNT; ++i) {
        const PassMeasure m = getPassMeasure(camera, PassId(i));
        r.milliseconds[i] = m.milliseconds;
        r.fragments[i] = m.fragments;
    }
    _caustics.report(r);
    return r;
}

WaterSettings::CausticsGather WaterNodeImpl::getActiveCausticsGather() const
{
    return _caustics.getActiveGather();
}

namespace {

// the statistics' attribute names of each row, made once ("" for a row not measured on its own)
struct PassStatNames {
    std::string ran[PASS_COUNT], gpuMs[PASS_COUNT], fragments[PASS_COUNT];
    PassStatNames()
    {
        for (int i = 0; i < PASS_COUNT; ++i) {
            ran[i] = std::string("osgWater ") + passRow(PassId(i)).name + " ran";
            if (const char* label = gpuTimeLabel(PassId(i))) {
                gpuMs[i] = std::string("osgWater ") + label + " GPU ms";
                fragments[i] = std::string("osgWater ") + label + " fragments";
            }
        }
    }
};

}

void WaterNodeImpl::recordPassStats(osgUtil::CullVisitor& cv, const ViewFrame& v, const PassPlan& plan) const
{
    static const PassStatNames names;
    osg::View* view = cv.getCurrentCamera()->getView();
    osg::Stats* stats = view ? view->getStats() : nullptr;
    if (!stats) return;
    for (int i = 0; i < PASS_COUNT; ++i) {
        stats->setAttribute(v.frameNumber, names.ran[i], plan.runs(PassId(i)) ? 1.0 : 0.0);
        if (names.gpuMs[i].empty()) continue;
        const PassMeasure m = getPassMeasure(cv.getCurrentCamera(), PassId(i));
        if (m.milliseconds >= 0.0) stats->setAttribute(v.frameNumber, names.gpuMs[i], m.milliseconds);
        if (m.fragments >= 0.0) stats->setAttribute(v.frameNumber, names.fragments[i], m.fragments);
    }
}

void WaterNodeImpl::setSkippingEnabled(bool on)
{
    _skipping = on;
    _underwater->setCapSkipping(on);
}

void WaterNodeImpl::refreshStates()
{
    if (_appliedSettings == _settings.get() && _settingsRevision == _settings->getRevision()
        && _appliedSurface == _surface.get() && _surfaceRevision == _surface->getRevision())
        return;
    if (_appliedSurface != _surface.get() || _surfaceRevision != _surface->getRevision()) _node.dirtyBound();
    _states.applySettings(*_settings, *_surface, _debug);
    _underwater->setWaveBand(_surface->getLevel(), _surface->usesGrid() ? _surface->getMaxAmplitude() : 0.0);
    // the grid is rebuilt when its size or resolution changes: time the one drawn now
    if (_surface->usesGrid() && !_surface->getGeometry()->getDrawCallback()) _surfaceMeter->attach(_surface->getGeometry());
    _appliedSettings = _settings.get();
    _appliedSurface = _surface.get();
    _settingsRevision = _settings->getRevision();
    _surfaceRevision = _surface->getRevision();
}

void WaterNodeImpl::resizeGLObjectBuffers(unsigned int maxSize)
{
    _node.osg::Group::resizeGLObjectBuffers(maxSize);
    _surface->resizeGLObjectBuffers(maxSize);
    _states.resizeGLObjectBuffers(maxSize);
    _underwater->resizeGLObjectBuffers(maxSize);
    _views.resizeGLObjectBuffers(maxSize);
    {
        OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_environmentMutex);
        if (_environment.valid()) _environment->resizeGLObjectBuffers(maxSize);
    }
    _caustics.resizeGLObjectBuffers(maxSize);
}

void WaterNodeImpl::releaseGLObjects(osg::State* state) const
{
    _node.osg::Group::releaseGLObjects(state);
    _surface->releaseGLObjects(state);
    _surfaceMeter->releaseGLObjects(state);
    _states.releaseGLObjects(state);
    _underwater->releaseGLObjects(state);
    _views.releaseGLObjects(state);
    {
        // a released map holds nothing: EnvironmentMap::stale() sees its texture gone
        OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_environmentMutex);
        if (_environment.valid()) _environment->releaseGLObjects(state);
    }
    _caustics.releaseGLObjects(state);
}

void WaterNodeImpl::traverse(osg::NodeVisitor& nv)
{
    if (nv.getVisitorType() == osg::NodeVisitor::UPDATE_VISITOR) {
        refreshStates();
        // (the waves are brought to this time by the culls whose passes read them)
        if (nv.getFrameStamp()) _simulationTime = nv.getFrameStamp()->getSimulationTime();
        _node.osg::Group::traverse(nv);
        // bounds are computed lazily; views may cull in parallel threads: compute them here, once
        _node.getBound();
        _surface->getBoundingBox();
        const osg::BoundingSphere children = _node.osg::Group::computeBound();
        updateSceneFacts(children);
        updateEnvironment(children);
        return;
    }
    if (osgUtil::CullVisitor* cv = nv.asCullVisitor()) {
        cull(*cv);
        return;
    }
    _node.osg::Group::traverse(nv);
    // intersections, statistics and the like: the surface takes part like a child; a line
    // segment meets the animated grid, not its flat CPU geometry
    osgUtil::IntersectionVisitor* iv = nv.asIntersectionVisitor();
    if (iv && _surface->usesGrid() && dynamic_cast<osgUtil::LineSegmentIntersector*>(iv->getIntersector()))
        intersectSurface(*iv);
    else
        _surface->accept(nv);
}

void WaterNodeImpl::intersectSurface(osgUtil::IntersectionVisitor& iv)
{
    osgUtil::LineSegmentIntersector* lsi = static_cast<osgUtil::LineSegmentIntersector*>(iv.getIntersector());
    if (lsi->reachedLimit()) return;
    // the visitor's intersector is the user's, in its own frame: bring its segment into this
    // node's local frame the way OSG's clones do
    const osg::Matrix toLocal = osgUtil::LineSegmentIntersector::getTransformation(iv, lsi->getCoordinateFrame());
    double ratio;
    osg::Vec3d point, normal;
    if (!_surface->intersect(lsi->getStart() * toLocal, lsi->getEnd() * toLocal, _simulationTime.load(), ratio, point,
                             normal))
        return;
    osgUtil::LineSegmentIntersector::Intersection hit;
    hit.ratio = ratio;
    hit.nodePath = iv.getNodePath();
    hit.nodePath.push_back(_surface.get());
    hit.drawable = _surface->getGeometry();
    hit.matrix = iv.getModelMatrix();
    hit.localIntersectionPoint = point;
    hit.localIntersectionNormal = normal;
    lsi->insertIntersection(hit);
}

double WaterNodeImpl::getSurfaceHeightAt(double x, double y, double t, osg::Vec3d* normal) const
{
    // a grid follows the waves; a user mesh is drawn as it is, about the level
    const bool grid = _surface->usesGrid();
    if (normal) *normal = grid ? _surface->normal(x, y, t) : osg::Vec3d(0.0, 0.0, 1.0);
    return grid ? _surface->height(x, y, t) : _surface->getLevel();
}

double WaterNodeImpl::eyeHeightAboveSurface(const osg::Vec3d& eye, double t) const
{
    return eye.z() - getSurfaceHeightAt(eye.x(), eye.y(), t);
}

void WaterNodeImpl::cull(osgUtil::CullVisitor& cv)
{
    if (!cv.getCurrentCamera()) { // no view to hold passes for: the scene alone
        ScopedStateSets states(cv, { _states.getSceneStateSet() });
        _node.osg::Group::traverse(cv);
        return;
    }
    if (isWaterPass(cv.getCurrentCamera())) { // inside another water's pass: a guest, no passes
        cullAsGuest(cv);
        return;
    }
    // 1. the frame's facts: where the eye is, whether the water is in view, what the context
    //    can do, the shared caustics
    ViewFrame v = gatherFacts(cv);

    // 2. which passes run: the pass table, planned from the facts (a pass nothing reads does not)
    PassPlan plan = planPasses(v.facts);
    if ((plan.runs(PASS_PHOTONS) || plan.runs(PASS_SUN_DEPTH)) && !_caustics.claim(v.frameNumber, v.contextID, v.time, v.facts, plan, v.support)) {
        v.facts.causticsDone = true; // another view on this context rendered them meanwhile
        plan = planPasses(v.facts);
    }
    // the waves' textures as of this frame, only for a frame that draws or reads them: with the
    // water out of view (and no caustics to render) the cascades are neither filled nor uploaded
    if (plan.reads(RES_WAVES)) _states.applyTime(*_surface, v.time);

    // 3. aim what runs: one SceneLighting for the view and every pass that draws the scene; the
    //    water shader's defines follow what runs
    const SceneLighting lighting = sceneLighting(v, plan);
    applySceneLighting(v.lighting, lighting, v.ctx.view);
    if (plan.usesViewPasses()) {
        v.passes = viewPasses(cv, v);
        if (plan.runs(PASS_GLOW_HIGHLIGHT)) prepareGlow(cv, v);
        v.passes->update(v.ctx, plan, lighting);
    }

    // 4. walk the table: pre-render passes first, then the view's own rows
    for (int i = 0; i < PASS_COUNT; ++i)
        if (plan.runs(PassId(i))) cullPass(PassId(i), cv, v);
    _views.setPlan(cv.getCurrentCamera(), plan);
    if (_passTiming) recordPassStats(cv, v, plan);
}

void WaterNodeImpl::warnIfScaledUnevenly(const osg::Matrixd& view)
{
    const osg::Vec3d s = axisScales(view);
    const double lo = std::min(s.x(), std::min(s.y(), s.z())), hi = std::max(s.x(), std::max(s.y(), s.z()));
    if (hi <= lo * 1.001 || _warnedUnevenScale.exchange(true)) return;
    OSG_WARN << "osgWater: WaterNode \"" << _node.getName() << "\" is under a non-uniform scale (" << lo << " to " << hi
             << "): light fades over distances in its local frame, and the sun's direction is bent" << std::endl;
}

void WaterNodeImpl::cullAsGuest(osgUtil::CullVisitor& cv)
{
    if (cv.getFrameStamp()) _states.applyTime(*_surface, cv.getFrameStamp()->getSimulationTime()); // the guest draws the surface
    // the host pass's camera carries its lighting (clip plane, sun, fog); this water's scene and
    // its surface under the guest program go beneath it
    {
        ScopedStateSets states(cv, { _states.getSceneStateSet() });
        _node.osg::Group::traverse(cv);
    }
    ScopedStateSets states(cv, { _states.getSceneStateSet(), _states.getWaterStateSet(), _states.getGuestStateSet() });
    _surface->getUniformMesh()->accept(cv); // the rings follow an eye: not the host pass's
}

WaterNodeImpl::ViewFrame WaterNodeImpl::gatherFacts(osgUtil::CullVisitor& cv)
{
    const WaterSettings& s = *_settings;
    osg::Camera* camera = cv.getCurrentCamera();
    ViewFrame v;
    v.contextID = cv.getState() ? cv.getState()->getContextID() : 0u;
    v.frameNumber = cv.getFrameStamp() ? cv.getFrameStamp()->getFrameNumber() : 0u;
    v.support = support(v.contextID);
    const double t = cv.getFrameStamp() ? cv.getFrameStamp()->getSimulationTime() : 0.0;
    v.time = t;

    // the view, in the water's local frame
    PassContext& ctx = v.ctx;
    ctx.view = *cv.getModelViewMatrix();
    ctx.projection = *cv.getProjectionMatrix();
    ctx.scene = _node.osg::Group::computeBound();
    ctx.level = _surface->getLevel();
    ctx.clearance = clearance();
    const osg::Vec4 background = camera->getClearColor(); // a display value; the passes hold linear light
    const glm::vec3 linear = optics::decodeSrgb(glm::vec3(background.r(), background.g(), background.b()));
    ctx.clearColor.set(linear.x, linear.y, linear.z, background.a());
    ctx.settings = &s;
    ctx.truePositions = _debug == DEBUG_BOTTOM_HIT;
    warnIfScaledUnevenly(ctx.view);
    const osg::Vec3d eye = eyePosition(ctx.view);
    // is the water in view? The surface's box, not its sphere: a flat lake's sphere reaches far
    // above and below it
    const osg::BoundingBox& water = _surface->getBoundingBox();
    const bool boxCulled = cv.isCulled(water);
    const bool boxSeen = !boxCulled && (water.contains(eye) ||
                                        boxInsidePlanes(water, cv.getCurrentCullingSet().getFrustum().getPlaneList()));
    // the eye's height over the waves under it; outside their band, and with nothing of them in
    // view, its height over the level has the same sign and the waves are not evaluated (the wind's
    // are a few milliseconds of FFTs a frame)
    double eyeHeight = eye.z() - ctx.level;
    if (boxSeen || std::abs(eyeHeight) <= _surface->getMaxAmplitude()) eyeHeight = eyeHeightAboveSurface(eye, t);
    ctx.eyeBelow = eyeHeight < 0.0;
    ctx.eyeAmongWaves = _surface->usesGrid() && std::abs(eye.z() - ctx.level) <= _surface->getMaxAmplitude();
    ctx.fovExtension = s.fovExtensionAt(eyeHeight);

    FrameFacts& f = v.facts;
    f.eyeBelow = ctx.eyeBelow;
    f.waterInView = boxSeen || (!boxCulled && ctx.eyeBelow);
    f.reflectionEnabled = s.getReflectionEnabled();
    f.refractionEnabled = s.getRefractionEnabled();
    // never over debug outputs: they are data, and the glow would add light to coordinates
    f.glowInView = _debug == DEBUG_NONE && cv.getViewport() && GlowPasses::highlightInView(ctx, *_surface);
    {
        OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_environmentMutex);
        f.environment = _environment.valid();
        if (f.environment) _environment->setBackground(ctx.clearColor); // the views' background
        f.environmentStale = f.environment && _environment->stale(v.contextID);
    }

    v.lighting = _views.getLighting(camera);
    // the shared caustics: aimed once per frame; whether this context has them already and whether
    // its sun depth map is stale go into the facts
    _caustics.prepare(v.frameNumber, v.contextID, v.time, clearance(), v.support,
                      [&](const char* what, int size) { return fitTexture(what, size, v.support); }, v.facts);
    return v;
}

ViewPasses* WaterNodeImpl::viewPasses(osgUtil::CullVisitor& cv, const ViewFrame& v)
{
    const WaterSettings& s = *_settings;
    // the targets: the fixed square sizes, or a fraction of this view's viewport
    const osg::Viewport* vp = cv.getViewport();
    auto target = [&](const char* what, int fixedSize) {
        const osg::Vec2i size = passTargetSize(vp ? vp->width() : 0.0, vp ? vp->height() : 0.0, s.getPassTargetScale(),
                                               fixedSize);
        return osg::Vec2i(fitTexture(what, size.x(), v.support), fitTexture(what, size.y(), v.support));
    };
    ViewPasses* passes = _views.get(cv.getCurrentCamera(), &_node, _states.getSceneStateSet(), _states.getWaterStateSet(),
                                    &_states.getPrograms(),
                                    target("reflection target", s.getReflectionTextureSize()),
                                    target("refraction target", s.getRefractionTextureSize()));
    passes->setTimingEnabled(_passTiming);
    return passes;
}

SceneLighting WaterNodeImpl::sceneLighting(const ViewFrame& v, const PassPlan& plan) const
{
    const WaterSettings& s = *_settings;
    SceneLighting l;
    l.towardsSun = s.getSunDirection();
    l.level = v.ctx.level;
    l.display = true; // the view's own: what the kit draws there is encoded once, at the end
    // eq. 10: with the eye under water every object is seen through water
    if (v.ctx.eyeBelow) {
        l.fogColor = s.getBodyColor();
        l.fogExtinction = s.getViewExtinction();
    }
    // the caustics, when this frame has them on this context (rendered now or by another view)
    // (per pixel, whenever the sun's depth map holds: the scene program makes them itself)
    if (v.facts.caustics && (plan.runs(PASS_GATHER) || v.facts.causticsDone || v.facts.causticsInScene)) {
        _caustics.light(v.facts, l);
    }
    return l;
}

void WaterNodeImpl::cullPass(PassId pass, osgUtil::CullVisitor& cv, const ViewFrame& v)
{
    osg::StateSet* scene = _states.getSceneStateSet();
    osg::StateSet* water = _states.getWaterStateSet();
    ViewPasses* p = v.passes; // null only when the plan runs nothing but the shared rows and the scene
    switch (pass) {
    case PASS_ENVIRONMENT:
        if (claimEnvironment(v.contextID)) _environment->accept(cv);
        break;
    case PASS_SUN_DEPTH:
    case PASS_PHOTONS:
    case PASS_GATHER:
        _caustics.cull(pass, cv, v.facts);
        break;
    case PASS_REFLECTION: p->getReflectionCamera()->accept(cv); break;
    case PASS_REFRACTION: p->getRefractionCamera()->accept(cv); break;
    case PASS_GLOW_HIGHLIGHT:
    case PASS_GLOW_BLUR_H:
    case PASS_GLOW_BLUR_V:
        p->getGlow()->getPassCamera(pass)->accept(cv);
        break;
    case PASS_SCENE: {
        ScopedStateSets states(cv, { scene, v.lighting });
        _node.osg::Group::traverse(cv);
        break;
    }
    case PASS_SURFACE:
    case PASS_BACKDROP:
    case PASS_CAP: { // the water program over the scene's, with this view's inputs (cap and backdrop set their bins)
        ScopedStateSets states(cv, { scene, v.lighting, p->getWaterInputs(), water,
                                     pass == PASS_SURFACE ? _states.getSurfaceBinStateSet() : nullptr });
        osg::Node* node = pass == PASS_SURFACE ? static_cast<osg::Node*>(_surface.get())
                        : pass == PASS_CAP ? _underwater->getCap() : _underwater->getBackdrop();
        node->accept(cv);
        break;
    }
    case PASS_GLOW_COMPOSITE: p->getGlow()->getComposite()->accept(cv); break;
    case PASS_COUNT: break;
    }
}

void WaterNodeImpl::prepareGlow(osgUtil::CullVisitor& cv, const ViewFrame& v)
{
    const osg::Viewport* vp = cv.getViewport();
    const double f = _settings->getGlowResolution();
    const int w = fitTexture("glow target width", std::max(1, int(std::lround(vp->width() * f))), v.support);
    const int h = fitTexture("glow target height", std::max(1, int(std::lround(vp->height() * f))), v.support);
    v.passes->getOrCreateGlow(w, h, v.support.floatTargets)->update(v.ctx, _surface.get(), *vp, _skipping);
}

CausticsSupport WaterNodeImpl::support(unsigned int context)
{
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_supportMutex);
    auto known = _support.find(context);
    if (known == _support.end()) known = _support.emplace(context, CausticsSupport::detect(context)).first;
    return known->second;
}

int WaterNodeImpl::fitTexture(const char* what, int size, const CausticsSupport& support)
{
    if (size <= support.maxTextureSize) return size;
    const std::string key = std::string(what) + std::to_string(size);
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_supportMutex); // views may cull in parallel
    if (_fitWarnings.insert(key).second)
        OSG_WARN << "osgWater: " << what << " " << size << " exceeds this context's GL_MAX_TEXTURE_SIZE, using "
                 << support.maxTextureSize << std::endl;
    return support.maxTextureSize;
}

void WaterNodeImpl::updateSceneFacts(const osg::BoundingSphere& children)
{
    const WaterSettings& s = *_settings;
    const bool planes = s.getReflectionLookup() == WaterSettings::REFLECTION_PLANE ||
                        s.getRefractionLookup() == WaterSettings::PLANE_OFFSET;
    // the caustics' window, and the flat bed of tileable caustics, come from the lit water too
    const bool focus = s.getCausticsEnabled() && (s.getCausticsFocused() || s.getCausticsTileSize() > 0.0f);
    const double level = _surface->getLevel();
    const LitWater lit = _caustics.updateScene(children, level + clearance(), planes || focus);
    // the planes: as set, or the scene's (see WaterSettings::setReflectionPlaneHeight)
    float height = s.getReflectionPlaneHeight(), depth = s.getRefractionPlaneDepth();
    if (height <= 0.0f) height = lit.shaded && lit.meanShadeZ > level ? float(lit.meanShadeZ - level) : s.getReflectionScale();
    if (depth <= 0.0f) depth = lit.box.valid() && lit.meanBedZ < level ? float(level - lit.meanBedZ) : 1.0f;
    _lookupPlanes = osg::Vec2f(std::max(height, 1e-3f), std::max(depth, 1e-3f));
    _states.applyLookupPlanes(_lookupPlanes);
}

void WaterNodeImpl::setEnvironmentMap(osg::TextureCubeMap* map)
{
    _userEnvironment = map;
    updateEnvironment(_node.osg::Group::computeBound());
}

osg::TextureCubeMap* WaterNodeImpl::getEnvironmentMap() const
{
    if (!_settings->getEnvironmentMapEnabled()) return nullptr;
    if (_userEnvironment.valid()) return _userEnvironment.get();
    return _environment.valid() ? _environment->getTexture() : nullptr;
}

void WaterNodeImpl::dirtyEnvironmentMap()
{
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_environmentMutex);
    if (_environment.valid()) _environment->dirty();
}

void WaterNodeImpl::updateEnvironment(const osg::BoundingSphere& children)
{
    const WaterSettings& s = *_settings;
    const bool draw = s.getEnvironmentMapEnabled() && !_userEnvironment.valid();
    {
        OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_environmentMutex);
        if (!draw) {
            _environment = nullptr;
        } else {
            if (!_environment.valid() || _environment->getSize() != s.getEnvironmentMapSize())
                _environment = new EnvironmentMap(&_node, _states.getSceneStateSet(), s.getEnvironmentMapSize());
            // seen from the middle of the surface, just above the crests; lit by the sun alone (no
            // fog, no caustics: it holds what lies above the water)
            const osg::BoundingBox& water = _surface->getBoundingBox();
            SceneLighting l;
            l.towardsSun = s.getSunDirection();
            l.level = _surface->getLevel();
            const osg::Vec3d centre(water.center().x(), water.center().y(), l.level + clearance());
            _environment->aim(centre, children, l);
        }
    }
    _states.setEnvironmentMap(getEnvironmentMap());
}

bool WaterNodeImpl::claimEnvironment(unsigned int contextID)
{
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_environmentMutex);
    if (!_environment.valid() || !_environment->stale(contextID)) return false;
    _environment->markDrawn(contextID);
    return true;
}

double WaterNodeImpl::clearance() const
{
    return _surface->getMaxAmplitude() + _settings->getClipOffset();
}


double WaterNodeImpl::getCausticsHoldTime() const
{
    return _caustics.getHoldTime();
}
