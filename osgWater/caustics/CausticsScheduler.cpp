#include "caustics/CausticsScheduler.h"
#include "frame/PassMath.h"
#include "frame/WaterStateSets.h"
#include <osgWater/WaterNode>
#include <OpenThreads/ScopedLock>
#include <osgUtil/CullVisitor>
#include <algorithm>
#include <cmath>
#include <limits>

using namespace osgWater;

using Lock = OpenThreads::ScopedLock<OpenThreads::Mutex>;

CausticsScheduler::CausticsScheduler(WaterNode& water, WaterStateSets& states) : _water(water), _states(states) {}

LitWater CausticsScheduler::updateScene(const osg::BoundingSphere& children, double keepBelow, bool walkLitWater)
{
    Lock lock(_mutex);
    // the rays along the sun are walked only for what uses them, and again only on a change
    _sceneBoxes.update(_water, children, _water.getSurface()->getBoundingBox(), keepBelow,
                       _water.getSettings()->getSunDirection(), walkLitWater);
    return _sceneBoxes.litWater();
}

void CausticsScheduler::aim(unsigned int frame, double clearance, const CausticsSupport& support, const FitTexture& fit)
{
    const WaterSettings& s = *_water.getSettings();
    WaterSurface& surface = *_water.getSurface();
    _aimedFrame = frame;
    CausticsCamera::Frame f;
    f.towardsSun = s.getSunDirection();
    f.water = surface.getBoundingBox();
    f.level = surface.getLevel();
    f.clearance = clearance;
    f.scene = _sceneBoxes.whole(); // brought up to date by the update traversal (updateScene)
    f.litWater = _sceneBoxes.litWater().box;
    // tileable caustics over a flat bed at the lit water's mean depth (1 m without lit water)
    f.tile = s.getCausticsTileSize();
    f.tileBedZ = _sceneBoxes.litWater().box.valid() ? std::min(_sceneBoxes.litWater().meanBedZ, f.level - 1e-3)
                                                     : f.level - 1.0;
    // (the wind's cascades repeat over tiles of their own, chosen never to repeat together)
    if (f.tile > 0.0 &&
        !(surface.usesGrid() && surface.getWaveModel() == WaterSurface::WAVES_SUM && WaterSurface::wavesTileOver(surface.getWaves(), f.tile)) &&
        !_warnedTile.exchange(true))
        OSG_WARN << "osgWater: WaterNode \"" << _water.getName() << "\": the waves do not repeat over the caustics tile of "
                 << f.tile << " m: the tiled caustics show seams" << std::endl;
    f.surface = surface.getUniformMesh(); // seen from the sun: the uniform grid
    f.settings = &s;
    _needed = CausticsCamera::needed(f);
    _reflectedNeeded = false;
    if (!_needed) return;
    // the focused window keeps the texel spacing the settings give the whole one, and the
    // photons per texel exactly (a ratio off by a rounding makes a moire of 3s and 4s)
    const int setResolution = fit("causticsResolution", s.getCausticsResolution());
    const int setGrid = fit("photonGridSize", s.getPhotonGridSize());
    // (a tile keeps the spacing too: its counts shrink with its side)
    const int resolution = focusedCount(setResolution, f.tile > 0.0 ? CausticsCamera::tileRatio(f)
                                                                    : CausticsCamera::focusRatio(f));
    const int grid = std::max(1, int(std::lround(double(setGrid) * resolution / setResolution)));
    if (!_caustics.valid() || !_caustics->matches(resolution, grid, support.floatTargets)) {
        _caustics = new CausticsCamera(&_water, _states.getSceneStateSet(), _states.getWaterStateSet(),
                                       _states.getPrograms(), resolution, grid,
                                       support.floatTargets);
        _caustics->setTimingEnabled(_timing);
    }
    _caustics->update(f);
    // the reflective caustics: over the whole window (the lit water is where refracted light lands)
    _reflectedNeeded = CausticsCamera::reflectedNeeded(f);
    if (!_reflectedNeeded) {
        _reflected = nullptr;
    } else {
        if (!_reflected.valid() || !_reflected->matches(setResolution, setGrid, support.floatTargets)) {
            _reflected = new CausticsCamera(&_water, _states.getSceneStateSet(), _states.getWaterStateSet(),
                                       _states.getPrograms(),
                                            setResolution, setGrid, support.floatTargets, true);
            _reflected->setTimingEnabled(_timing);
        }
        _reflected->update(f);
    }
    const AimKey key{ _caustics.get(), _reflected.get(), &s, &surface, s.getRevision(), surface.getRevision(),
                      _caustics->getDepthVersion(), _reflectedNeeded ? _reflected->getDepthVersion() : 0u };
    if (key != _aimKey) {
        _aimKey = key;
        ++_aim;
    }
}

void CausticsScheduler::prepare(unsigned int frame, unsigned int contextID, double time, double clearance,
                                const CausticsSupport& support, const FitTexture& fit, FrameFacts& facts)
{
    if (!_water.getSettings()->getCausticsEnabled()) return;
    Lock lock(_mutex);
    if (_aimedFrame != frame) aim(frame, clearance, support, fit); // once per frame: every view and context shares them
    if (!_needed || !_caustics.valid()) return;
    facts.caustics = true;
    facts.causticsInScene = _caustics->getLighting().procedural;
    auto done = _rendered.find(contextID);
    facts.causticsDone = done != _rendered.end() &&
                         (done->second.frame == frame ||
                          (_water.getSkippingEnabled() && stillHold(done->second.aim, done->second.time, time)));
    facts.sunDepthStale = _caustics->depthStale(contextID);
    facts.reflectedCaustics = _reflectedNeeded && _reflected.valid();
    if (facts.reflectedCaustics) facts.sunDepthStale = facts.sunDepthStale || _reflected->depthStale(contextID);
}

bool CausticsScheduler::stillHold(unsigned int aim, double renderedAt, double t) const
{
    // the automatic gather times its candidates on frames that render caustics: every frame until it chose
    const bool choosing = _water.getSettings()->getCausticsGather() == WaterSettings::GATHER_AUTO &&
                          !_caustics->isAutoGatherSettled();
    return aim == _aim && !choosing && (t == renderedAt || std::abs(t - renderedAt) <= holdTime());
}

double CausticsScheduler::holdTime() const
{
    if (!_caustics.valid() || !_water.getSkippingEnabled()) return 0.0;
    // the pattern is a sum of the waves' patterns, each travelling at its phase speed
    const double texel = _caustics->getTexelSize();
    const double speed = _water.getSurface()->getMaxPhaseSpeed();
    if (speed == 0.0) return std::numeric_limits<double>::infinity();
    return _water.getSettings()->getCausticsMotionTolerance() * texel / speed;
}

double CausticsScheduler::getHoldTime() const
{
    Lock lock(_mutex);
    return holdTime();
}

bool CausticsScheduler::claim(unsigned int frame, unsigned int contextID, double time, const FrameFacts& facts,
                              const PassPlan& plan, const CausticsSupport& support)
{
    Lock lock(_mutex);
    Rendered& last = _rendered[contextID];
    if (last.frame == frame) return false;
    last.frame = frame;
    last.aim = _aim;
    last.time = time;
    const bool reflected = facts.reflectedCaustics && _reflected.valid();
    if (plan.runs(PASS_SUN_DEPTH)) {
        _caustics->markDepthDrawn(contextID);
        if (reflected) _reflected->markDepthDrawn(contextID);
    }
    if (plan.runs(PASS_PHOTONS) && _gatherResolved != frame) { // the gather follows frames that gather
        _gatherResolved = frame;
        _caustics->resolveGather(*_water.getSettings(), support);
        if (reflected) _reflected->resolveGather(*_water.getSettings(), support);
    }
    return true;
}

void CausticsScheduler::light(const FrameFacts& facts, SceneLighting& l) const
{
    // (the passes are replaced only while aiming, before any view of the frame reads them)
    l.caustics = &_caustics->getLighting();
    if (facts.reflectedCaustics) l.reflectedCaustics = &_reflected->getLighting();
}

void CausticsScheduler::cull(PassId pass, osgUtil::CullVisitor& cv, const FrameFacts& facts)
{
    _caustics->cullPass(pass, cv);
    if (facts.reflectedCaustics) _reflected->cullPass(pass, cv);
}

PassMeasure CausticsScheduler::getMeasure(PassId pass) const
{
    Lock lock(_mutex);
    if (!_caustics.valid()) return PassMeasure();
    return pass == PASS_SUN_DEPTH ? _caustics->getDepthMeasure() : _caustics->getMeasure();
}

void CausticsScheduler::report(ViewReport& r) const
{
    Lock lock(_mutex);
    if (!_caustics.valid()) return;
    r.caustics = true;
    r.causticsGather = _caustics->getActiveGather();
    r.causticsGatherSettled = _caustics->isAutoGatherSettled();
    r.causticsResolution = _caustics->getResolution();
    r.photonGridSize = _caustics->getGridSize();
}

WaterSettings::CausticsGather CausticsScheduler::getActiveGather() const
{
    Lock lock(_mutex);
    return _caustics.valid() ? _caustics->getActiveGather() : WaterSettings::GATHER_AUTO;
}

void CausticsScheduler::setTimingEnabled(bool on)
{
    Lock lock(_mutex);
    _timing = on;
    if (_caustics.valid()) _caustics->setTimingEnabled(on);
    if (_reflected.valid()) _reflected->setTimingEnabled(on);
}

void CausticsScheduler::resizeGLObjectBuffers(unsigned int maxSize)
{
    Lock lock(_mutex);
    if (_caustics.valid()) _caustics->resizeGLObjectBuffers(maxSize);
    if (_reflected.valid()) _reflected->resizeGLObjectBuffers(maxSize);
}

void CausticsScheduler::releaseGLObjects(osg::State* state) const
{
    Lock lock(_mutex);
    if (_caustics.valid()) _caustics->releaseGLObjects(state);
    if (_reflected.valid()) _reflected->releaseGLObjects(state);
    // released caustics hold nothing any more: the next frame renders them again
    if (state) _rendered.erase(state->getContextID());
    else _rendered.clear();
}
