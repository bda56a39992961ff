// osgDB wrapper of WaterSurface (see WaterSettingsSerializer.cpp for how osgDB finds it).
#include <osgWater/WaterSurface>
#include "serialize/PreciseSerializer.h"
#include "serialize/LayoutVersion.h"
#include <osgDB/ObjectWrapper>
#include <osgDB/InputStream>
#include <osgDB/OutputStream>
#include <osgDB/Registry>

using namespace osgWater;

namespace {

bool checkWaves(const WaterSurface& s) { return !(s.getWaves() == defaultWaves()); }

bool readWaves(osgDB::InputStream& is, WaterSurface& s)
{
    const unsigned int n = is.readSize();
    if (n > 1024) { // a garbage count would make us read forever
        is.throwException("osgWater::WaterSurface: absurd wave count");
        return false;
    }
    std::vector<Wave> waves(n);
    is >> is.BEGIN_BRACKET;
    for (Wave& w : waves) is >> w.direction >> w.wavelength >> w.amplitude >> w.phase;
    is >> is.END_BRACKET;
    s.setWaves(waves);
    return true;
}

bool writeWaves(osgDB::OutputStream& os, const WaterSurface& s)
{
    const std::vector<Wave>& waves = s.getWaves();
    int digits = 6;
    for (const Wave& w : waves)
        digits = std::max({ digits, detail::digitsFor(w.direction), detail::digitsFor(w.wavelength),
                            detail::digitsFor(w.amplitude), detail::digitsFor(w.phase) });
    os << detail::setPrecision(digits);
    os.writeSize(waves.size());
    os << os.BEGIN_BRACKET << std::endl;
    for (const Wave& w : waves) os << w.direction << w.wavelength << w.amplitude << w.phase << std::endl;
    os << os.END_BRACKET << detail::restorePrecision << std::endl;
    return true;
}

bool checkWind(const WaterSurface& s) { return s.getWind() != WindWaves(); }

// the wind as named fields in a block, each read into a default wind (setWind clamps)
bool readWind(osgDB::InputStream& is, WaterSurface& s)
{
    WindWaves w;
    is >> is.BEGIN_BRACKET;
    is >> is.PROPERTY("Speed") >> w.speed;
    is >> is.PROPERTY("Direction") >> w.direction;
    is >> is.PROPERTY("Fetch") >> w.fetch;
    is >> is.PROPERTY("Depth") >> w.depth;
    is >> is.PROPERTY("Spread") >> w.spread;
    is >> is.PROPERTY("Swell") >> w.swell;
    is >> is.PROPERTY("Seed") >> w.seed;
    is >> is.END_BRACKET;
    s.setWind(w);
    return true;
}

bool writeWind(osgDB::OutputStream& os, const WaterSurface& s)
{
    const WindWaves& w = s.getWind();
    int digits = 6;
    for (float f : { w.speed, w.fetch, w.depth, w.spread, w.swell }) digits = std::max(digits, detail::digitsFor(f));
    digits = std::max(digits, detail::digitsFor(w.direction));
    os << detail::setPrecision(digits) << os.BEGIN_BRACKET << std::endl;
    os << os.PROPERTY("Speed") << w.speed << std::endl;
    os << os.PROPERTY("Direction") << w.direction << std::endl;
    os << os.PROPERTY("Fetch") << w.fetch << std::endl;
    os << os.PROPERTY("Depth") << w.depth << std::endl;
    os << os.PROPERTY("Spread") << w.spread << std::endl;
    os << os.PROPERTY("Swell") << w.swell << std::endl;
    os << os.PROPERTY("Seed") << w.seed << std::endl;
    os << os.END_BRACKET << detail::restorePrecision << std::endl;
    return true;
}

}

REGISTER_OBJECT_WRAPPER(osgWater_WaterSurface, new osgWater::WaterSurface, osgWater::WaterSurface,
                        "osg::Object osg::Node osgWater::WaterSurface") // not osg::Geode: the grid is rebuilt, never stored
{
    ADD_BINARY_LAYOUT_SERIALIZER("osgWater::WaterSurface");
    ADD_PRECISE_DOUBLE_SERIALIZER(Level, 0.0);
    ADD_PRECISE_FLOAT_SERIALIZER(Size, 100.0f);
    ADD_PRECISE_VEC2F_SERIALIZER(Center, osg::Vec2f(0.0f, 0.0f));
    ADD_UINT_SERIALIZER(Resolution, 49u);
    BEGIN_ENUM_SERIALIZER(MeshLayout, MESH_EYE_RINGS);
        ADD_ENUM_VALUE(MESH_GRID);
        ADD_ENUM_VALUE(MESH_EYE_RINGS);
    END_ENUM_SERIALIZER();
    ADD_USER_SERIALIZER(Waves);
    ADD_OBJECT_SERIALIZER(Mesh, osg::Geometry, NULL);
    BEGIN_ENUM_SERIALIZER(WaveModel, WAVES_SUM);
        ADD_ENUM_VALUE(WAVES_SUM);
        ADD_ENUM_VALUE(WAVES_WIND);
    END_ENUM_SERIALIZER();
    ADD_USER_SERIALIZER(Wind);
}

