// osgDB wrapper of WaterNode (see WaterSettingsSerializer.cpp for how osgDB finds it).
#include <osgWater/WaterNode>
#include "serialize/LayoutVersion.h"
#include "serialize/OtherFields.h"
#include <osgDB/ObjectWrapper>
#include <osgDB/InputStream>
#include <osgDB/OutputStream>
#include <osgDB/Registry>

using namespace osgWater;

REGISTER_OBJECT_WRAPPER(osgWater_WaterNode, new osgWater::WaterNode, osgWater::WaterNode,
                        "osg::Object osg::Node osg::Group osgWater::WaterNode")
{
    ADD_BINARY_LAYOUT_SERIALIZER("osgWater::WaterNode");
    ADD_OBJECT_SERIALIZER(Settings, osgWater::WaterSettings, NULL);
    ADD_OBJECT_SERIALIZER(Surface, osgWater::WaterSurface, NULL);
    ADD_OTHER_FIELDS_SERIALIZER("osgWater::WaterNode");
}
