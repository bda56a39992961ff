// Private to the library's osgDB wrappers: strict reading of .osgt text. osgDB's text reader turns
// what does not parse into 0 ("inf", "x"), wraps "-5" in an unsigned field, reads "1e9" as 1 and
// an unknown enum name as the first value, all without a word; and it matches fields in the
// wrapper's order, so one unknown or misplaced field made it drop every later field of the object.
// Here a value is parsed whole or reported by field name and line and left as it was, and the
// fields osgDB did not take in order are read by name afterwards (OtherFields.h).
#pragma once
#include <osgDB/InputStream>
#include <osg/Vec2f>
#include <osg/Vec3f>
#include <istream>
#include <string>
#include <vector>

namespace osgWater {
namespace detail {

//! The .osgt text under an InputStream, for what osgDB's reader cannot do: look at a token and put
//! it back, skip a field to its end, say which line a value is on. Invalid (and unused) for binary
//! files, the XML format and streams that cannot seek.
class TextCursor {
public:
    explicit TextCursor(osgDB::InputStream& is);
    bool valid() const { return _text != nullptr; }

    //! The next token, through osgDB's reader (it may hold one token read ahead); empty at the end.
    std::string next();
    //! Puts back the token next() just gave, so osgDB's reader reads it again.
    bool putBack(const std::string& token);
    //! Skips the rest of the field whose name next() just gave: its line, and any block it opens.
    void skipField();
    //! Where the text is now (bytes from the start; -1 when unknown), and the line of an offset
    //! (1-based; 0 when unknown).
    std::streamoff offset() const;
    int lineAt(std::streamoff offset) const;

private:
    osgDB::InputStream& _is;
    std::istream* _text;
};

//! "osgWater: line 12: osgWater::WaterSettings Attenuation: <what>", as a warning; the line is the
//! text's where it stands, or at the offset given.
void reportField(osgDB::InputStream& is, const osg::Object& object, const std::string& field, const std::string& what,
                 std::streamoff at = -1);

//! A token parsed whole as its type, or false with why ("is not a number", "is negative", ...).
//! Numbers must be finite: "inf" and "nan" are refused as the writer never writes them.
bool parseToken(const std::string& token, double& value, std::string& why);
bool parseToken(const std::string& token, float& value, std::string& why);
bool parseToken(const std::string& token, int& value, std::string& why);
bool parseToken(const std::string& token, unsigned int& value, std::string& why);
bool parseToken(const std::string& token, bool& value, std::string& why);

//! Reads a value of the type's tokens (one, or one per component) and parses them; on the first
//! that does not parse, the rest are still read and why says which and how.
template <typename T> bool readValue(osgDB::InputStream& is, T& value, std::string& why)
{
    std::string token;
    is >> token;
    if (parseToken(token, value, why)) return true;
    why = "\"" + token + "\" " + why;
    return false;
}
bool readValue(osgDB::InputStream& is, osg::Vec2f& value, std::string& why);
bool readValue(osgDB::InputStream& is, osg::Vec3f& value, std::string& why);

//! A value as the text writes it, for messages ("keeping 0.5").
std::string describe(double v);
std::string describe(const osg::Vec2f& v);
std::string describe(const osg::Vec3f& v);
std::string describe(int v);
std::string describe(unsigned int v);
std::string describe(bool v);

}
}
