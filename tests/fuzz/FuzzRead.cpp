#include "FuzzRead.h"
#include <osgWater/WaterNode>
#include <osgDB/Registry>
#include <osg/Notify>
#include <cmath>
#include <sstream>

namespace osgwater_fuzz {

namespace {

struct Silent : public osg::NotifyHandler {
    void notify(osg::NotifySeverity, const char*) override {}
};

osgDB::ReaderWriter* readerWriter()
{
    static osg::ref_ptr<osgDB::ReaderWriter> rw = osgDB::Registry::instance()->getReaderWriterForExtension("osgt");
    return rw.get();
}

bool finite(const osg::Vec3& v) { return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()); }

// osg::Node's own InitialBound is OSG's to fuzz: OSG writes a non-finite one as "inf", which its parser
// reads as 0, so it could never round-trip
void resetInfiniteBound(osg::Node& n)
{
    const osg::BoundingSphere& b = n.getInitialBound();
    if (!std::isfinite(b.center().x()) || !std::isfinite(b.center().y()) || !std::isfinite(b.center().z()) ||
        !std::isfinite(b.radius()))
        n.setInitialBound(osg::BoundingSphere());
}

// the setters' promise: whatever the file said, what is stored is finite and usable
std::string checkSettings(const osgWater::WaterSettings& s)
{
    const float values[] = { s.getAirIOR(), s.getWaterIOR(), s.getAttenuation(), s.getFresnelExponent(),
                             s.getReflectionScale(), s.getErrorBudget(), s.getOneStepScale(),
                             s.getOneStepMaxDepth(), s.getUnderwaterLookupScale(), s.getGlowIntensity(),
                             s.getGlowRadius(), s.getGlowResolution(), s.getGlowExponent(),
                             s.getFovExtensionNear(), s.getFovExtensionFar(), s.getFovExtensionFalloff(),
                             s.getClipOffset(), s.getCausticsIntensity(), s.getNormalReflectance(),
                             s.getFresnelReciprocalPower(), s.getReflectionPlaneHeight(), s.getRefractionPlaneDepth(),
                             s.getPassTargetScale(), s.getCausticsMotionTolerance(), s.getExposure() };
    for (float v : values)
        if (!std::isfinite(v)) return "a setting is not finite";
    if (!finite(s.getWaterColor()) || !finite(s.getSunDirection()) || !finite(s.getSunColor()) ||
        !finite(s.getAmbientColor()))
        return "a colour or the sun direction is not finite";
    using W = osgWater::WaterSettings;
    auto outside = [](int v, int last) { return v < 0 || v > last; };
    if (outside(s.getFresnelModel(), W::FRESNEL_RECIPROCAL) || outside(s.getRefractionLookup(), W::VIRTUAL_VERTICES) ||
        outside(s.getReflectionLookup(), W::REFLECTION_SEARCH) || outside(s.getCausticsGather(), W::GATHER_CPU) ||
        outside(s.getCausticsMethod(), W::CAUSTICS_PROCEDURAL_SCREEN) || outside(s.getUnderwaterModel(), W::UNDERWATER_THESIS))
        return "an enum setting holds a value it does not define";
    if (s.getSearchSteps() < 1 || s.getReflectionTextureSize() < 1 || s.getRefractionTextureSize() < 1 ||
        s.getCausticsResolution() < 1 || s.getPhotonGridSize() < 1 || s.getEnvironmentMapSize() < 1)
        return "a count or size is not positive";
    return "";
}

std::string checkSurface(const osgWater::WaterSurface& f)
{
    if (!std::isfinite(f.getLevel()) || !std::isfinite(f.getSize()) || !(f.getSize() > 0.0f) ||
        !std::isfinite(f.getCenter().x()) || !std::isfinite(f.getCenter().y()) || !std::isfinite(f.getMaxAmplitude()))
        return "the surface's level, size, centre or amplitude is not finite";
    if (f.getResolution() < 2 || f.getWaves().size() > osgWater::WaterSurface::MAX_WAVES ||
        !osgWater::WaterSurface::meshLayoutName(f.getMeshLayout()))
        return "the surface's resolution, mesh layout or wave count is out of range";
    for (const osgWater::Wave& w : f.getWaves())
        if (!std::isfinite(w.wavenumber()) || !std::isfinite(w.angularFrequency()) || !std::isfinite(w.amplitude) ||
            !std::isfinite(w.phase) || !std::isfinite(w.direction.x()) || !std::isfinite(w.direction.y()))
            return "a wave is not finite";
    if (!std::isfinite(f.height(0.0, 0.0, 1.0e7))) return "the surface height is not finite";
    return "";
}

std::string write(const osg::Object& o, bool ascii)
{
    std::ostringstream out;
    // to a stream the osg2 plugin writes .osgt only when told the file type
    osg::ref_ptr<osgDB::Options> opts = new osgDB::Options;
    if (ascii) opts->setPluginStringData("fileType", "Ascii");
    if (!readerWriter()->writeObject(o, out, opts.get()).success()) return "";
    return out.str();
}

osg::ref_ptr<osg::Object> read(const std::string& bytes)
{
    std::istringstream in(bytes);
    return readerWriter()->readObject(in, nullptr).getObject();
}

// written, read and written again: the same bytes (one normalisation, then a fixed point)
std::string checkRoundTrip(const osg::Object& o)
{
    for (bool ascii : { true, false }) {
        const std::string first = write(o, ascii);
        if (first.empty()) return ascii ? "writing .osgt failed" : "writing .osgb failed";
        osg::ref_ptr<osg::Object> back = read(first);
        if (!back.valid()) return ascii ? "the written .osgt does not read back" : "the written .osgb does not read back";
        if (write(*back, ascii) != first) return ascii ? ".osgt round trip is not a fixed point" : ".osgb round trip is not a fixed point";
    }
    return "";
}

}

void init()
{
    osg::setNotifyHandler(new Silent);
    osg::setNotifyLevel(osg::ALWAYS);
    readerWriter();
}

bool isWater(const uint8_t* data, size_t size)
{
    osg::ref_ptr<osg::Object> obj = read(std::string(reinterpret_cast<const char*>(data), size));
    return dynamic_cast<osgWater::WaterNode*>(obj.get()) || dynamic_cast<osgWater::WaterSettings*>(obj.get()) ||
           dynamic_cast<osgWater::WaterSurface*>(obj.get());
}

std::string readOne(const uint8_t* data, size_t size)
{
    osg::ref_ptr<osg::Object> obj = read(std::string(reinterpret_cast<const char*>(data), size));
    if (!obj.valid()) return ""; // rejected: fine, as long as nothing broke
    std::string failure;
    if (osgWater::WaterNode* w = dynamic_cast<osgWater::WaterNode*>(obj.get())) {
        failure = checkSettings(*w->getSettings());
        if (failure.empty()) failure = checkSurface(*w->getSurface());
        w->removeChildren(0, w->getNumChildren()); // other OSG classes are OSG's to fuzz
        resetInfiniteBound(*w);
        resetInfiniteBound(*w->getSurface());
        if (failure.empty()) failure = checkRoundTrip(*w);
    } else if (osgWater::WaterSettings* s = dynamic_cast<osgWater::WaterSettings*>(obj.get())) {
        failure = checkSettings(*s);
        if (failure.empty()) failure = checkRoundTrip(*s);
    } else if (osgWater::WaterSurface* f = dynamic_cast<osgWater::WaterSurface*>(obj.get())) {
        failure = checkSurface(*f);
        resetInfiniteBound(*f);
        if (failure.empty()) failure = checkRoundTrip(*f);
    }
    return failure;
}

}
