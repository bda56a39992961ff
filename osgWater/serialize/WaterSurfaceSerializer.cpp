// osgDB wrapper of WaterSurface (see WaterSettingsSerializer.cpp for how osgDB finds it).
#include <osgWater/WaterSurface>
#include "serialize/FieldSerializers.h"
#include "serialize/LayoutVersion.h"
#include "serialize/OtherFields.h"
#include <osgDB/ObjectWrapper>
#include <osgDB/InputStream>
#include <osgDB/OutputStream>
#include <osgDB/Registry>

using namespace osgWater;

namespace {

bool checkWaves(const WaterSurface& s) { return !(s.getWaves() == defaultWaves()); }

// Binary: a count and the numbers. Text: a count and a block of lines of five numbers, read whole
// before any is used, so a wrong count or a bad number is reported and the waves kept as they were.
bool readWaves(osgDB::InputStream& is, WaterSurface& s)
{
    const unsigned int most = 1024; // a garbage count would make us read forever
    if (is.isBinary()) {
        const unsigned int n = is.readSize();
        if (n > most) {
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
    std::string count, why;
    unsigned int n = 0;
    is >> count;
    const detail::TextCursor text(is);
    const std::streamoff at = text.valid() ? text.offset() : -1; // the field's line, for messages
    const bool counted = detail::parseToken(count, n, why);
    if (!counted) why = "count \"" + count + "\" " + why;
    std::string token;
    is >> token;
    if (token != "{") { // no block: what the line holds is left to be read as fields (OtherFields.h)
        detail::reportField(is, s, "Waves", "expects a count and a block; keeping the " + std::to_string(s.getWaves().size()) + " waves", at);
        return true;
    }
    std::vector<std::string> numbers;
    for (is >> token; token != "}" && !token.empty() && !is.getException(); is >> token)
        if (numbers.size() <= 5 * most) numbers.push_back(token);
    if (is.getException()) return false;
    std::vector<Wave> waves(counted ? std::min(n, most) : 0);
    if (counted && n > most) why = "count " + count + " is more than " + std::to_string(most);
    else if (counted && numbers.size() != 5 * size_t(n))
        why = count + " waves are five numbers each, " + std::to_string(5 * size_t(n)) + ", and the block holds " +
              std::to_string(numbers.size());
    for (size_t i = 0; why.empty() && i < numbers.size(); ++i) {
        Wave& w = waves[i / 5];
        float* const fields[] = { &w.direction.x(), &w.direction.y(), &w.wavelength, &w.amplitude, &w.phase };
        if (!detail::parseToken(numbers[i], *fields[i % 5], why))
            why = "wave " + std::to_string(i / 5 + 1) + ": \"" + numbers[i] + "\" " + why;
    }
    if (why.empty())
        s.setWaves(waves);
    else
        detail::reportField(is, s, "Waves", why + "; keeping the " + std::to_string(s.getWaves().size()) + " waves", at);
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

// the wind's fields, by name in a block, in the order written
struct WindField {
    const char* name;
    float WindWaves::*number;
    osg::Vec2 WindWaves::*vector;
    unsigned int WindWaves::*whole;
};
const WindField kWindFields[] = {
    { "Speed", &WindWaves::speed, nullptr, nullptr },   { "Direction", nullptr, &WindWaves::direction, nullptr },
    { "Fetch", &WindWaves::fetch, nullptr, nullptr },   { "Depth", &WindWaves::depth, nullptr, nullptr },
    { "Spread", &WindWaves::spread, nullptr, nullptr }, { "Swell", &WindWaves::swell, nullptr, nullptr },
    { "Choppiness", &WindWaves::choppiness, nullptr, nullptr }, { "Seed", nullptr, nullptr, &WindWaves::seed },
};

template <typename T> bool readInto(osgDB::InputStream& is, T& field, std::string& why)
{
    T value = field;
    if (!detail::readValue(is, value, why)) return false;
    field = value;
    return true;
}

// the wind as named fields in a block, in any order, each read into a default wind (setWind clamps);
// a field that does not parse, or that the wind lacks, is reported and the rest still read
bool readWind(osgDB::InputStream& is, WaterSurface& s)
{
    WindWaves w;
    if (is.isBinary()) {
        is >> is.BEGIN_BRACKET;
        for (const WindField& f : kWindFields) {
            if (f.number) is >> w.*f.number;
            if (f.vector) is >> w.*f.vector;
            if (f.whole) is >> w.*f.whole;
        }
        is >> is.END_BRACKET;
        s.setWind(w);
        return true;
    }
    detail::TextCursor text(is);
    std::string name;
    is >> name; // the block's "{"
    for (is >> name; name != "}" && !name.empty() && !is.getException(); is >> name) {
        const WindField* field = nullptr;
        for (const WindField& f : kWindFields) field = name == f.name ? &f : field;
        std::string why;
        if (!field) {
            detail::reportField(is, s, "Wind " + name, "is not a field of the wind; skipped to its end");
            if (text.valid()) text.skipField();
        } else if (!(field->number ? readInto(is, w.*field->number, why)
                                   : field->vector ? readInto(is, w.*field->vector, why) : readInto(is, w.*field->whole, why)))
            detail::reportField(is, s, std::string("Wind ") + field->name, why + "; keeping its default");
    }
    if (is.getException()) return false;
    s.setWind(w);
    return true;
}

bool writeWind(osgDB::OutputStream& os, const WaterSurface& s)
{
    const WindWaves& w = s.getWind();
    int digits = detail::digitsFor(w.direction);
    for (const WindField& f : kWindFields)
        if (f.number) digits = std::max(digits, detail::digitsFor(w.*f.number));
    os << detail::setPrecision(digits) << os.BEGIN_BRACKET << std::endl;
    for (const WindField& f : kWindFields) {
        os << os.PROPERTY(f.name);
        if (f.number) os << w.*f.number;
        if (f.vector) os << w.*f.vector;
        if (f.whole) os << w.*f.whole;
        os << std::endl;
    }
    os << os.END_BRACKET << detail::restorePrecision << std::endl;
    return true;
}

}

REGISTER_OBJECT_WRAPPER(osgWater_WaterSurface, new osgWater::WaterSurface, osgWater::WaterSurface,
                        "osg::Object osg::Node osgWater::WaterSurface") // not osg::Geode: the grid is rebuilt, never stored
{
    ADD_BINARY_LAYOUT_SERIALIZER("osgWater::WaterSurface");
    ADD_DOUBLE_FIELD(Level, 0.0);
    ADD_FLOAT_FIELD(Size, 100.0f);
    ADD_VEC2F_FIELD(Center, osg::Vec2f(0.0f, 0.0f));
    ADD_UINT_FIELD(Resolution, 49u);
    BEGIN_ENUM_FIELD(MeshLayout, MESH_EYE_RINGS);
        ADD_ENUM_VALUE(MESH_GRID);
        ADD_ENUM_VALUE(MESH_EYE_RINGS);
    END_ENUM_FIELD();
    ADD_USER_SERIALIZER(Waves);
    ADD_OBJECT_SERIALIZER(Mesh, osg::Geometry, NULL);
    BEGIN_ENUM_FIELD(WaveModel, WAVES_SUM);
        ADD_ENUM_VALUE(WAVES_SUM);
        ADD_ENUM_VALUE(WAVES_WIND);
    END_ENUM_FIELD();
    ADD_USER_SERIALIZER(Wind);
    ADD_OTHER_FIELDS_SERIALIZER("osgWater::WaterSurface");
}

