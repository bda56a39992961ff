#include <osgWater/CausticsCamera>
#include <osgWater/PassMath>
#include <osgWater/WaterSettings>
#include <osg/GLExtensions>
#include <osgUtil/CullVisitor>
#include <algorithm>
#include <cstdlib>

using namespace osgWater;

CausticsSupport CausticsSupport::detect(unsigned int contextID)
{
    CausticsSupport s;
    if (const osg::GLExtensions* ext = osg::GLExtensions::Get(contextID, false)) {
        s.floatTargets = ext->glVersion >= 3.0f || (osg::isGLExtensionSupported(contextID, "GL_ARB_texture_float")
                                                    && osg::isGLExtensionSupported(contextID, "GL_ARB_color_buffer_float"));
        s.pixelBuffers = ext->isBufferObjectSupported && ext->isPBOSupported;
        s.vertexTextures = ext->glslLanguageVersion >= 1.3f; // texelFetch; GL 3.0 has 16 vertex units
        if (ext->maxTextureSize > 0) s.maxTextureSize = ext->maxTextureSize;
    }
    const char* env = std::getenv("OSGWATER_NO_FLOAT_TARGETS");
    if (env && std::atoi(env) != 0) s.floatTargets = false;
    return s;
}

WaterSettings::CausticsGather CausticsSupport::resolve(WaterSettings::CausticsGather wanted) const
{
    if (!floatTargets) return WaterSettings::GATHER_CPU; // photons need float (u, v) on the GPU paths
    const WaterSettings::CausticsGather order[] = { WaterSettings::GATHER_POINTS_TEXTURE,
                                                    WaterSettings::GATHER_POINTS_COPY, WaterSettings::GATHER_CPU };
    auto supported = [this](WaterSettings::CausticsGather g) {
        return g == WaterSettings::GATHER_CPU || (g == WaterSettings::GATHER_POINTS_COPY && pixelBuffers)
               || (g == WaterSettings::GATHER_POINTS_TEXTURE && vertexTextures);
    };
    if (wanted != WaterSettings::GATHER_AUTO && supported(wanted)) return wanted;
    for (WaterSettings::CausticsGather g : order)
        if (supported(g)) return g;
    return WaterSettings::GATHER_CPU;
}

const char* CausticsCamera::gatherName(WaterSettings::CausticsGather g)
{
    switch (g) {
    case WaterSettings::GATHER_POINTS_COPY: return "points (copy)";
    case WaterSettings::GATHER_POINTS_TEXTURE: return "points (texture)";
    case WaterSettings::GATHER_CPU: return "CPU";
    default: return "auto";
    }
}

CausticsCamera::CausticsCamera(osg::Group* scene, osg::StateSet* sceneState, osg::StateSet* waterState,
                               int resolution, int gridSize, bool floatTargets)
    : PassCamera(scene, sceneState, gridSize), _floatTargets(floatTargets)
{
    setName("osgWater.CausticsCamera");
    setRenderOrder(osg::Camera::PRE_RENDER, -3); // first: the photons search this depth map
    setClearColor(osg::Vec4(0.0f, 0.0f, 0.0f, 0.0f));
    _depth = makeTexture(gridSize, GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT, GL_FLOAT, false);
    _depth->setName("osgWater.sunDepth");
    attach(osg::Camera::DEPTH_BUFFER, _depth.get());

    _photons = new PhotonCamera(waterState, gridSize, floatTargets);
    _gather = new PhotonGather(_photons->getPhotonTexture(), gridSize, resolution, floatTargets);
    _lighting.caustics = _gather->getCausticsTexture();
    _lighting.depth = _depth;
    _timer = new GpuTimer;
    // the per-frame passes (the depth map is redrawn only on change); set once: draw callbacks
    // must not change while drawing
    _timer->attach(_photons.get(), _gather.get());
}

bool CausticsCamera::matches(int resolution, int gridSize, bool floatTargets) const
{
    return getResolution() == resolution && getGridSize() == gridSize && _floatTargets == floatTargets;
}

bool CausticsCamera::needed(const Frame& f)
{
    return f.settings && f.settings->getCausticsEnabled() && f.surface && f.water.valid() && f.scene.valid()
           && f.towardsSun.z() > 0.0f        // the sun above the horizon
           && f.scene.zMin() < f.level;      // something under the water
}

void CausticsCamera::update(const Frame& f)
{
    // what the sun sees of the water volume: the water's extent (cut to the scene's) from the
    // deepest scene point up to just above the crests
    osg::BoundingBox box = f.water;
    box.xMin() = std::max(box.xMin(), f.scene.xMin());
    box.yMin() = std::max(box.yMin(), f.scene.yMin());
    box.xMax() = std::min(box.xMax(), f.scene.xMax());
    box.yMax() = std::min(box.yMax(), f.scene.yMax());
    if (!box.valid()) box = f.water;
    box.zMin() = std::min(f.scene.zMin(), float(f.level) - 0.01f);
    box.zMax() = float(f.level + f.clearance);

    const osg::Matrixd view = sunView(f.towardsSun, box);
    const osg::Matrixd proj = sunProjection(view, box);
    setKeepPlane(osg::Plane(0.0, 0.0, -1.0, f.level + f.clearance)); // the underwater part only
    if (view != _depthView || proj != _depthProj) {
        _depthView = view;
        _depthProj = proj;
        ++_depthVersion;
    }
    setMatrices(view, proj, f.towardsSun);
    _photons->setSun(f.surface, view, proj, _depth.get());
    _gather->setMethod(f.gather);

    double l, r, b, t, n, fa;
    proj.getOrtho(l, r, b, t, n, fa);
    _window.set(r - l, t - b, fa - n);
    const double texel = std::max(r - l, t - b) / getGridSize();
    _lighting.localToSun = view * proj * clipToTexture();
    _lighting.intensity = f.settings->getCausticsIntensity() * _gather->getValueScale();
    _lighting.depthBias.set(float(1.5 * texel / _window.z()), float(texel / _window.z()));

    const osg::Texture::FilterMode filter = f.settings->getCausticsFiltering() ? osg::Texture::LINEAR
                                                                             : osg::Texture::NEAREST;
    osg::Texture2D* c = _gather->getCausticsTexture();
    if (c->getFilter(osg::Texture::MAG_FILTER) != filter) {
        c->setFilter(osg::Texture::MIN_FILTER, filter);
        c->setFilter(osg::Texture::MAG_FILTER, filter);
    }
}

void CausticsCamera::cullPasses(osgUtil::CullVisitor& cv)
{
    const unsigned int context = cv.getState() ? cv.getState()->getContextID() : 0u;
    // also when the map's GL texture was released (a view removed from the context releases the
    // passes it culled last): a released texture holds nothing, so a map drawn once is drawn again
    _depthDrawn = _depthDone[context] != _depthVersion || !_depth->getTextureObject(context);
    if (_depthDrawn) {
        accept(cv);        // pass 1: this camera, the sun's depth map
        _depthDone[context] = _depthVersion;
    }
    _photons->accept(cv);  // pass 2
    _gather->accept(cv);   // pass 3
}

WaterSettings::CausticsGather CausticsCamera::autoGather(const CausticsSupport& support)
{
    std::vector<WaterSettings::CausticsGather> candidates;
    if (support.floatTargets) {
        if (support.vertexTextures) candidates.push_back(WaterSettings::GATHER_POINTS_TEXTURE);
        if (support.pixelBuffers) candidates.push_back(WaterSettings::GATHER_POINTS_COPY);
    }
    candidates.push_back(WaterSettings::GATHER_CPU);
    if (_autoChoice >= 0 && _autoChoice < int(candidates.size())) return candidates[_autoChoice];
    if (candidates.size() == 1) return candidates[0];

    // a timer result arrives a frame or two late: the first frames of a trial are not its own
    const unsigned int skip = 3, frames = 8;
    _trialMs.resize(candidates.size());
    if (_trial < candidates.size() && _trialFrame >= skip && getMilliseconds() >= 0.0)
        _trialMs[_trial].push_back(getMilliseconds());
    if (++_trialFrame > frames) {
        _trialFrame = 0;
        ++_trial;
    }
    if (_trial < candidates.size()) return candidates[_trial];

    auto median = [](std::vector<double> v) {
        if (v.empty()) return 1e30;
        std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
        return v[v.size() / 2];
    };
    _autoChoice = 0;
    for (size_t i = 1; i < candidates.size(); ++i)
        if (median(_trialMs[i]) < median(_trialMs[_autoChoice])) _autoChoice = int(i);
    OSG_NOTICE << "osgWater: caustics gather (auto): " << gatherName(candidates[_autoChoice]) << ", GPU medians";
    for (size_t i = 0; i < candidates.size(); ++i)
        OSG_NOTICE << " " << gatherName(candidates[i]) << " " << median(_trialMs[i]) << " ms";
    OSG_NOTICE << std::endl;
    return candidates[_autoChoice];
}
