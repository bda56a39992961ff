#include <osgWater/WaterSurface>
#include "settings/Clamp.h"
#include "settings/EnumNames.h"
#include "surface/SpectralWaves.h"
#include <osg/Notify>
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

using namespace osgWater;

namespace {
const double kTwoPi = 6.283185307179586;
const double kGravity = 9.81;

// what makes a user mesh unusable, or "": vertices that are not finite (or beyond +-1e7 m, where
// float positions are metre-coarse) poison the bound and the clip planes; indices past the
// vertex array make GL read beyond it
std::string meshProblem(const osg::Geometry& mesh)
{
    const osg::Array* v = mesh.getVertexArray();
    if (!v || v->getNumElements() == 0) return "has no vertices";
    const unsigned int n = v->getNumElements(), dim = v->getDataSize();
    const unsigned int count = n * dim;
    if (v->getDataType() == GL_FLOAT || v->getDataType() == GL_DOUBLE) {
        for (unsigned int i = 0; i < count; ++i) {
            const double x = v->getDataType() == GL_FLOAT ? double(static_cast<const float*>(v->getDataPointer())[i])
                                                          : static_cast<const double*>(v->getDataPointer())[i];
            if (!std::isfinite(x) || std::fabs(x) > 1.0e7) return "has a vertex coordinate " + std::to_string(x);
        }
    }
    for (unsigned int p = 0; p < mesh.getNumPrimitiveSets(); ++p) {
        const osg::PrimitiveSet* ps = mesh.getPrimitiveSet(p);
        if (!ps) return "has an empty primitive set";
        if (const osg::DrawElements* de = ps->getDrawElements()) {
            for (unsigned int i = 0; i < de->getNumIndices(); ++i)
                if (de->index(i) >= n) return "indexes vertex " + std::to_string(de->index(i)) + " of " + std::to_string(n);
        } else if (const osg::DrawArrays* da = dynamic_cast<const osg::DrawArrays*>(ps)) {
            if (da->getFirst() < 0 || da->getCount() < 0 || (long long)da->getFirst() + da->getCount() > n)
                return "draws vertices past its vertex array";
        } else {
            return std::string("has a primitive set it cannot check (") + ps->className() + ")";
        }
    }
    return "";
}
}

double Wave::wavenumber() const { return kTwoPi / std::max(double(wavelength), 1.0e-3); }
bool WaterSurface::wavesTileOver(const std::vector<Wave>& waves, double tile, double tolerance)
{
    if (!(tile > 0.0)) return false;
    for (const Wave& w : waves) {
        if (w.amplitude == 0.0f) continue; // a still wave repeats over anything
        const double cycles[2] = { w.direction.x() * tile / std::max(double(w.wavelength), 1.0e-3),
                                   w.direction.y() * tile / std::max(double(w.wavelength), 1.0e-3) };
        for (double c : cycles)
            if (!(std::abs(c - std::round(c)) <= tolerance)) return false;
    }
    return true;
}

std::vector<Wave> WaterSurface::wavesSnappedToTile(const std::vector<Wave>& waves, double tile)
{
    if (!(tile > 0.0)) return waves;
    std::vector<Wave> snapped = waves;
    for (Wave& w : snapped) {
        const double cycles = tile / std::max(double(w.wavelength), 1.0e-3);
        double m = std::round(w.direction.x() * cycles), n = std::round(w.direction.y() * cycles);
        if (m == 0.0 && n == 0.0) { // longer than the tile: one cycle along its main axis
            if (std::abs(w.direction.x()) >= std::abs(w.direction.y())) m = w.direction.x() < 0.0f ? -1.0 : 1.0;
            else n = w.direction.y() < 0.0f ? -1.0 : 1.0;
        }
        const double length = std::sqrt(m * m + n * n);
        w.direction.set(float(m / length), float(n / length));
        w.wavelength = float(tile / length);
    }
    return snapped;
}

double Wave::angularFrequency() const { return std::sqrt(kGravity * wavenumber()); }

std::vector<Wave> osgWater::defaultWaves()
{
    std::vector<Wave> w(4);
    w[0].direction.set(1.0f, 0.2f);  w[0].wavelength = 6.0f; w[0].amplitude = 0.030f; w[0].phase = 0.0f;
    w[1].direction.set(0.6f, 1.0f);  w[1].wavelength = 3.5f; w[1].amplitude = 0.020f; w[1].phase = 1.3f;
    w[2].direction.set(-0.7f, 0.8f); w[2].wavelength = 2.1f; w[2].amplitude = 0.015f; w[2].phase = 2.1f;
    w[3].direction.set(0.9f, -0.5f); w[3].wavelength = 1.3f; w[3].amplitude = 0.010f; w[3].phase = 4.0f;
    for (Wave& x : w) x.direction.normalize();
    return w;
}

WaterSurface::WaterSurface()
    : _level(0.0), _size(100.0f), _center(0.0f, 0.0f), _resolution(49), _layout(MESH_EYE_RINGS), _waves(defaultWaves()),
      _model(WAVES_SUM), _spectralMade(nullptr), _uniformMesh(new osg::Geode), _revision(0), _stale(true), _waveSlope(slopeBound(_waves)),
      _saidNoPlace(false)
{
}

WaterSurface::~WaterSurface() = default;

WaterSurface::WaterSurface(const WaterSurface& o, const osg::CopyOp& copyop)
    : osg::Geode(o, copyop), _level(o._level), _size(o._size), _center(o._center), _resolution(o._resolution),
      _layout(o._layout), _waves(o._waves), _model(o._model), _wind(o._wind), _spectralMade(nullptr), _userMesh(o._userMesh), _uniformMesh(new osg::Geode), _revision(0), _stale(true),
      _waveSlope(o._waveSlope), _saidNoPlace(false)
{
}

void WaterSurface::setLevel(double z)
{
    if (!std::isfinite(z) || std::fabs(z) > 1.0e7) {
        OSG_WARN << "osgWater::WaterSurface: level " << z << " is not finite or beyond 1e7 m, using 0" << std::endl;
        z = 0.0;
    }
    _level = z;
    rebuild();
}

void WaterSurface::setSize(float size)
{
    // NaN and <= 0 name no size: the water keeps its own (a file's "Size 0" leaves the lake as it was)
    const float used = !(size > 0.01f) ? _size : std::min(size, 1.0e7f);
    if (used != size)
        OSG_WARN << "osgWater::WaterSurface: size " << size << " out of (0.01, 1e7], "
                 << (size > 0.01f ? "using " : "keeping ") << used << std::endl;
    _size = used;
    respectrum(); // the wind's cascades are chosen for the water's size (and its fetch by default)
    rebuild();
}

void WaterSurface::setCenter(const osg::Vec2& c)
{
    osg::Vec2 used;
    for (int i = 0; i < 2; ++i) used[i] = std::isnan(c[i]) ? 0.0f : std::min(std::max(c[i], -1.0e7f), 1.0e7f);
    if (!(used == c))
        OSG_WARN << "osgWater::WaterSurface: center (" << c.x() << " " << c.y() << ") out of [-1e7, 1e7], using ("
                 << used.x() << " " << used.y() << ")" << std::endl;
    _center = used;
    rebuild();
}

void WaterSurface::setResolution(unsigned int n)
{
    const unsigned int c = std::min(std::max(n, 2u), 1025u);
    if (c != n) OSG_WARN << "osgWater::WaterSurface: resolution " << n << " clamped to " << c << std::endl;
    _resolution = c;
    rebuild();
}

void WaterSurface::setMeshLayout(MeshLayout layout)
{
    if (layout != MESH_GRID && layout != MESH_EYE_RINGS) {
        OSG_WARN << "osgWater::WaterSurface: meshLayout " << int(layout) << " names no layout, using MESH_EYE_RINGS"
                 << std::endl;
        layout = MESH_EYE_RINGS;
    }
    _layout = layout;
    rebuild();
}

namespace {
// each enum's names in its values' order
const char* const kMeshLayoutNames[] = { "grid", "rings" };
const char* const kWaveModelNames[] = { "sum", "wind" };
}

std::string WaterSurface::meshLayoutNames() { return detail::joinedNames(kMeshLayoutNames); }
const char* WaterSurface::meshLayoutName(MeshLayout layout) { return detail::nameOf(kMeshLayoutNames, layout, nullptr); }

bool WaterSurface::meshLayoutFromName(const std::string& name, MeshLayout& layout)
{
    return detail::valueOf(kMeshLayoutNames, name, layout);
}

namespace {
// the rings' height H (at least RING_INNER_HEIGHT) and growth c for an eye and a reach: the
// growth that takes the last ring to the reach, or the angle between segments where that is more
struct RingScale {
    double h, c;
    RingScale(double eyeHeight, double reach)
        : h(std::max(std::fabs(eyeHeight), WaterSurface::RING_INNER_HEIGHT)),
          c(std::max(std::asinh(std::max(reach, 0.0) / h) / WaterSurface::RING_COUNT,
                     2.0 * osg::PI / WaterSurface::RING_SEGMENTS)) {}
    double radius(unsigned int i) const { return h * std::sinh(c * std::min(i, WaterSurface::RING_COUNT)); }
};
}

double WaterSurface::ringRadius(unsigned int i, double eyeHeight, double reach)
{
    return RingScale(eyeHeight, reach).radius(i);
}

double WaterSurface::ringCellSize(unsigned int i, double eyeHeight, double reach)
{
    // dr/di = H c cosh(c i) = c sqrt(r^2 + H^2): radially each ring spans the angle c from an eye
    // at height H; around, a cell spans 2 pi r / RING_SEGMENTS, which is never more (c is at least
    // 2 pi / RING_SEGMENTS and r at most sqrt(r^2 + H^2))
    const RingScale ring(eyeHeight, reach);
    const double r = ring.radius(i);
    return ring.c * std::sqrt(r * r + ring.h * ring.h);
}

double WaterSurface::ringWaveFade(double wavelength, double cellSize)
{
    if (!(cellSize > 0.0)) return 1.0;
    const double x = std::min(std::max((wavelength / cellSize - RING_FADE_MIN_CELLS) /
                                           (RING_FADE_FULL_CELLS - RING_FADE_MIN_CELLS), 0.0), 1.0);
    return x * x * (3.0 - 2.0 * x); // GLSL's smoothstep
}

void WaterSurface::setWaves(const std::vector<Wave>& waves)
{
    if (waves.size() > MAX_WAVES)
        OSG_WARN << "osgWater::WaterSurface: " << waves.size() << " waves given, using the first " << MAX_WAVES << std::endl;
    _waves.assign(waves.begin(), waves.begin() + std::min<size_t>(waves.size(), MAX_WAVES));
    for (Wave& w : _waves) {
        if (!std::isfinite(w.direction.x()) || !std::isfinite(w.direction.y()) || w.direction.length2() < 1e-12f
            || !std::isfinite(w.direction.length2())) {
            OSG_WARN << "osgWater::WaterSurface: wave direction (" << w.direction.x() << " " << w.direction.y()
                     << ") is not a direction, using (1 0)" << std::endl;
            w.direction.set(1.0f, 0.0f);
        }
        // normalised once: a unit vector is left as it is, so writing and reading a file back
        // is a fixed point (re-normalising in float flipped the last bit back and forth)
        const double len = std::hypot(double(w.direction.x()), double(w.direction.y()));
        if (std::fabs(len - 1.0) > 1.0e-6)
            w.direction.set(float(w.direction.x() / len), float(w.direction.y() / len));
        // a wave longer than 1e6 m or higher than 1e3 m is no lake wave: both clamped
        w.wavelength = detail::clampOr("osgWater::WaterSurface", "wave wavelength", w.wavelength, 0.01f, 1.0e6f, 4.0f);
        w.amplitude = detail::clampOr("osgWater::WaterSurface", "wave amplitude", w.amplitude, 0.0f, 1.0e3f, 0.0f);
        if (!std::isfinite(w.phase)) {
            OSG_WARN << "osgWater::WaterSurface: wave phase " << w.phase << " is not finite, using 0" << std::endl;
            w.phase = 0.0f;
        }
    }
    _waveSlope = slopeBound(_waves); // asked per view and frame (the glow's cone): worked out here, once
    rewaved();
}

void WaterSurface::setWaveModel(WaveModel model)
{
    if (model != WAVES_SUM && model != WAVES_WIND) {
        OSG_WARN << "osgWater::WaterSurface: waveModel " << int(model) << " names no model, using WAVES_SUM" << std::endl;
        model = WAVES_SUM;
    }
    _model = model;
    rewaved();
}

std::string WaterSurface::waveModelNames() { return detail::joinedNames(kWaveModelNames); }
const char* WaterSurface::waveModelName(WaveModel model) { return detail::nameOf(kWaveModelNames, model, nullptr); }

bool WaterSurface::waveModelFromName(const std::string& name, WaveModel& model)
{
    return detail::valueOf(kWaveModelNames, name, model);
}

void WaterSurface::setWind(const WindWaves& wind)
{
    const char* who = "osgWater::WaterSurface";
    WindWaves w = wind;
    // a gale is the strongest wind JONSWAP's fetch-limited fit describes; beyond, it is no lake
    w.speed = detail::clampOr(who, "wind speed", w.speed, 0.0f, 40.0f, 5.0f);
    w.fetch = detail::clampOr(who, "wind fetch", w.fetch, 0.0f, 1.0e7f, 0.0f);
    w.depth = detail::clampOr(who, "wind depth", w.depth, 0.0f, 1.0e5f, 0.0f);
    w.spread = detail::clampOr(who, "wind spread", w.spread, 0.0f, 1.0f, 0.0f);
    w.swell = detail::clampOr(who, "wind swell", w.swell, 0.0f, 1.0f, 0.0f);
    w.choppiness = detail::clampOr(who, "wind choppiness", w.choppiness, 0.0f, 1.0f, 0.0f);
    const double len = std::hypot(double(w.direction.x()), double(w.direction.y()));
    if (!std::isfinite(len) || len < 1e-6) {
        OSG_WARN << who << ": wind direction (" << w.direction.x() << " " << w.direction.y()
                 << ") is not a direction, using (1 0)" << std::endl;
        w.direction.set(1.0f, 0.0f);
    } else if (std::fabs(len - 1.0) > 1.0e-6) {
        w.direction.set(float(w.direction.x() / len), float(w.direction.y() / len));
    }
    _wind = w;
    respectrum();
    rewaved();
}

void WaterSurface::respectrum()
{
    std::lock_guard<std::mutex> lock(_spectralMaking);
    _spectralMade = nullptr;
    _spectral = nullptr;
}

detail::SpectralWaves* WaterSurface::getSpectralWaves() const
{
    if (_model != WAVES_WIND || !usesGrid()) return nullptr;
    // asked for on every height query, from any thread: made once, then read without the lock
    if (detail::SpectralWaves* made = _spectralMade.load(std::memory_order_acquire)) return made;
    std::lock_guard<std::mutex> lock(_spectralMaking);
    if (!_spectral.valid()) {
        WaveCascades::Params p;
        p.sea.windSpeed = _wind.speed;
        p.sea.fetch = _wind.fetch > 0.0f ? _wind.fetch : _size;
        p.sea.depth = _wind.depth > 0.0f ? _wind.depth : spectrum::kDeep;
        p.sea.windDirection = std::atan2(double(_wind.direction.y()), double(_wind.direction.x()));
        p.sea.spread = _wind.spread;
        p.sea.swell = _wind.swell;
        p.choppiness = _wind.choppiness;
        p.extent = _size;
        p.seed = _wind.seed;
        _spectral = new detail::SpectralWaves(p);
        _spectralMade.store(_spectral.get(), std::memory_order_release);
    }
    return _spectral.get();
}

void WaterSurface::setMesh(osg::Geometry* mesh)
{
    const std::string problem = mesh ? meshProblem(*mesh) : std::string();
    if (!problem.empty()) {
        OSG_WARN << "osgWater::WaterSurface: the mesh " << problem << ", using the grid instead" << std::endl;
        mesh = nullptr;
    }
    _userMesh = mesh;
    rebuild();
}

double WaterSurface::getShortestWavelength() const
{
    if (!usesGrid()) return 0.0;
    if (const detail::SpectralWaves* wind = getSpectralWaves())
        return wind->heightBound() > 0.0 ? wind->shortestWave() : 0.0;
    double shortest = 0.0;
    for (const Wave& w : _waves)
        if (w.amplitude > 0.0f && (shortest == 0.0 || w.wavelength < shortest)) shortest = w.wavelength;
    return shortest;
}

double WaterSurface::getMaxPhaseSpeed() const
{
    if (const detail::SpectralWaves* wind = getSpectralWaves()) return wind->maxPhaseSpeed();
    double c = 0.0;
    if (usesGrid())
        for (const Wave& w : _waves)
            if (w.amplitude > 0.0f) c = std::max(c, w.angularFrequency() / w.wavenumber());
    return c;
}

double WaterSurface::getMaxSlope() const
{
    if (const detail::SpectralWaves* wind = getSpectralWaves()) return wind->slopeBound();
    return usesGrid() ? _waveSlope : 1.0;
}

double WaterSurface::slopeBound(const std::vector<Wave>& waves)
{
    double total = 0.0, best = 0.0;
    for (const Wave& w : waves) total += std::fabs(double(w.amplitude)) * w.wavenumber();
    const int n = 720;
    for (int i = 0; i < n; ++i) {
        const double psi = osg::PI * i / n; // u and -u give the same sum
        const double ux = std::cos(psi), uy = std::sin(psi);
        double along = 0.0;
        for (const Wave& w : waves) {
            osg::Vec2d d(w.direction.x(), w.direction.y());
            if (!(d.normalize() > 0.0)) continue;
            along += std::fabs(double(w.amplitude)) * w.wavenumber() * std::fabs(d.x() * ux + d.y() * uy);
        }
        best = std::max(best, along);
    }
    // between two sampled directions the sum rises at most total * (half the step)
    return std::min(total, best + total * 0.5 * osg::PI / n);
}

float WaterSurface::getMaxAmplitude() const
{
    if (_userMesh.valid()) {
        const osg::BoundingBox& bb = _userMesh->getBoundingBox();
        if (!bb.valid()) return 0.0f;
        return float(std::max(std::fabs(bb.zMax() - _level), std::fabs(bb.zMin() - _level)));
    }
    if (const detail::SpectralWaves* wind = getSpectralWaves()) return float(wind->heightBound());
    float a = 0.0f;
    for (const Wave& w : _waves) a += w.amplitude;
    return a;
}

float WaterSurface::wrappedPhase(unsigned int i, double t) const
{
    if (i >= _waves.size()) return 0.0f;
    if (!std::isfinite(t)) t = 0.0;
    const Wave& w = _waves[i];
    double p = std::fmod(w.angularFrequency() * t - double(w.phase), kTwoPi);
    if (p < 0.0) p += kTwoPi;
    return float(p);
}

bool WaterSurface::isPlace(double x, double y) const
{
    if (std::isfinite(x) && std::isfinite(y)) return true;
    if (!_saidNoPlace.exchange(true))
        OSG_WARN << "osgWater::WaterSurface: asked about (" << x << ", " << y
                 << "), which is no place: answering the level and the up normal (said once)" << std::endl;
    return false;
}

double WaterSurface::height(double x, double y, double t) const
{
    if (!isPlace(x, y)) return _level;
    if (const detail::SpectralWaves* wind = getSpectralWaves()) return _level + wind->height(x, y, t);
    double h = _level;
    for (unsigned int i = 0; i < _waves.size(); ++i) {
        const Wave& w = _waves[i];
        const double k = w.wavenumber();
        h += w.amplitude * std::sin(k * (w.direction.x() * x + w.direction.y() * y) - wrappedPhase(i, t));
    }
    return h;
}

osg::Vec3d WaterSurface::normal(double x, double y, double t) const
{
    if (!isPlace(x, y)) return osg::Vec3d(0.0, 0.0, 1.0);
    if (const detail::SpectralWaves* wind = getSpectralWaves()) return wind->normal(x, y, t);
    double hx = 0.0, hy = 0.0;
    for (unsigned int i = 0; i < _waves.size(); ++i) {
        const Wave& w = _waves[i];
        const double k = w.wavenumber();
        const double c = w.amplitude * k * std::cos(k * (w.direction.x() * x + w.direction.y() * y) - wrappedPhase(i, t));
        hx += c * w.direction.x();
        hy += c * w.direction.y();
    }
    osg::Vec3d n(-hx, -hy, 1.0);
    n.normalize();
    return n;
}

bool WaterSurface::intersect(const osg::Vec3d& start, const osg::Vec3d& end, double t, double& ratio,
                             osg::Vec3d& point, osg::Vec3d& normal) const
{
    // where the surface can be: the grid's square (the mesh's bounds), between its lowest troughs
    // and highest crests
    double x0, y0, x1, y1;
    if (usesGrid()) {
        x0 = _center.x() - 0.5 * _size;
        y0 = _center.y() - 0.5 * _size;
        x1 = x0 + _size;
        y1 = y0 + _size;
    } else {
        const osg::BoundingBox& b = _userMesh->getBoundingBox();
        x0 = b.xMin(), y0 = b.yMin(), x1 = b.xMax(), y1 = b.yMax();
    }
    // padded a little, so that flat water is a slab the segment crosses, not a plane it may
    // only touch in rounding
    const double a = (usesGrid() ? getMaxAmplitude() : 0.0) + 1.0e-9 * (1.0 + std::fabs(_level));
    const double boxLo[3] = { x0, y0, _level - a }, boxHi[3] = { x1, y1, _level + a };
    const osg::Vec3d d = end - start;
    double s0 = 0.0, s1 = 1.0; // the segment's part inside that box (slab clipping)
    for (int i = 0; i < 3; ++i) {
        if (std::fabs(d[i]) < 1e-300) {
            if (start[i] < boxLo[i] || start[i] > boxHi[i]) return false;
            continue;
        }
        double ta = (boxLo[i] - start[i]) / d[i], tb = (boxHi[i] - start[i]) / d[i];
        if (ta > tb) std::swap(ta, tb);
        s0 = std::max(s0, ta);
        s1 = std::min(s1, tb);
        if (s0 > s1) return false;
    }
    const detail::SpectralWaves* wind = getSpectralWaves();
    const bool waves = usesGrid() && (wind ? wind->heightBound() > 0.0 : !_waves.empty());
    const double maxSlope = waves ? getMaxSlope() : 0.0;
    // the wind's cascades at t, held for the whole march: one lock, not one a sample (nothing
    // below asks the waves through height() or normal() while it is held)
    std::optional<detail::SpectralWaves::Sampler> windAt;
    if (wind) windAt.emplace(wind->at(t));
    // the signed height above the surface at s along the segment, f, and its rate of change
    // dz - grad h . dxy: one sample of the wind's cascades gives both
    struct Above { double f, rise; };
    auto above = [&](double s, bool withRise) {
        const osg::Vec3d p = start + d * s;
        if (!usesGrid() || !isPlace(p.x(), p.y())) return Above{ p.z() - _level, d.z() };
        if (windAt) {
            osg::Vec2d slope;
            const double h = windAt->heightAndSlope(p.x(), p.y(), slope);
            return Above{ p.z() - _level - h, d.z() - (slope.x() * d.x() + slope.y() * d.y()) };
        }
        const double f = p.z() - height(p.x(), p.y(), t);
        if (!withRise || !waves) return Above{ f, d.z() };
        const osg::Vec3d n = this->normal(p.x(), p.y(), t);
        return Above{ f, d.z() + (n.x() * d.x() + n.y() * d.y()) / std::max(n.z(), 1e-12) };
    };
    // |d2h/du2| along any horizontal unit u: at most sum a k^2 for the waves; the wind's bound
    double curvature = 0.0;
    if (waves && wind) curvature = wind->curvatureBound();
    else if (waves)
        for (const Wave& w : _waves) curvature += std::fabs(double(w.amplitude)) * w.wavenumber() * w.wavenumber();
    const double dxy = osg::Vec2d(d.x(), d.y()).length();
    // Steps that cannot pass a crossing, the longer of two bounds on the height above the surface
    // f: it changes by at most |dz| + slope |dxy| per unit of s (a step of |f| / that), and it
    // bends by at most c = curvature |dxy|^2, so g = |f| moving at g' stays above
    // g + g' x - c x^2 / 2, positive for x < 2 g / (sqrt(g'^2 + 2 c g) - g'). A ray that clips a
    // crest over a few millimetres meets it. One that touches a crest exactly is approached in ever
    // shorter steps, so none is shorter than 1e-5 of the segment (1e5 steps at most).
    const double rate = std::fabs(d.z()) + maxSlope * dxy;
    const double bend = curvature * dxy * dxy;
    const double minStep = (s1 - s0) * 1.0e-5;
    auto safeStep = [&](const Above& a) {
        const double g = std::fabs(a.f), dg = a.f > 0.0 ? a.rise : -a.rise;
        const double away = std::sqrt(dg * dg + 2.0 * bend * g) - dg;
        const double bent = away > 0.0 ? 2.0 * g / away : 1e30;
        return std::max(minStep, 0.999 * std::max(rate > 0.0 ? g / rate : 1e30, bent));
    };
    // the first sign change between samples, then bisection (lo keeps the start's side)
    double sa = s0;
    Above here = above(s0, true);
    const bool startAbove = here.f > 0.0; // the side every sample keeps until the crossing
    bool found = here.f == 0.0;
    ratio = s0;
    while (!found && sa < s1) {
        const double sb = std::min(s1, sa + safeStep(here));
        if (!(sb > sa)) break; // a step below the precision of s: nothing left to sample
        const Above next = above(sb, true);
        if ((next.f > 0.0) != startAbove || next.f == 0.0) {
            // halved until no double lies between the two ends (further halving changes nothing)
            double lo = sa, hi = sb;
            for (int k = 0; k < 80; ++k) {
                const double sm = 0.5 * (lo + hi);
                if (!(sm > lo && sm < hi)) break;
                if ((above(sm, false).f > 0.0) == startAbove) lo = sm;
                else hi = sm;
            }
            ratio = 0.5 * (lo + hi);
            found = true;
        }
        sa = sb;
        here = next;
    }
    if (!found) return false;
    point = start + d * ratio;
    normal = osg::Vec3d(0.0, 0.0, 1.0);
    if (usesGrid() && windAt && isPlace(point.x(), point.y())) normal = windAt->normal(point.x(), point.y());
    else if (usesGrid() && !windAt) normal = this->normal(point.x(), point.y(), t);
    return true;
}

void WaterSurface::rewaved()
{
    // the built-in mesh does not depend on the waves (the shaders displace it): only its bound does.
    // Rebuilding it would cost a new vertex buffer every time an animation sets them
    ++_revision;
    if (_stale || !usesGrid() || !getNumDrawables()) {
        rebuild();
        return;
    }
    std::lock_guard<std::mutex> lock(_building);
    for (osg::Geode* geode : { static_cast<osg::Geode*>(this), _uniformMesh.get() })
        for (unsigned int i = 0; i < geode->getNumDrawables(); ++i)
            if (osg::Geometry* g = geode->getDrawable(i)->asGeometry()) {
                g->setInitialBound(builtInBound());
                g->dirtyBound();
            }
    _uniformMesh->dirtyBound();
    dirtyBound();
}

osg::BoundingBox WaterSurface::builtInBound() const
{
    const float a = getMaxAmplitude();
    const float x0 = _center.x() - 0.5f * _size, y0 = _center.y() - 0.5f * _size;
    return osg::BoundingBox(x0, y0, float(_level) - a, x0 + _size, y0 + _size, float(_level) + a);
}

void WaterSurface::rebuild()
{
    ++_revision;
    _stale = true;
    dirtyBound();
}

osg::Geometry* WaterSurface::getGeometry()
{
    if (_stale) {
        std::lock_guard<std::mutex> lock(_building);
        if (_stale) {
            build();
            _stale = false;
        }
    }
    return getNumDrawables() ? getDrawable(0)->asGeometry() : nullptr;
}

void WaterSurface::traverse(osg::NodeVisitor& nv)
{
    getGeometry();
    osg::Geode::traverse(nv);
}

osg::BoundingSphere WaterSurface::computeBound() const
{
    getGeometry();
    return osg::Geode::computeBound();
}

void WaterSurface::resizeGLObjectBuffers(unsigned int maxSize)
{
    osg::Geode::resizeGLObjectBuffers(maxSize);
    _uniformMesh->resizeGLObjectBuffers(maxSize);
}

void WaterSurface::releaseGLObjects(osg::State* state) const
{
    osg::Geode::releaseGLObjects(state);
    _uniformMesh->releaseGLObjects(state);
}

osg::Node* WaterSurface::getUniformMesh()
{
    getGeometry(); // built together
    return _uniformMesh.get();
}

void WaterSurface::build()
{
    removeDrawables(0, getNumDrawables());
    _uniformMesh->removeDrawables(0, _uniformMesh->getNumDrawables());
    if (_userMesh.valid()) {
        addDrawable(_userMesh.get());
        _uniformMesh->addDrawable(_userMesh.get());
        return;
    }
    osg::ref_ptr<osg::Geometry> g = _layout == MESH_GRID ? buildGrid() : buildRings();
    finishBuiltIn(*g);
    addDrawable(g.get());
    if (_layout != MESH_GRID) {
        g = buildGrid();
        finishBuiltIn(*g);
    }
    _uniformMesh->addDrawable(g.get());
}

void WaterSurface::finishBuiltIn(osg::Geometry& g) const
{
    g.setUseVertexBufferObjects(true);
    osg::ref_ptr<osg::Vec3Array> nrm = new osg::Vec3Array(1);
    (*nrm)[0].set(0.0f, 0.0f, 1.0f);
    g.setNormalArray(nrm.get(), osg::Array::BIND_OVERALL);
    // the vertex shader moves vertices by up to the amplitude (and the rings about the square):
    // the bound is the square between the troughs and the crests, so culling stays right
    g.setInitialBound(builtInBound());
}

namespace {
// two triangles of a quad whose corners p0..p3 run counter-clockwise seen from above
void addQuad(osg::DrawElementsUInt& tris, unsigned int p0, unsigned int p1, unsigned int p2, unsigned int p3)
{
    for (unsigned int v : { p0, p1, p2, p0, p2, p3 }) tris.push_back(v);
}
}

osg::Geometry* WaterSurface::buildGrid() const
{
    const unsigned int n = _resolution;
    osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array;
    v->reserve(n * n);
    const float step = _size / float(n - 1);
    const float x0 = _center.x() - 0.5f * _size, y0 = _center.y() - 0.5f * _size;
    for (unsigned int j = 0; j < n; ++j)
        for (unsigned int i = 0; i < n; ++i)
            v->push_back(osg::Vec3(x0 + i * step, y0 + j * step, float(_level)));
    osg::ref_ptr<osg::DrawElementsUInt> tris = new osg::DrawElementsUInt(GL_TRIANGLES);
    tris->reserve((n - 1) * (n - 1) * 6);
    for (unsigned int j = 0; j + 1 < n; ++j)
        for (unsigned int i = 0; i + 1 < n; ++i) {
            const unsigned int a = j * n + i, b = a + 1, c = a + n, d = c + 1;
            addQuad(*tris, a, b, d, c);
        }
    osg::Geometry* g = new osg::Geometry;
    g->setName("osgWater.grid");
    g->setVertexArray(v.get());
    g->addPrimitiveSet(tris.get());
    return g;
}

namespace {
// the drawn bound is the initial bound (the square between troughs and crests), whatever the
// vertex array holds: the rings' CPU vertices reach past the square
struct InitialBoundOnly : osg::Drawable::ComputeBoundingBoxCallback {
    osg::BoundingBox computeBound(const osg::Drawable&) const override { return osg::BoundingBox(); }
};
}

osg::Geometry* WaterSurface::buildRings() const
{
    // the vertex array holds the rings evenly spaced out to the square's corners, flat at the level
    // (what a polytope intersector or the statistics read); water.vert reads ring i and direction
    // phi back from each vertex (i = its distance from the centre over the spacing) and places it
    // for this view's eye. One array: a second (texture coordinates) in the same vertex buffer
    // crashed Mesa's llvmpipe when buffers were remade under it
    const unsigned int m = RING_SEGMENTS, n = RING_COUNT;
    osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array;
    v->reserve((n + 1) * m);
    const double spacing = 0.5 * _size * std::sqrt(2.0) / n;
    for (unsigned int i = 0; i <= n; ++i)
        for (unsigned int j = 0; j < m; ++j) {
            const double phi = kTwoPi * j / m, r = spacing * i;
            v->push_back(osg::Vec3(float(_center.x() + r * std::cos(phi)), float(_center.y() + r * std::sin(phi)),
                                   float(_level)));
        }
    osg::ref_ptr<osg::DrawElementsUInt> tris = new osg::DrawElementsUInt(GL_TRIANGLES);
    tris->reserve(n * m * 6);
    for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < m; ++j) {
            // a on ring i, b the next around it, c and d one ring out (ring 0 is one point: a = b there)
            const unsigned int a = i * m + j, b = i * m + (j + 1) % m, c = a + m, d = b + m;
            addQuad(*tris, a, c, d, b);
        }
    osg::Geometry* g = new osg::Geometry;
    g->setName("osgWater.rings");
    g->setVertexArray(v.get());
    g->addPrimitiveSet(tris.get());
    g->setComputeBoundingBoxCallback(new InitialBoundOnly);
    return g;
}
