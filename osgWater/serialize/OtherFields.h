// Private to the library's osgDB wrappers. osgDB reads a text object's fields in its wrapper's
// order, each taken only if it is the next name in the file: one unknown or misplaced field left
// every later one unread, and osgDB then skipped them all to the object's end without a word. The
// last serializer of each osgWater wrapper reads what is left by name, in any order, and reports
// each unknown field (by name, class and line) and skips it to its end, so nothing after it is lost.
#pragma once
#include <osgDB/Serializer>
#include <string>

namespace osgWater {
namespace detail {

class OtherFields : public osgDB::BaseSerializer
{
public:
    explicit OtherFields(const char* className);
    bool read(osgDB::InputStream& is, osg::Object& obj) override;
    bool write(osgDB::OutputStream&, const osg::Object&) override { return true; }
    const std::string& getName() const override { return _name; }

private:
    //! The serializer of that name in the class's wrapper or the wrappers it builds on; none for
    //! this one and the binary layout stamp, which a text file never names.
    osgDB::BaseSerializer* fieldNamed(const std::string& name) const;

    std::string _name, _className;
};

}
}

//! The last serializer of each osgWater wrapper.
#define ADD_OTHER_FIELDS_SERIALIZER(CLASS_NAME) \
    wrapper->addSerializer(new osgWater::detail::OtherFields(CLASS_NAME), osgDB::BaseSerializer::RW_USER)
