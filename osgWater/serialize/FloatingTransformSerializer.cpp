// osgDB wrapper of FloatingTransform (see WaterSettingsSerializer.cpp for how osgDB finds it).
#include <osgWater/FloatingTransform>
#include "serialize/FieldSerializers.h"
#include "serialize/LayoutVersion.h"
#include "serialize/OtherFields.h"
#include <osgDB/ObjectWrapper>
#include <osgDB/InputStream>
#include <osgDB/OutputStream>
#include <osgDB/Registry>

using namespace osgWater;

REGISTER_OBJECT_WRAPPER(osgWater_FloatingTransform, new osgWater::FloatingTransform, osgWater::FloatingTransform,
                        "osg::Object osg::Node osg::Group osg::Transform osg::MatrixTransform osgWater::FloatingTransform")
{
    ADD_BINARY_LAYOUT_SERIALIZER("osgWater::FloatingTransform");
    ADD_DOUBLE_FIELD(PositionX, 0.0);
    ADD_DOUBLE_FIELD(PositionY, 0.0);
    ADD_DOUBLE_FIELD(Heading, 0.0);
    ADD_DOUBLE_FIELD(Draft, 0.0);
    ADD_DOUBLE_FIELD(Damping, 0.0);
    ADD_BOOL_FIELD(Tilt, true);
    ADD_OTHER_FIELDS_SERIALIZER("osgWater::FloatingTransform");
}
