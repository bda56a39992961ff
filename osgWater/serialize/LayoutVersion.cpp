#include "serialize/LayoutVersion.h"
#include <osgDB/InputStream>
#include <osgDB/OutputStream>
#include <osg/Notify>

namespace osgWater {
namespace detail {

namespace {
// the stamp: a mark no older file has where it stands (they start their first field there), and
// the layout's number
constexpr int kMark = 0x6F570000; // "oW" and the number in the low half
}

LayoutVersionSerializer::LayoutVersionSerializer(const char* className)
    : osgDB::BaseSerializer(READ_WRITE_PROPERTY), _name("BinaryLayout"), _className(className)
{
}

bool LayoutVersionSerializer::read(osgDB::InputStream& is, osg::Object&)
{
    if (!is.isBinary()) return true;
    int stamp = 0;
    is >> stamp;
    if (is.getException()) return false;
    if (stamp == (kMark | kBinaryLayout)) return true;
    const bool stamped = (stamp & 0xFFFF0000) == kMark;
    const std::string message =
        "osgWater: this .osgb's " + _className + " was written " +
        (stamped ? "in binary layout " + std::to_string(stamp & 0xFFFF) : std::string("before binary layouts were numbered")) +
        ", and this osgWater reads layout " + std::to_string(kBinaryLayout) +
        " only (binary fields are positional: read, it would be shifted). Write the .osgb again from its .osgt "
        "(osgconv scene.osgt scene.osgb)";
    OSG_WARN << message << std::endl;
    is.throwException(message);
    return false;
}

bool LayoutVersionSerializer::write(osgDB::OutputStream& os, const osg::Object&)
{
    if (os.isBinary()) os << int(kMark | kBinaryLayout);
    return true;
}

}
}
