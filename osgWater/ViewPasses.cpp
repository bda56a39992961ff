#include <osgWater/ViewPasses>
#include <osgWater/PassMath>
#include <osgWater/WaterSettings>
#include <OpenThreads/ScopedLock>

using namespace osgWater;

ViewPasses::ViewPasses(osg::Group* scene, osg::StateSet* sceneState, int reflectionSize, int refractionSize)
{
    _reflection = new ReflectionCamera(scene, sceneState, reflectionSize);
    _refraction = new RefractionCamera(scene, sceneState, refractionSize);
    _reflectionTimer = new GpuTimer;
    _refractionTimer = new GpuTimer;
    _stateSet = new osg::StateSet;
    _stateSet->setDataVariance(osg::Object::DYNAMIC);
    _stateSet->setTextureAttribute(1, _reflection->getColorTexture());
    _stateSet->setTextureAttribute(2, _refraction->getColorTexture());
    _stateSet->setTextureAttribute(3, _refraction->getDepthTexture());
    const char* mats[] = { "osgWater_ReflectionMVP", "osgWater_RefractionView", "osgWater_RefractionViewInverse",
                           "osgWater_RefractionProj", "osgWater_RefractionInvProj" };
    for (const char* m : mats) _stateSet->addUniform(new osg::Uniform(m, osg::Matrixf()));
    _stateSet->addUniform(new osg::Uniform("osgWater_EyeLocal", osg::Vec3f()));
    _stateSet->addUniform(new osg::Uniform("osgWater_SunEye", osg::Vec3f(0.0f, 0.0f, 1.0f)));
    _stateSet->addUniform(new osg::Uniform("osgWater_ClipPlane", osg::Vec4f(0.0f, 0.0f, 0.0f, 1.0f)));
    addCausticsUniforms(_stateSet.get());
    setUnderwaterFog(_stateSet.get(), osg::Vec3(), 0.0f);
}

GlowPasses* ViewPasses::getOrCreateGlow(int width, int height, bool floatTargets, osg::Group* scene,
                                        osg::StateSet* sceneState, osg::StateSet* waterState)
{
    if (!_glow.valid() || !_glow->matches(width, height, floatTargets))
        _glow = new GlowPasses(scene, sceneState, waterState, width, height, floatTargets);
    return _glow.get();
}

bool ViewPasses::matchesSizes(int reflectionSize, int refractionSize) const
{
    return _reflection->getTextureSize() == reflectionSize && _refraction->getTextureSize() == refractionSize;
}

void ViewPasses::setTimingEnabled(bool on)
{
    if (on == _timing) return;
    _timing = on;
    if (on) {
        _reflectionTimer->attach(_reflection.get());
        _refractionTimer->attach(_refraction.get());
    } else {
        _reflectionTimer->detach(_reflection.get());
        _refractionTimer->detach(_refraction.get());
    }
}

void ViewPasses::update(const PassContext& ctx, bool reflection, bool refraction)
{
    if (reflection) _reflection->update(ctx);
    if (refraction) {
        _refraction->update(ctx);
        applyCausticsLighting(_refraction->getOrCreateStateSet(), ctx.caustics, _refraction->getViewMatrix(), ctx.level);
    }
    osg::StateSet* ss = _stateSet.get();
    ss->getUniform("osgWater_ReflectionMVP")->set(osg::Matrixf(_reflection->getViewProjection()));
    const osg::Matrixd& rv = _refraction->getViewMatrix();
    const osg::Matrixd& rp = _refraction->getProjectionMatrix();
    ss->getUniform("osgWater_RefractionView")->set(osg::Matrixf(rv));
    ss->getUniform("osgWater_RefractionViewInverse")->set(osg::Matrixf(osg::Matrixd::inverse(rv)));
    ss->getUniform("osgWater_RefractionProj")->set(osg::Matrixf(rp));
    ss->getUniform("osgWater_RefractionInvProj")->set(osg::Matrixf(osg::Matrixd::inverse(rp)));
    ss->getUniform("osgWater_EyeLocal")->set(osg::Vec3f(eyePosition(ctx.view)));
    _eyeBelow = ctx.eyeBelow;
    if (ctx.eyeBelow) ss->setDefine("OSGWATER_EYE_BELOW");
    else ss->removeDefine("OSGWATER_EYE_BELOW");
    // eq. 10 in the main view: under water, every object is seen through water
    if (ctx.eyeBelow && ctx.settings) setUnderwaterFog(ss, ctx.settings->getWaterColor(), ctx.settings->getAttenuation());
    else setUnderwaterFog(ss, osg::Vec3(), 0.0f);
    applyCausticsLighting(ss, ctx.caustics, ctx.view, ctx.level);
    if (ctx.settings) {
        osg::Vec3f sun = osg::Matrixd::transform3x3(ctx.settings->getSunDirection(), ctx.view);
        sun.normalize();
        ss->getUniform("osgWater_SunEye")->set(sun);
    }
}

ViewPasses* ViewPassesMap::get(osg::Camera* camera, osg::Group* scene, osg::StateSet* sceneState,
                               int reflectionSize, int refractionSize)
{
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_mutex);
    // release the passes of views that are gone
    for (auto it = _map.begin(); it != _map.end();)
        it = it->second.camera.valid() ? std::next(it) : _map.erase(it);
    Entry& e = _map[camera];
    if (!e.passes.valid() || !e.passes->matchesSizes(reflectionSize, refractionSize)) {
        e.camera = camera;
        e.passes = new ViewPasses(scene, sceneState, reflectionSize, refractionSize);
    }
    return e.passes.get();
}

ViewPasses* ViewPassesMap::find(osg::Camera* camera) const
{
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_mutex);
    auto it = _map.find(camera);
    return it == _map.end() ? nullptr : it->second.passes.get();
}

size_t ViewPassesMap::size() const
{
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_mutex);
    return _map.size();
}

void ViewPassesMap::clear()
{
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_mutex);
    _map.clear();
}
