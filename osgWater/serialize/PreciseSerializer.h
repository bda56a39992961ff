// Private to the library's osgDB wrappers. OSG writes .osgt numbers at the stream's precision, six
// digits: a lake level of 1234.5678 m came back as 1234.57, and a value within a millionth of its
// default was written, read back as the default and then left out. These serializers write each
// value with the fewest digits that read back to the same bits, and read doubles with an exact parser:
// OSG's own (osg::asciiToDouble) misses the last bit of ~60% of doubles, though never of a float.
// Binary is exact already and untouched.
#pragma once
#include <osgDB/Serializer>
#include <osgDB/OutputStream>
#include <osgDB/InputStream>
#include <osg/Vec2f>
#include <osg/Vec3f>
#include <algorithm>
#include <ostream>
#include <string>
#include <type_traits>

namespace osgWater {
namespace detail {

int digitsFor(float v);  // 6..9
int digitsFor(double v); // 6..17
double parseDouble(const std::string& text); // exact (std::from_chars), else OSG's parser
inline int digitsFor(const osg::Vec2f& v) { return std::max(digitsFor(v.x()), digitsFor(v.y())); }
inline int digitsFor(const osg::Vec3f& v) { return std::max(digitsFor(v.x()), std::max(digitsFor(v.y()), digitsFor(v.z()))); }

// stream manipulators OutputStream passes to a text stream (and ignores in binary): the first sets
// the precision and keeps the old one in the stream itself, the second restores it
typedef std::ostream& (*Manipulator)(std::ostream&);
Manipulator setPrecision(int digits);
std::ostream& restorePrecision(std::ostream& s);

template <typename C, typename P, template <typename, typename> class Base>
class Precise : public Base<C, P> {
public:
    using Base<C, P>::Base;
    bool read(osgDB::InputStream& is, osg::Object& obj) override
    {
        if constexpr (std::is_same<P, double>::value) {
            if (!is.isBinary()) {
                if (is.matchString(this->_name)) {
                    std::string text;
                    is >> text;
                    const Base<C, P>& base = *this;
                    C& object = static_cast<C&>(obj);
                    (object.*(base._setter))(parseDouble(text));
                }
                return true;
            }
        }
        return Base<C, P>::read(is, obj);
    }
    bool write(osgDB::OutputStream& os, const osg::Object& obj) override
    {
        if (os.isBinary()) return Base<C, P>::write(os, obj);
        const Base<C, P>& base = *this; // GCC 12's UBSan misreads a dependent base's member as at 0
        const C& object = static_cast<const C&>(obj);
        const P value = (object.*(base._getter))();
        if (value == this->_defaultValue) return true; // text files leave defaults out, as OSG's own do
        // the manipulators mid-line: at the start of a line OSG would indent for them
        os << os.PROPERTY(this->_name.c_str()) << setPrecision(digitsFor(value)) << value << restorePrecision
           << std::endl;
        return true;
    }
};

}
}

#define ADD_PRECISE_SERIALIZER(PROP, TYPE, BASE, DEF, RW)                                                  \
    wrapper->addSerializer(new osgWater::detail::Precise<MyClass, TYPE, BASE>(#PROP, DEF, &MyClass::get##PROP, \
                                                                              &MyClass::set##PROP),        \
                           osgDB::BaseSerializer::RW)
#define ADD_PRECISE_FLOAT_SERIALIZER(PROP, DEF) ADD_PRECISE_SERIALIZER(PROP, float, osgDB::PropByValSerializer, DEF, RW_FLOAT)
#define ADD_PRECISE_DOUBLE_SERIALIZER(PROP, DEF) ADD_PRECISE_SERIALIZER(PROP, double, osgDB::PropByValSerializer, DEF, RW_DOUBLE)
#define ADD_PRECISE_VEC2F_SERIALIZER(PROP, DEF) ADD_PRECISE_SERIALIZER(PROP, osg::Vec2f, osgDB::PropByRefSerializer, DEF, RW_VEC2F)
#define ADD_PRECISE_VEC3F_SERIALIZER(PROP, DEF) ADD_PRECISE_SERIALIZER(PROP, osg::Vec3f, osgDB::PropByRefSerializer, DEF, RW_VEC3F)
