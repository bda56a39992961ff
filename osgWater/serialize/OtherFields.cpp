#include "serialize/OtherFields.h"
#include "serialize/LayoutVersion.h"
#include "serialize/TextReading.h"
#include <osgDB/InputStream>
#include <osgDB/ObjectWrapper>
#include <osgDB/Registry>

namespace osgWater {
namespace detail {

OtherFields::OtherFields(const char* className)
    : osgDB::BaseSerializer(READ_WRITE_PROPERTY), _name("OtherFields"), _className(className)
{
}

osgDB::BaseSerializer* OtherFields::fieldNamed(const std::string& name) const
{
    osgDB::ObjectWrapperManager* wrappers = osgDB::Registry::instance()->getObjectWrapperManager();
    osgDB::ObjectWrapper* wrapper = wrappers->findWrapper(_className);
    if (!wrapper) return nullptr;
    for (const osgDB::ObjectWrapperAssociate& associate : wrapper->getAssociates()) {
        osgDB::ObjectWrapper* own = wrappers->findWrapper(associate._name);
        if (!own) continue;
        for (const osg::ref_ptr<osgDB::BaseSerializer>& field : own->getSerializerList())
            if (field->getName() == name && !dynamic_cast<OtherFields*>(field.get())
                && !dynamic_cast<LayoutVersionSerializer*>(field.get()))
                return field.get();
    }
    return nullptr;
}

bool OtherFields::read(osgDB::InputStream& is, osg::Object& obj)
{
    TextCursor text(is);
    if (!text.valid()) return true; // binary files have no names, and all their fields were read
    for (;;) {
        const std::string name = text.next();
        if (name.empty() || is.getException()) return true; // the text ended: osgDB says it is cut short
        if (name == "}") { // the object's end, which osgDB reads
            text.putBack(name);
            return true;
        }
        osgDB::BaseSerializer* field = fieldNamed(name);
        if (field && text.putBack(name)) {
            const std::streamoff start = text.offset();
            field->read(is, obj);
            if (is.getException()) return false;
            if (text.offset() > start + std::streamoff(name.size())) continue; // it took its name and value
            text.next(); // it left its name, read ahead: take it, and skip the field below
        }
        reportField(is, obj, name, field ? "could not be read here; skipped to its end"
                                         : "is not a field of this class; skipped to its end, the fields after it are read");
        text.skipField();
    }
}

}
}
