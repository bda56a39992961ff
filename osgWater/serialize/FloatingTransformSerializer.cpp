// osgDB wrapper of FloatingTransform (see WaterSettingsSerializer.cpp for how osgDB finds it).
#include <osgWater/FloatingTransform>
#include "serialize/PreciseSerializer.h"
#include "serialize/LayoutVersion.h"
#include <osgDB/ObjectWrapper>
#include <osgDB/InputStream>
#include <osgDB/OutputStream>
#include <osgDB/Registry>

using namespace osgWater;

REGISTER_OBJECT_WRAPPER(osgWater_FloatingTransform, new osgWater::FloatingTransform, osgWater::FloatingTransform,
                        "osg::Object osg::Node osg::Group osg::Transform osg::MatrixTransform osgWater::FloatingTransform")
{
    ADD_BINARY_LAYOUT_SERIALIZER("osgWater::FloatingTransform");
    ADD_PRECISE_DOUBLE_SERIALIZER(PositionX, 0.0);
    ADD_PRECISE_DOUBLE_SERIALIZER(PositionY, 0.0);
    ADD_PRECISE_DOUBLE_SERIALIZER(Heading, 0.0);
    ADD_PRECISE_DOUBLE_SERIALIZER(Draft, 0.0);
    ADD_PRECISE_DOUBLE_SERIALIZER(Damping, 0.0);
    ADD_BOOL_SERIALIZER(Tilt, true);
}
