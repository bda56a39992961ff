// Private to the library's osgDB wrappers: the typed fields of every osgWater class.
//
// Writing: OSG writes .osgt numbers at the stream's precision, six digits: a lake level of
// 1234.5678 m came back as 1234.57, and a value within a millionth of its default was written, read
// back as the default and then left out. These write each number with the fewest digits that read
// back to the same bits. Binary is exact already and untouched.
//
// Reading text: each value is parsed whole as its type (TextReading.h) and given to the class's
// clamping setter; one that does not parse (not a number, "inf", "-5" for a count, "1e9" for a
// count, an enum name the class lacks) is reported with its field, line and the valid names, and the
// field keeps the value it had. Doubles are parsed exactly (std::from_chars): OSG's own parser misses
// the last bit of ~60% of doubles, though never of a float.
#pragma once
#include "serialize/TextReading.h"
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
inline int digitsFor(const osg::Vec2f& v) { return std::max(digitsFor(v.x()), digitsFor(v.y())); }
inline int digitsFor(const osg::Vec3f& v) { return std::max(digitsFor(v.x()), std::max(digitsFor(v.y()), digitsFor(v.z()))); }

// stream manipulators OutputStream passes to a text stream (and ignores in binary): the first sets
// the precision and keeps the old one in the stream itself, the second restores it
typedef std::ostream& (*Manipulator)(std::ostream&);
Manipulator setPrecision(int digits);
std::ostream& restorePrecision(std::ostream& s);

template <typename P> constexpr bool kHasDigits =
    std::is_floating_point<P>::value || std::is_same<P, osg::Vec2f>::value || std::is_same<P, osg::Vec3f>::value;

//! A number, vector, count or switch of class C, read through its setter.
template <typename C, typename P, template <typename, typename> class Base>
class Field : public Base<C, P> {
public:
    using Base<C, P>::Base;
    bool read(osgDB::InputStream& is, osg::Object& obj) override
    {
        if (is.isBinary()) return Base<C, P>::read(is, obj);
        if (!is.matchString(this->_name)) return true;
        const Base<C, P>& base = *this; // GCC 12's UBSan misreads a dependent base's member as at 0
        C& object = static_cast<C&>(obj);
        P value = (object.*(base._getter))();
        std::string why;
        if (readValue(is, value, why))
            (object.*(base._setter))(value);
        else
            reportField(is, obj, this->_name, why + "; keeping " + describe((object.*(base._getter))()));
        return true;
    }
    bool write(osgDB::OutputStream& os, const osg::Object& obj) override
    {
        if constexpr (!kHasDigits<P>) {
            return Base<C, P>::write(os, obj);
        } else {
            if (os.isBinary()) return Base<C, P>::write(os, obj);
            const Base<C, P>& base = *this;
            const C& object = static_cast<const C&>(obj);
            const P value = (object.*(base._getter))();
            if (value == this->_defaultValue) return true; // text files leave defaults out, as OSG's own do
            // the manipulators mid-line: at the start of a line OSG would indent for them
            os << os.PROPERTY(this->_name.c_str()) << setPrecision(digitsFor(value)) << value << restorePrecision
               << std::endl;
            return true;
        }
    }
};

//! An enum of class C: an unknown name is reported with the names there are, never read as 0.
template <typename C, typename P>
class EnumField : public osgDB::EnumSerializer<C, P, void> {
    typedef osgDB::EnumSerializer<C, P, void> Base;

public:
    using Base::Base;
    bool read(osgDB::InputStream& is, osg::Object& obj) override
    {
        if (is.isBinary()) return Base::read(is, obj);
        if (!is.matchString(this->_name)) return true;
        std::string name;
        is >> name;
        C& object = static_cast<C&>(obj);
        const osgDB::IntLookup::StringToValue& known = this->_lookup.getStringToValue();
        const osgDB::IntLookup::StringToValue::const_iterator found = known.find(name);
        if (found != known.end()) {
            (object.*(this->_setter))(static_cast<P>(found->second));
            return true;
        }
        std::string names;
        for (const auto& value : this->_lookup.getValueToString()) names += (names.empty() ? "" : "|") + value.second;
        reportField(is, obj, this->_name, "\"" + name + "\" is not one of " + names + "; keeping " +
                                              this->getString((object.*(this->_getter))()));
        return true;
    }
};

}
}

#define ADD_FIELD_SERIALIZER(PROP, TYPE, BASE, DEF, RW)                                                   \
    wrapper->addSerializer(new osgWater::detail::Field<MyClass, TYPE, BASE>(#PROP, DEF, &MyClass::get##PROP, \
                                                                            &MyClass::set##PROP),        \
                           osgDB::BaseSerializer::RW)
#define ADD_FLOAT_FIELD(PROP, DEF) ADD_FIELD_SERIALIZER(PROP, float, osgDB::PropByValSerializer, DEF, RW_FLOAT)
#define ADD_DOUBLE_FIELD(PROP, DEF) ADD_FIELD_SERIALIZER(PROP, double, osgDB::PropByValSerializer, DEF, RW_DOUBLE)
#define ADD_VEC2F_FIELD(PROP, DEF) ADD_FIELD_SERIALIZER(PROP, osg::Vec2f, osgDB::PropByRefSerializer, DEF, RW_VEC2F)
#define ADD_VEC3F_FIELD(PROP, DEF) ADD_FIELD_SERIALIZER(PROP, osg::Vec3f, osgDB::PropByRefSerializer, DEF, RW_VEC3F)
#define ADD_INT_FIELD(PROP, DEF) ADD_FIELD_SERIALIZER(PROP, int, osgDB::PropByValSerializer, DEF, RW_INT)
#define ADD_UINT_FIELD(PROP, DEF) ADD_FIELD_SERIALIZER(PROP, unsigned int, osgDB::PropByValSerializer, DEF, RW_UINT)
#define ADD_BOOL_FIELD(PROP, DEF) ADD_FIELD_SERIALIZER(PROP, bool, osgDB::PropByValSerializer, DEF, RW_BOOL)
// with OSG's ADD_ENUM_VALUE between them
#define BEGIN_ENUM_FIELD(PROP, DEF)                                                                         \
    {                                                                                                       \
        typedef osgWater::detail::EnumField<MyClass, MyClass::PROP> MySerializer;                           \
        osg::ref_ptr<MySerializer> serializer =                                                             \
            new MySerializer(#PROP, MyClass::DEF, &MyClass::get##PROP, &MyClass::set##PROP)
#define END_ENUM_FIELD() END_ENUM_SERIALIZER()
