#include "frame/ViewPasses.h"
#include "frame/PassMath.h"
#include <osgWater/WaterSettings>
#include <OpenThreads/ScopedLock>

using namespace osgWater;

namespace {

// A depth search's inputs for one pass: prefix + View, ViewInverse, Proj, and InvProj where the
// water reads it (the refraction's virtual vertices: a drawn point's whole place from its depth)
void setPassMatrices(osg::StateSet* ss, const std::string& prefix, const PassCamera& pass)
{
    const osg::Matrixd& v = pass.getViewMatrix();
    const osg::Matrixd& p = pass.getProjectionMatrix();
    ss->getUniform(prefix + "View")->set(osg::Matrixf(v));
    ss->getUniform(prefix + "ViewInverse")->set(osg::Matrixf(osg::Matrixd::inverse(v)));
    ss->getUniform(prefix + "Proj")->set(osg::Matrixf(p));
    if (osg::Uniform* inverse = ss->getUniform(prefix + "InvProj")) inverse->set(osg::Matrixf(osg::Matrixd::inverse(p)));
}

}

ViewPasses::ViewPasses(osg::Group* scene, osg::StateSet* sceneState, osg::StateSet* waterState,
                       ProgramLibrary* programs, osg::StateSet* lighting, const osg::Vec2i& reflectionSize,
                       const osg::Vec2i& refractionSize)
    : _scene(scene), _sceneState(sceneState), _waterState(waterState), _programs(programs), _lighting(lighting)
{
    _reflection = new ReflectionCamera(scene, sceneState, reflectionSize.x(), reflectionSize.y());
    _refraction = new RefractionCamera(scene, sceneState, refractionSize.x(), refractionSize.y());
    // the callbacks are set once, before any draw; setTimingEnabled() switches them on
    _reflectionMeter = new PassMeter;
    _reflectionMeter->attach(_reflection.get());
    _reflectionMeter->setEnabled(false);
    _refractionMeter = new PassMeter;
    _refractionMeter->attach(_refraction.get());
    _refractionMeter->setEnabled(false);
    // changes every frame: OSG must not draw it while the next frame's cull writes
    _waterInputs = new osg::StateSet;
    _waterInputs->setName("osgWater.viewWaterInputs");
    _waterInputs->setDataVariance(osg::Object::DYNAMIC);
    _waterInputs->setTextureAttribute(UNIT_REFLECTION, _reflection->getColorTexture());
    _waterInputs->setTextureAttribute(UNIT_REFRACTION, _refraction->getColorTexture());
    _waterInputs->setTextureAttribute(UNIT_REFRACTION_DEPTH, _refraction->getDepthTexture());
    _waterInputs->setTextureAttribute(UNIT_REFLECTION_DEPTH, _reflection->getDepthTexture());
    const char* mats[] = { "osgWater_ReflectionMVP", "osgWater_ReflectionView", "osgWater_ReflectionViewInverse",
                           "osgWater_ReflectionProj", "osgWater_RefractionView",
                           "osgWater_RefractionViewInverse", "osgWater_RefractionProj", "osgWater_RefractionInvProj" };
    for (const char* m : mats) _waterInputs->addUniform(new osg::Uniform(m, osg::Matrixf()));
    _waterInputs->addUniform(new osg::Uniform("osgWater_EyeLocal", osg::Vec3f()));
}

GlowPasses* ViewPasses::getOrCreateGlow(int width, int height, bool floatTargets)
{
    if (!_glow.valid() || !_glow->matches(width, height, floatTargets)) {
        _glow = new GlowPasses(_scene, _sceneState.get(), _waterState.get(), *_programs, width, height, floatTargets);
        _glow->setTimingEnabled(_timing);
    }
    return _glow.get();
}

bool ViewPasses::matchesSizes(const osg::Vec2i& reflectionSize, const osg::Vec2i& refractionSize) const
{
    auto sized = [](const PassCamera* c, const osg::Vec2i& size) {
        return c->getTargetWidth() == size.x() && c->getTargetHeight() == size.y();
    };
    return sized(_reflection.get(), reflectionSize) && sized(_refraction.get(), refractionSize);
}

void ViewPasses::setTimingEnabled(bool on)
{
    if (on == _timing) return; // called every frame
    _timing = on;
    _reflectionMeter->setEnabled(on);
    _refractionMeter->setEnabled(on);
    if (_glow.valid()) _glow->setTimingEnabled(on);
}

void ViewPasses::update(const PassContext& ctx, const PassPlan& plan, const SceneLighting& lighting)
{
    _plan = plan;
    _eyeBelow = ctx.eyeBelow;
    // A pass sees the underwater scene only across the surface from its eye: the reflection from
    // below, the refraction from above. On the eye's own side it draws the scene above the water,
    // and what lies below the level there is the band its clip plane keeps to clear the waves: no
    // caustics for it (on a software rasteriser their fetches cost every fragment of the pass).
    if (plan.runs(PASS_REFLECTION)) {
        // under water the mirror shows the underwater scene through water (thesis §7.5: eq. 10
        // with d = |A2 - C2| in this pass): the view's fog comes along
        SceneLighting l = lighting;
        if (!ctx.eyeBelow) l.caustics = nullptr;
        else l.reflectedCaustics = nullptr; // the mirror under water shows the underwater scene
        _reflection->update(ctx);
        _reflection->applyLighting(l);
    }
    if (plan.runs(PASS_REFRACTION)) {
        // from above, the water shader attenuates the refracted colour itself; from below, this
        // pass sees the air: no fog either way
        SceneLighting l = lighting;
        l.fogExtinction = osg::Vec3();
        if (ctx.eyeBelow) l.caustics = nullptr;
        else l.reflectedCaustics = nullptr; // from above it sees the underwater scene
        _refraction->update(ctx);
        _refraction->applyLighting(l);
        // the debug output's true places replace the colour target while it is on
        if (_waterInputs->getTextureAttribute(UNIT_REFRACTION, osg::StateAttribute::TEXTURE) != _refraction->getColorTexture())
            _waterInputs->setTextureAttribute(UNIT_REFRACTION, _refraction->getColorTexture());
    }
    if (!plan.runs(PASS_SURFACE) && !plan.runs(PASS_CAP)) return; // the water inputs are read by nothing

    osg::StateSet* ss = _waterInputs.get();
    ss->getUniform("osgWater_ReflectionMVP")->set(osg::Matrixf(_reflection->getViewProjection()));
    setPassMatrices(ss, "osgWater_Reflection", *_reflection);
    setPassMatrices(ss, "osgWater_Refraction", *_refraction);
    ss->getUniform("osgWater_EyeLocal")->set(osg::Vec3f(eyePosition(ctx.view)));
    setDefineIf(ss, "OSGWATER_EYE_BELOW", ctx.eyeBelow);
    setDefineIf(ss, "OSGWATER_EYE_AMONG_WAVES", ctx.eyeAmongWaves);
    // the shader reads a pass's texture only when the pass ran this frame
    setDefineIf(ss, "OSGWATER_NO_REFLECTION", !plan.runs(PASS_REFLECTION));
    setDefineIf(ss, "OSGWATER_NO_REFRACTION", !plan.runs(PASS_REFRACTION));
}

void ViewPasses::resizeGLObjectBuffers(unsigned int maxSize)
{
    _reflection->resizeGLObjectBuffers(maxSize);
    _refraction->resizeGLObjectBuffers(maxSize);
    _waterInputs->resizeGLObjectBuffers(maxSize);
    if (_glow.valid()) _glow->resizeGLObjectBuffers(maxSize);
}

void ViewPasses::releaseGLObjects(osg::State* state) const
{
    _reflection->releaseGLObjects(state);
    _refraction->releaseGLObjects(state);
    _waterInputs->releaseGLObjects(state);
    for (const PassMeter* m : { _reflectionMeter.get(), _refractionMeter.get() }) m->releaseGLObjects(state);
    if (_glow.valid()) _glow->releaseGLObjects(state);
}

ViewPassesMap::Entry& ViewPassesMap::entry(osg::Camera* camera)
{
    // release what views that are gone held
    for (auto it = _map.begin(); it != _map.end();)
        it = it->second.camera.valid() ? std::next(it) : _map.erase(it);
    Entry& e = _map[camera];
    if (!e.lighting.valid()) {
        e.camera = camera;
        // changes every frame: OSG must not draw it while the next frame's cull writes
        e.lighting = new osg::StateSet;
        e.lighting->setName("osgWater.viewLighting");
        e.lighting->setDataVariance(osg::Object::DYNAMIC);
    }
    return e;
}

void ViewPassesMap::setPlan(osg::Camera* camera, const PassPlan& plan)
{
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_mutex);
    entry(camera).plan = plan;
}

PassPlan ViewPassesMap::getPlan(osg::Camera* camera) const
{
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_mutex);
    auto it = _map.find(camera);
    return it == _map.end() ? PassPlan() : it->second.plan;
}

osg::StateSet* ViewPassesMap::getLighting(osg::Camera* camera)
{
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_mutex);
    return entry(camera).lighting.get();
}

ViewPasses* ViewPassesMap::get(osg::Camera* camera, osg::Group* scene, osg::StateSet* sceneState,
                               osg::StateSet* waterState, ProgramLibrary* programs, const osg::Vec2i& reflectionSize,
                               const osg::Vec2i& refractionSize)
{
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_mutex);
    Entry& e = entry(camera);
    if (!e.passes.valid() || !e.passes->matchesSizes(reflectionSize, refractionSize))
        e.passes = new ViewPasses(scene, sceneState, waterState, programs, e.lighting.get(), reflectionSize, refractionSize);
    return e.passes.get();
}

ViewPasses* ViewPassesMap::find(osg::Camera* camera) const
{
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_mutex);
    auto it = _map.find(camera);
    return it == _map.end() ? nullptr : it->second.passes.get();
}

void ViewPassesMap::report(osg::Camera* camera, ViewReport& r) const
{
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_mutex);
    auto it = _map.find(camera);
    if (it == _map.end()) return;
    const PassPlan& plan = it->second.plan;
    r.valid = true;
    r.plan = plan.describe();
    for (int i = 0; i < PASS_COUNT; ++i) r.ran[i] = plan.runs(PassId(i));
    r.glowDrawn = plan.runs(PASS_GLOW_COMPOSITE);
    const ViewPasses* p = it->second.passes.get();
    if (!p) return;
    r.hasPasses = true;
    r.eyeBelow = p->getEyeBelow();
    r.reflectionSize[0] = p->getReflectionCamera()->getTargetWidth();
    r.reflectionSize[1] = p->getReflectionCamera()->getTargetHeight();
    r.refractionSize[0] = p->getRefractionCamera()->getTargetWidth();
    r.refractionSize[1] = p->getRefractionCamera()->getTargetHeight();
}

size_t ViewPassesMap::size() const
{
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_mutex);
    size_t n = 0;
    for (const auto& e : _map) n += e.second.passes.valid();
    return n;
}

void ViewPassesMap::clear()
{
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_mutex);
    _map.clear();
}

void ViewPassesMap::resizeGLObjectBuffers(unsigned int maxSize)
{
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_mutex);
    for (auto& e : _map) {
        e.second.lighting->resizeGLObjectBuffers(maxSize);
        if (e.second.passes.valid()) e.second.passes->resizeGLObjectBuffers(maxSize);
    }
}

void ViewPassesMap::releaseGLObjects(osg::State* state) const
{
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_mutex);
    for (const auto& e : _map) {
        e.second.lighting->releaseGLObjects(state);
        if (e.second.passes.valid()) e.second.passes->releaseGLObjects(state);
    }
}
