// osgDB wrapper of Sky (see WaterSettingsSerializer.cpp for how osgDB finds it): its settings, never
// its triangle and state (made by the node).
#include <osgWater/Sky>
#include <osgWater/WaterSettings>
#include "serialize/FieldSerializers.h"
#include "serialize/LayoutVersion.h"
#include "serialize/OtherFields.h"
#include <osgDB/ObjectWrapper>
#include <osgDB/InputStream>
#include <osgDB/OutputStream>
#include <osgDB/Registry>

using namespace osgWater;

REGISTER_OBJECT_WRAPPER(osgWater_Sky, new osgWater::Sky, osgWater::Sky, "osg::Object osg::Node osgWater::Sky")
{
    ADD_BINARY_LAYOUT_SERIALIZER("osgWater::Sky");
    ADD_VEC3F_FIELD(SunDirection, osgWater::WaterSettings::defaultSunDirection());
    ADD_FLOAT_FIELD(Turbidity, 2.5f);
    ADD_FLOAT_FIELD(LuminanceScale, 0.06f);
    ADD_OTHER_FIELDS_SERIALIZER("osgWater::Sky");
}
