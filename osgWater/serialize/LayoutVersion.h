// Private to the library's osgDB wrappers. Binary files name no fields: a field added to a wrapper
// shifts every later one, and a file of another layout would read as garbage (clamped with
// warnings). So each osgWater object in a .osgb starts with the kit's binary layout number, and an
// object of another layout is refused, with a message that says what to do, and never read
// shifted. Text files name their fields and carry no number.
#pragma once
#include <osgDB/Serializer>

namespace osgWater {
namespace detail {

//! The binary layout of every osgWater wrapper together: raised whenever a wrapper's binary fields
//! change (Serialization.TheBinarySeedsReadAsTheirTextTwins fails until it is, and the seeds are
//! written again).
constexpr int kBinaryLayout = 4; // 2: the wind's choppiness; 3: the tone curve; 4: the error budget

class LayoutVersionSerializer : public osgDB::BaseSerializer
{
public:
    explicit LayoutVersionSerializer(const char* className);
    bool read(osgDB::InputStream& is, osg::Object& obj) override;
    bool write(osgDB::OutputStream& os, const osg::Object& obj) override;
    const std::string& getName() const override { return _name; }

private:
    std::string _name, _className;
};

}
}

//! The first serializer of each osgWater wrapper.
#define ADD_BINARY_LAYOUT_SERIALIZER(CLASS_NAME) \
    wrapper->addSerializer(new osgWater::detail::LayoutVersionSerializer(CLASS_NAME), osgDB::BaseSerializer::RW_INT)
