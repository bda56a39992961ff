#include "serialize/TextReading.h"
#include <osgDB/StreamOperator>
#include <osg/Math>
#include <osg/Notify>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <sstream>
#include <typeinfo>

namespace osgWater {
namespace detail {

namespace {

// osgDB's InputStream keeps its iterator (and so the text) protected, with no accessor; a member
// pointer named through a derived class reaches it without touching the object's layout
struct InputStreamInternals : osgDB::InputStream {
    static osgDB::InputIterator* iterator(osgDB::InputStream& is) { return (is.*(&InputStreamInternals::_in)).get(); }
};

// the text iterator is private to OSG's osg plugin; the XML one parses its file up front and reads
// from a copy, so only the plain text one is read beside osgDB
bool isPlainText(osgDB::InputIterator* it)
{
    return it && std::strstr(typeid(*it).name(), "AsciiInputIterator") != nullptr;
}

// std::errc() when the whole token is a number, result_out_of_range past a double, else invalid_argument
std::errc parseWhole(const std::string& token, double& v)
{
    const char* begin = token.data() + (token.size() > 1 && token[0] == '+' ? 1 : 0);
    const char* end = token.data() + token.size();
    const std::from_chars_result r = std::from_chars(begin, end, v);
    if (r.ptr != end || begin == end) return std::errc::invalid_argument;
    return r.ec;
}

template <typename T> bool parseInteger(const std::string& token, T& value, std::string& why)
{
    long long v = 0;
    const char* begin = token.data() + (token.size() > 1 && token[0] == '+' ? 1 : 0);
    const char* end = token.data() + token.size();
    const std::from_chars_result r = std::from_chars(begin, end, v);
    if (r.ec == std::errc::result_out_of_range) {
        why = "is out of range";
        return false;
    }
    if (r.ec != std::errc() || r.ptr != end || begin == end) {
        double d = 0.0;
        why = parseWhole(token, d) == std::errc::invalid_argument ? "is not a number" : "is not a whole number";
        return false;
    }
    if (std::is_unsigned<T>::value && v < 0) {
        why = "is negative";
        return false;
    }
    if (v < (long long)std::numeric_limits<T>::min() || v > (long long)std::numeric_limits<T>::max()) {
        why = "is out of range";
        return false;
    }
    value = T(v);
    return true;
}

template <typename V> bool readComponents(osgDB::InputStream& is, V& value, std::string& why)
{
    bool ok = true;
    for (int i = 0; i < V::num_components; ++i) {
        std::string token, whyNot;
        is >> token;
        float c = 0.0f;
        if (parseToken(token, c, whyNot))
            value[i] = c;
        else if (ok) {
            why = "\"" + token + "\" " + whyNot;
            ok = false;
        }
    }
    return ok;
}

}

TextCursor::TextCursor(osgDB::InputStream& is) : _is(is), _text(nullptr)
{
    if (is.isBinary()) return;
    osgDB::InputIterator* it = InputStreamInternals::iterator(is);
    if (!isPlainText(it) || !it->getStream()) return;
    _text = it->getStream();
    if (offset() < 0) _text = nullptr;
}

std::string TextCursor::next()
{
    std::string token;
    if (_text->eof()) return token;
    _is >> token;
    return token;
}

bool TextCursor::putBack(const std::string& token)
{
    // the token was the last thing read from the text (osgDB reads ahead one token at most, and
    // next() took it), so it ends where the text stands
    std::streambuf* buf = _text->rdbuf();
    _text->clear(_text->rdstate() & ~std::ios::eofbit);
    const std::streamoff at = offset() - std::streamoff(token.size());
    if (at < 0 || buf->pubseekpos(at, std::ios::in) == std::streampos(-1)) return false;
    std::string there(token.size(), '\0');
    const bool same = buf->sgetn(&there[0], std::streamsize(there.size())) == std::streamsize(there.size()) && there == token;
    buf->pubseekpos(at, std::ios::in);
    return same;
}

void TextCursor::skipField()
{
    std::string rest;
    std::getline(*_text, rest);
    _text->clear(_text->rdstate() & ~std::ios::failbit); // a last line with no newline
    int open = 0;
    std::istringstream tokens(rest);
    for (std::string t; tokens >> t;) open += t == "{" ? 1 : t == "}" ? -1 : 0;
    for (; open > 0 && !_text->eof(); --open) _is.advanceToCurrentEndBracket();
}

std::streamoff TextCursor::offset() const
{
    return std::streamoff(_text->rdbuf()->pubseekoff(0, std::ios::cur, std::ios::in));
}

int TextCursor::lineAt(std::streamoff at) const
{
    const std::streamoff here = offset();
    std::streambuf* buf = _text->rdbuf();
    if (at < 0 || here < 0 || buf->pubseekpos(0, std::ios::in) == std::streampos(-1)) return 0;
    int line = 1;
    for (std::streamoff i = 0; i < at; ++i) {
        const int c = buf->sbumpc();
        if (c == std::char_traits<char>::eof()) break;
        line += c == '\n';
    }
    buf->pubseekpos(here, std::ios::in);
    return line;
}

void reportField(osgDB::InputStream& is, const osg::Object& object, const std::string& field, const std::string& what,
                 std::streamoff at)
{
    const TextCursor text(is);
    const int line = text.valid() ? text.lineAt(at < 0 ? text.offset() : at) : 0;
    OSG_WARN << "osgWater: " << (line > 0 ? "line " + std::to_string(line) + ": " : std::string())
             << object.libraryName() << "::" << object.className() << " " << field << ": " << what << std::endl;
}

bool parseToken(const std::string& token, double& value, std::string& why)
{
    double v = 0.0;
    const std::errc parsed = parseWhole(token, v);
    if (parsed != std::errc()) {
        why = parsed == std::errc::result_out_of_range ? "is out of range" : "is not a number";
        return false;
    }
    if (!std::isfinite(v)) {
        why = "is not a finite number";
        return false;
    }
    value = v;
    return true;
}

bool parseToken(const std::string& token, float& value, std::string& why)
{
    double v = 0.0;
    if (!parseToken(token, v, why)) return false;
    if (std::fabs(v) > std::numeric_limits<float>::max()) {
        why = "is out of range";
        return false;
    }
    // read as osgDB reads floats, which is what the writer's digits are chosen for (FieldSerializers.h)
    value = float(osg::asciiToDouble(token.c_str()));
    return true;
}

bool parseToken(const std::string& token, int& value, std::string& why) { return parseInteger(token, value, why); }
bool parseToken(const std::string& token, unsigned int& value, std::string& why) { return parseInteger(token, value, why); }

bool parseToken(const std::string& token, bool& value, std::string& why)
{
    if (token != "TRUE" && token != "FALSE") {
        why = "is not TRUE or FALSE";
        return false;
    }
    value = token == "TRUE";
    return true;
}

bool readValue(osgDB::InputStream& is, osg::Vec2f& value, std::string& why) { return readComponents(is, value, why); }
bool readValue(osgDB::InputStream& is, osg::Vec3f& value, std::string& why) { return readComponents(is, value, why); }

std::string describe(double v)
{
    char text[32];
    std::snprintf(text, sizeof(text), "%g", v);
    return text;
}
std::string describe(const osg::Vec2f& v) { return describe(v.x()) + " " + describe(v.y()); }
std::string describe(const osg::Vec3f& v) { return describe(v.x()) + " " + describe(v.y()) + " " + describe(v.z()); }
std::string describe(int v) { return std::to_string(v); }
std::string describe(unsigned int v) { return std::to_string(v); }
std::string describe(bool v) { return v ? "TRUE" : "FALSE"; }

}
}
