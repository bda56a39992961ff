#include "caustics/CausticsCamera.h"
#include "caustics/CausticsMethod.h"
#include "frame/PassMath.h"
#include <osgWater/WaterSettings>
#include <osg/FrontFace>
#include <osg/GLExtensions>
#include <osgUtil/CullVisitor>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include "shaders/Shaders.h"

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

bool CausticsSupport::supports(WaterSettings::CausticsGather g) const
{
    switch (g) {
    case WaterSettings::GATHER_CPU: return true;
    // the GPU paths need float (u, v) photons
    case WaterSettings::GATHER_POINTS_COPY: return floatTargets && pixelBuffers;
    case WaterSettings::GATHER_POINTS_TEXTURE: return floatTargets && vertexTextures;
    default: return false;
    }
}

const char* osgWater::causticsGatherLabel(WaterSettings::CausticsGather g)
{
    switch (g) {
    case WaterSettings::GATHER_POINTS_COPY: return "points (copy)";
    case WaterSettings::GATHER_POINTS_TEXTURE: return "points (texture)";
    case WaterSettings::GATHER_CPU: return "CPU";
    default: return "auto";
    }
}

CausticsCamera::CausticsCamera(osg::Group* scene, osg::StateSet* sceneState, osg::StateSet* waterState,
                               ProgramLibrary& programs, int resolution, int gridSize, bool floatTargets, bool reflected)
    : PassCamera(scene, { sceneState, depthOnlyState(programs) }, gridSize, gridSize, PASS_SUN_DEPTH), _floatTargets(floatTargets),
      _reflected(reflected)
{
    setName(reflected ? "osgWater.ReflectedCausticsCamera" : "osgWater.CausticsCamera");
    // the mirror flips winding: keep front faces front
    if (reflected) getOrCreateStateSet()->setAttribute(new osg::FrontFace(osg::FrontFace::CLOCKWISE));
    // depth only: no colour target, no shading
    setDepthOnly();
    _depth->setName("osgWater.sunDepth");
    if (!reflected) {
        // what stands above the water shades it: the whole scene seen from the sun, unclipped
        // (the clipped map holds only the underwater scene the photons' search needs)
        _shade = new PassCamera(scene, { sceneState, depthOnlyState(programs) }, gridSize, gridSize, PASS_SUN_DEPTH);
        _shade->setName("osgWater.SunShadeCamera");
        _shade->setDepthOnly();
        _shade->getDepthTexture()->setName("osgWater.sunShade");
    }

    _photons = new PhotonCamera(waterState, programs, gridSize, floatTargets);
    _gather = new PhotonGather(_photons->getPhotonTexture(), programs, gridSize, resolution, floatTargets, waterState);
    _lighting.caustics = _gather->getCausticsTexture();
    _lighting.depth = _depth;
    _meter = new PassMeter;
    // the per-frame passes (the depth map is redrawn only on change); set once: draw callbacks
    // must not change while drawing
    _meter->attach(_photons.get(), _gather.get());
    _depthMeter = new PassMeter;
    _depthMeter->setEnabled(false);
    _depthMeter->attach(this);
    _shadeMeter = new PassMeter; // its own: tiled caustics do not draw the shade map
    _shadeMeter->setEnabled(false);
    if (_shade.valid()) _shadeMeter->attach(_shade.get());
}

osg::StateSet* CausticsCamera::depthOnlyState(ProgramLibrary& programs)
{
    osg::StateSet* ss = new osg::StateSet; // held by the camera's draw list
    ss->setName("osgWater.depthOnly");
    ss->setAttribute(programs.get("osgWater.depth", "depth.vert", "depth.frag"));
    return ss;
}

void CausticsCamera::cullPass(PassId pass, osg::NodeVisitor& cv)
{
    switch (pass) {
    case PASS_SUN_DEPTH:
        accept(cv);
        if (_shade.valid() && !_tiled) _shade->accept(cv);
        break;
    case PASS_PHOTONS: _photons->accept(cv); break;
    case PASS_GATHER: _gather->accept(cv); break;
    default: break;
    }
}

bool CausticsCamera::matches(int resolution, int gridSize, bool floatTargets) const
{
    return getResolution() == resolution && getGridSize() == gridSize && _floatTargets == floatTargets;
}

bool CausticsCamera::reflectedNeeded(const Frame& f)
{
    return f.settings && f.settings->getCausticsEnabled() && f.settings->getReflectiveCaustics() && f.surface &&
           f.water.valid() && f.scene.valid() && f.towardsSun.z() > 0.0f && f.scene.zMax() > f.level;
}

osg::BoundingBox CausticsCamera::reflectedBox(const Frame& f)
{
    osg::BoundingBox box = lightBox(f, false);
    box.zMin() = std::min(float(2.0 * f.level) - f.scene.zMax(), float(f.level) - 0.01f);
    return box;
}

osg::Vec2d CausticsCamera::tileOrigin(const Frame& f)
{
    const osg::Vec3 c = f.water.valid() ? f.water.center() : osg::Vec3();
    return osg::Vec2d(c.x() - 0.5 * f.tile, c.y() - 0.5 * f.tile);
}

bool CausticsCamera::needed(const Frame& f)
{
    return f.settings && f.settings->getCausticsEnabled() && f.surface && f.water.valid() && f.scene.valid()
           && f.towardsSun.z() > 0.0f        // the sun above the horizon
           && f.scene.zMin() < f.level;      // something under the water
}

osg::BoundingBox CausticsCamera::lightBox(const Frame& f, bool focused)
{
    const osg::BoundingBox& cut = focused && f.litWater.valid() ? f.litWater : f.scene;
    osg::BoundingBox box = f.water;
    box.xMin() = std::max(box.xMin(), cut.xMin());
    box.yMin() = std::max(box.yMin(), cut.yMin());
    box.xMax() = std::min(box.xMax(), cut.xMax());
    box.yMax() = std::min(box.yMax(), cut.yMax());
    if (!box.valid()) box = f.water;
    box.zMin() = std::min(cut.zMin(), float(f.level) - 0.01f);
    box.zMax() = float(f.level + f.clearance);
    return box;
}

double CausticsCamera::focusRatio(const Frame& f)
{
    if (!f.settings || !f.settings->getCausticsFocused()) return 1.0;
    auto side = [](const osg::BoundingBox& b) { return std::max(b.xMax() - b.xMin(), b.yMax() - b.yMin()); };
    const double whole = side(lightBox(f, false));
    return whole > 0.0 ? std::min(1.0, side(lightBox(f, true)) / whole) : 1.0;
}

double CausticsCamera::tileRatio(const Frame& f)
{
    const osg::BoundingBox whole = lightBox(f, false);
    const double side = std::max(whole.xMax() - whole.xMin(), whole.yMax() - whole.yMin());
    return side > 0.0 && f.tile > 0.0 ? std::min(1.0, f.tile / side) : 1.0;
}

void CausticsCamera::update(const Frame& f)
{
    _depthDrawn = false; // a new frame
    // what the sun sees of the water volume: where its light can land (or the water's extent cut
    // to the scene's), from the deepest point there up to just above the crests
    // (reflected: the scene above the water mirrored in the water plane, seen the same way)
    const osg::BoundingBox box = _reflected ? reflectedBox(f) : lightBox(f, f.settings->getCausticsFocused());

    const osg::Matrixd sun = sunView(f.towardsSun, box);
    const osg::Matrixd proj = sunProjection(sun, box);
    const osg::Matrixd mirror = mirrorMatrix(f.level);
    // the depth map's view: the mirrored scene's, in the sun's eye space
    const osg::Matrixd view = _reflected ? mirror * sun : sun;
    // the underwater part only, or what stands above the water
    setKeepPlane(_reflected ? osg::Plane(0.0, 0.0, 1.0, -f.level) : osg::Plane(0.0, 0.0, -1.0, f.level + f.clearance));
    // the shade map: the same window, its near plane raised to the scene's top
    const osg::Matrixd shadeProj = _shade.valid() ? shadeProjection(sun, proj, box, f.scene) : osg::Matrixd();
    if (view != _depthView || proj != _depthProj || shadeProj != _shadeProj) {
        _depthView = view;
        _depthProj = proj;
        _shadeProj = shadeProj;
        ++_depthVersion;
    }
    setViewMatrix(view);
    setProjectionMatrix(proj);
    SceneLighting depthPass; // the bundle every scene pass gets: here only its clip plane is used
    depthPass.towardsSun = f.towardsSun;
    depthPass.level = f.level;
    applyLighting(depthPass);
    if (_shade.valid()) {
        _shade->setViewMatrix(sun);
        _shade->setProjectionMatrix(shadeProj);
        // all of it down to the scene's floor: the bed under open water is in the map too, so the
        // shade test reads between texels right up to the waterline (no cleared texel beside it)
        _shade->setKeepPlane(osg::Plane(0.0, 0.0, 1.0, -(std::min(f.scene.zMin(), box.zMin()) - 1.0)));
        _shade->applyLighting(depthPass);
    }
    _tiled = !_reflected && f.tile > 0.0;
    _tileSide = _tiled ? f.tile : 0.0;
    if (_tiled) {
        // one tile of the surface seen straight down, its light on the flat bed (the depth map above
        // still gives the shadows)
        const osg::Vec2d o = tileOrigin(f);
        const double above = f.clearance + 1.0;
        const osg::Matrixd tileView = osg::Matrixd::translate(-o.x(), -o.y(), -(f.level + above));
        // texel centres on both edges of the tile, grid - 1 samples apart: the repeating surface's
        // mesh closes on its neighbour's copy without a gap or an overlap
        const double half = 0.5 * f.tile / std::max(getGridSize() - 1, 1);
        const osg::Matrixd tileProj = osg::Matrixd::ortho(-half, f.tile + half, -half, f.tile + half, 0.5,
                                                          2.0 * above + 2.0 + (f.level - f.tileBedZ));
        _lighting.localToTile = osg::Matrixd::translate(-o.x(), -o.y(), 0.0) * osg::Matrixd::scale(1.0 / f.tile, 1.0 / f.tile, 1.0);
        _photons->setTile(f.surface, tileView, tileProj, f.towardsSun, f.tileBedZ, _lighting.localToTile);
    } else {
        _photons->setSun(f.surface, sun, proj, _depth.get(), _reflected ? &mirror : nullptr);
        if (_shade.valid()) _photons->setSunShade(_shade->getDepthTexture(), shadeProj);
    }
    // the procedural caustics trace no photons (a tile's and the sun's reflection keep theirs). Per
    // pixel, the scene program makes them and neither the photons nor the gather run, unless the
    // sun's reflection runs those passes anyway: then into the texture. Into the texture, the
    // photon pass stays, empty (no surface, no clear), only as the start of the caustics' GPU timer
    const CausticsChoice choice = chooseCaustics(f.settings->getCausticsMethod(), _reflected, _tiled, reflectedNeeded(f));
    const bool procedural = choice.procedural;
    _lighting.procedural = choice.perPixel;
    _photons->setEmpty(procedural && !_lighting.procedural);
    _lighting.tiled = _tiled;

    double l, r, b, t, n, fa;
    proj.getOrtho(l, r, b, t, n, fa);
    _window.set(r - l, t - b, fa - n);
    const double texel = std::max(r - l, t - b) / getGridSize();
    _lighting.localToSun = view * proj * clipToTexture(); // reflected: a fragment mirrored first
    if (procedural && !_lighting.procedural)
        _gather->setProceduralSun(osg::Matrixd::inverse(_lighting.localToSun), view, f.towardsSun, _depth.get(),
                                  _shade.valid() ? _shade->getDepthTexture() : nullptr, shadeProj);
    _lighting.shade = _lighting.procedural && _shade.valid() ? _shade->getDepthTexture() : nullptr;
    _lighting.sunView = view;
    _lighting.shadeProjection = shadeProj;
    // the texture holds value / scale; per pixel the value itself
    _lighting.intensity = f.settings->getCausticsIntensity() * (_lighting.procedural ? 1.0f : _gather->getValueScale());
    // the photons' green-channel fade is the others' too in the air
    // (a tile's photons carry no fade: the fragment's depth gives all of it)
    _lighting.channelExtinction = _reflected ? osg::Vec3f() : channelExtinction(*f.settings, _tiled);
    _lighting.depthBias.set(float(1.5 * texel / _window.z()), float(texel / _window.z()));

    const osg::Texture::FilterMode filter = f.settings->getCausticsFiltering() ? osg::Texture::LINEAR
                                                                             : osg::Texture::NEAREST;
    osg::Texture2D* c = _gather->getCausticsTexture();
    const osg::Texture::WrapMode wrap = _tiled ? osg::Texture::REPEAT : osg::Texture::CLAMP_TO_EDGE; // a tile repeats
    if (c->getWrap(osg::Texture::WRAP_S) != wrap) {
        c->setWrap(osg::Texture::WRAP_S, wrap);
        c->setWrap(osg::Texture::WRAP_T, wrap);
    }
    // filtered: between the mipmap levels the gather makes as well
    const osg::Texture::FilterMode minFilter =
        filter == osg::Texture::LINEAR ? osg::Texture::LINEAR_MIPMAP_LINEAR : filter;
    if (c->getFilter(osg::Texture::MAG_FILTER) != filter || c->getFilter(osg::Texture::MIN_FILTER) != minFilter) {
        c->setFilter(osg::Texture::MIN_FILTER, minFilter);
        c->setFilter(osg::Texture::MAG_FILTER, filter);
    }
}

osg::Matrixd CausticsCamera::shadeProjection(const osg::Matrixd& sun, const osg::Matrixd& proj,
                                             const osg::BoundingBox& box, const osg::BoundingBox& scene)
{
    // what can shade the box's water lies on the sun's rays through it: the same window, from
    // the scene's top (the near plane may lie behind the sun camera's eye: orthographic) down
    // to the box's floor
    osg::BoundingBox tall = box;
    if (scene.valid()) tall.zMax() = std::max(tall.zMax(), scene.zMax());
    double l, r, b, t, n, fa, tl, tr, tb, tt, tn, tf;
    proj.getOrtho(l, r, b, t, n, fa);
    sunProjection(sun, tall).getOrtho(tl, tr, tb, tt, tn, tf);
    return osg::Matrixd::ortho(l, r, b, t, std::min(n, tn), fa);
}

PassMeasure CausticsCamera::getDepthMeasure() const
{
    const PassMeasure depth = _depthMeter->getMeasure();
    return _shade.valid() && !_tiled ? depth + _shadeMeter->getMeasure() : depth;
}

void CausticsCamera::setTimingEnabled(bool on)
{
    _depthMeter->setEnabled(on);
    _shadeMeter->setEnabled(on);
}

double CausticsCamera::getTexelSize() const
{
    const double side = _tiled ? _tileSide : std::max(_window.x(), _window.y());
    return side / std::max(1, getResolution());
}

bool CausticsCamera::depthStale(unsigned int context) const
{
    // also when the map's GL texture was released (a view removed from the context releases the
    // passes it culled last): a released texture holds nothing, so a map drawn once is drawn again
    auto done = _depthDone.find(context);
    return done == _depthDone.end() || done->second != _depthVersion || !_depth->getTextureObject(context) ||
           (_shade.valid() && !_tiled && !_shade->getDepthTexture()->getTextureObject(context));
}

void CausticsCamera::markDepthDrawn(unsigned int context)
{
    _depthDone[context] = _depthVersion;
    _depthDrawn = true;
}

WaterSettings::CausticsGather CausticsCamera::resolveGather(const WaterSettings& settings,
                                                            const CausticsSupport& support)
{
    const WaterSettings::CausticsGather wanted = settings.getCausticsGather();
    const WaterSettings::CausticsMethod method = chooseCaustics(settings.getCausticsMethod(), _reflected, _tiled, false).gathered;
    if (_tiled && settings.getCausticsMethod() != method && !_saidTiledMesh) {
        _saidTiledMesh = true;
        OSG_NOTICE << "osgWater: tileable caustics are gathered by the area-ratio mesh" << std::endl;
    }
    const bool supersampled = settings.getCausticsSupersampling();
    if ((method != _gather->getCausticsMethod() || supersampled != _gather->getSupersampled() ||
         _tiled != _gather->getTiled()) &&
        _activeGather != WaterSettings::GATHER_AUTO) {
        // the paths' speeds differ by method and passes: the automatic choice is made again
        _trial = _trialFrame = 0;
        _trialMs.clear();
        _autoChoice = -1;
    }
    WaterSettings::CausticsGather g = wanted;
    if (wanted == WaterSettings::GATHER_AUTO) g = autoGather(support);
    else if (!support.supports(wanted)) {
        const WaterSettings::CausticsGather order[] = { WaterSettings::GATHER_POINTS_TEXTURE,
                                                        WaterSettings::GATHER_POINTS_COPY, WaterSettings::GATHER_CPU };
        for (WaterSettings::CausticsGather o : order)
            if (support.supports(o)) { g = o; break; }
    }
    if (g != _activeGather) {
        if (wanted != WaterSettings::GATHER_AUTO && g != wanted)
            OSG_WARN << "osgWater: caustics gather " << causticsGatherLabel(wanted) << " is not supported by this context, using "
                     << causticsGatherLabel(g) << std::endl;
        if (!support.floatTargets)
            OSG_WARN << "osgWater: no float render targets, caustics fall back to the CPU gather" << std::endl;
        OSG_DEBUG << "osgWater: caustics gather: " << causticsGatherLabel(g) << std::endl;
        _activeGather = g;
    }
    _gather->setMethod(g, method, supersampled, _tiled);
    return g;
}

WaterSettings::CausticsGather CausticsCamera::autoGather(const CausticsSupport& support)
{
    std::vector<WaterSettings::CausticsGather> candidates;
    for (WaterSettings::CausticsGather g : { WaterSettings::GATHER_POINTS_TEXTURE, WaterSettings::GATHER_POINTS_COPY,
                                             WaterSettings::GATHER_CPU })
        if (support.supports(g)) candidates.push_back(g);
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
    OSG_NOTICE << "osgWater: caustics gather (auto): " << causticsGatherLabel(candidates[_autoChoice]) << ", GPU medians";
    for (size_t i = 0; i < candidates.size(); ++i)
        OSG_NOTICE << " " << causticsGatherLabel(candidates[i]) << " " << median(_trialMs[i]) << " ms";
    OSG_NOTICE << std::endl;
    return candidates[_autoChoice];
}

void CausticsCamera::resizeGLObjectBuffers(unsigned int maxSize)
{
    PassCamera::resizeGLObjectBuffers(maxSize);
    if (_shade.valid()) _shade->resizeGLObjectBuffers(maxSize);
    resizePassGLObjectBuffers(_photons.get(), maxSize);
    _gather->resizeGLObjectBuffers(maxSize);
    resizePassGLObjectBuffers(_gather.get(), maxSize);
}

void CausticsCamera::releaseGLObjects(osg::State* state) const
{
    PassCamera::releaseGLObjects(state);
    if (_shade.valid()) _shade->releaseGLObjects(state);
    releasePassGLObjects(_photons.get(), state);
    _gather->releaseGLObjects(state); // its point clouds and CPU gather are its children
    releasePassGLObjects(_gather.get(), state);
    for (const PassMeter* m : { _meter.get(), _depthMeter.get(), _shadeMeter.get() }) m->releaseGLObjects(state);
}
