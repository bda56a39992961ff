// osgDB wrappers for WaterNode, WaterSettings and WaterSurface, registered when the library loads.
// osgDB finds them for a class "osgWater::X" by loading the node kit library libosgWater (from
// OSG_LIBRARY_PATH or the system library path), so stock osgviewer / osgconv read .osgt/.osgb.
// Reading goes through the clamping setters: bad values are clamped with a warning. Text files
// carry only the values that differ from the defaults, so missing fields take defaults; numbers are
// written with the digits they need to read back exactly (PreciseSerializer.h).
#include <osgWater/WaterSettings>
#include "serialize/PreciseSerializer.h"
#include "serialize/LayoutVersion.h"
#include <osgDB/ObjectWrapper>
#include <osgDB/InputStream>
#include <osgDB/OutputStream>
#include <osgDB/Registry>

using namespace osgWater;

// The quality preset, when the speed settings are one other than the default (BALANCED): written
// first, so the settings after it in the file (any written) come on top of its bundle.
static bool checkQuality(const WaterSettings& s)
{
    return s.getQuality() == WaterSettings::QUALITY_FAST || s.getQuality() == WaterSettings::QUALITY_EXACT;
}

static bool readQuality(osgDB::InputStream& is, WaterSettings& s)
{
    std::string name;
    is >> name;
    WaterSettings::Quality q;
    if (WaterSettings::qualityFromName(name, q))
        s.setQuality(q);
    else
        OSG_WARN << "osgWater::WaterSettings: unknown Quality \"" << name << "\" (not one of "
                 << WaterSettings::qualityNames() << "), keeping the settings as they are" << std::endl;
    return true;
}

static bool writeQuality(osgDB::OutputStream& os, const WaterSettings& s)
{
    os << std::string(WaterSettings::qualityName(s.getQuality())) << std::endl;
    return true;
}

REGISTER_OBJECT_WRAPPER(osgWater_WaterSettings, new osgWater::WaterSettings, osgWater::WaterSettings,
                        "osg::Object osgWater::WaterSettings")
{
    ADD_BINARY_LAYOUT_SERIALIZER("osgWater::WaterSettings");
    ADD_USER_SERIALIZER(Quality);
    ADD_PRECISE_FLOAT_SERIALIZER(AirIOR, 1.0f);
    ADD_PRECISE_FLOAT_SERIALIZER(WaterIOR, 1.333f);
    ADD_PRECISE_VEC3F_SERIALIZER(WaterColor, osg::Vec3f(0.0f, 0.2f, 0.1f));
    ADD_PRECISE_FLOAT_SERIALIZER(Attenuation, 0.5f);
    BEGIN_ENUM_SERIALIZER(WaterModel, WATER_THESIS);
        ADD_ENUM_VALUE(WATER_THESIS);
        ADD_ENUM_VALUE(WATER_PER_CHANNEL);
    END_ENUM_SERIALIZER();
    ADD_PRECISE_VEC3F_SERIALIZER(Absorption, osgWater::WaterSettings::defaultAbsorption());
    ADD_PRECISE_VEC3F_SERIALIZER(Scattering, osgWater::WaterSettings::defaultScattering());
    ADD_PRECISE_VEC3F_SERIALIZER(Backscattering, osgWater::WaterSettings::defaultBackscattering());
    BEGIN_ENUM_SERIALIZER(FresnelModel, FRESNEL_SCHLICK);
        ADD_ENUM_VALUE(FRESNEL_SCHLICK);
        ADD_ENUM_VALUE(FRESNEL_POWER);
        ADD_ENUM_VALUE(FRESNEL_EXACT);
        ADD_ENUM_VALUE(FRESNEL_RECIPROCAL);
    END_ENUM_SERIALIZER();
    ADD_PRECISE_FLOAT_SERIALIZER(FresnelExponent, 5.0f);
    ADD_PRECISE_FLOAT_SERIALIZER(FresnelReciprocalPower, 6.62f);
    ADD_PRECISE_FLOAT_SERIALIZER(ReflectionScale, 1.0f);
    BEGIN_ENUM_SERIALIZER(ReflectionLookup, REFLECTION_SEARCH);
        ADD_ENUM_VALUE(REFLECTION_OFFSET);
        ADD_ENUM_VALUE(REFLECTION_PLANE);
        ADD_ENUM_VALUE(REFLECTION_SEARCH);
    END_ENUM_SERIALIZER();
    ADD_PRECISE_FLOAT_SERIALIZER(ReflectionPlaneHeight, 0.0f);
    BEGIN_ENUM_SERIALIZER(RefractionLookup, ITERATIVE);
        ADD_ENUM_VALUE(ONE_STEP);
        ADD_ENUM_VALUE(ITERATIVE);
        ADD_ENUM_VALUE(PLANE_OFFSET);
        ADD_ENUM_VALUE(BRACKETED);
        ADD_ENUM_VALUE(VIRTUAL_VERTICES);
    END_ENUM_SERIALIZER();
    ADD_PRECISE_FLOAT_SERIALIZER(RefractionPlaneDepth, 0.0f);
    ADD_INT_SERIALIZER(SearchSteps, 3);
    ADD_PRECISE_FLOAT_SERIALIZER(SearchTolerance, 0.01f);
    ADD_PRECISE_FLOAT_SERIALIZER(OneStepScale, 1.0f);
    ADD_PRECISE_FLOAT_SERIALIZER(OneStepMaxDepth, 20.0f);
    ADD_PRECISE_FLOAT_SERIALIZER(UnderwaterLookupScale, 1.5f);
    ADD_PRECISE_FLOAT_SERIALIZER(FovExtensionNear, 1.5f);
    ADD_PRECISE_FLOAT_SERIALIZER(FovExtensionFar, 1.2f);
    ADD_PRECISE_FLOAT_SERIALIZER(FovExtensionFalloff, 10.0f);
    ADD_PRECISE_FLOAT_SERIALIZER(ClipOffset, 0.05f);
    ADD_INT_SERIALIZER(ReflectionTextureSize, 512);
    ADD_INT_SERIALIZER(RefractionTextureSize, 512);
    ADD_PRECISE_FLOAT_SERIALIZER(PassTargetScale, 0.0f);
    ADD_BOOL_SERIALIZER(RefractionCameraRotation, true);
    ADD_BOOL_SERIALIZER(RefractionCameraApparentEye, true);
    ADD_BOOL_SERIALIZER(ReflectionEnabled, true);
    ADD_BOOL_SERIALIZER(RefractionEnabled, true);
    ADD_BOOL_SERIALIZER(CausticsEnabled, true);
    ADD_INT_SERIALIZER(CausticsResolution, 256);
    ADD_INT_SERIALIZER(PhotonGridSize, 512);
    ADD_PRECISE_FLOAT_SERIALIZER(CausticsIntensity, 1.0f);
    ADD_BOOL_SERIALIZER(CausticsFiltering, true);
    ADD_BOOL_SERIALIZER(CausticsFocused, true);
    BEGIN_ENUM_SERIALIZER(CausticsGather, GATHER_AUTO);
        ADD_ENUM_VALUE(GATHER_AUTO);
        ADD_ENUM_VALUE(GATHER_POINTS_COPY);
        ADD_ENUM_VALUE(GATHER_POINTS_TEXTURE);
        ADD_ENUM_VALUE(GATHER_CPU);
    END_ENUM_SERIALIZER();
    BEGIN_ENUM_SERIALIZER(CausticsMethod, CAUSTICS_PHOTONS);
        ADD_ENUM_VALUE(CAUSTICS_PHOTONS);
        ADD_ENUM_VALUE(CAUSTICS_AREA_MESH);
        ADD_ENUM_VALUE(CAUSTICS_PROCEDURAL);
        ADD_ENUM_VALUE(CAUSTICS_PROCEDURAL_SCREEN);
    END_ENUM_SERIALIZER();
    ADD_BOOL_SERIALIZER(CausticsSupersampling, false);
    ADD_BOOL_SERIALIZER(ReflectiveCaustics, false);
    ADD_PRECISE_FLOAT_SERIALIZER(CausticsTileSize, 0.0f);
    ADD_BOOL_SERIALIZER(EnvironmentMapEnabled, false);
    ADD_INT_SERIALIZER(EnvironmentMapSize, 256);
    ADD_PRECISE_FLOAT_SERIALIZER(CausticsMotionTolerance, 0.5f);
    BEGIN_ENUM_SERIALIZER(UnderwaterModel, UNDERWATER_PHYSICAL);
        ADD_ENUM_VALUE(UNDERWATER_PHYSICAL);
        ADD_ENUM_VALUE(UNDERWATER_THESIS);
    END_ENUM_SERIALIZER();
    ADD_BOOL_SERIALIZER(GlowEnabled, true);
    ADD_PRECISE_FLOAT_SERIALIZER(GlowIntensity, 1.0f);
    ADD_PRECISE_FLOAT_SERIALIZER(GlowRadius, 3.0f);
    ADD_PRECISE_FLOAT_SERIALIZER(GlowResolution, 0.25f);
    ADD_PRECISE_FLOAT_SERIALIZER(GlowExponent, 200.0f);
    ADD_PRECISE_VEC3F_SERIALIZER(SunDirection, osgWater::WaterSettings::defaultSunDirection());
    ADD_PRECISE_VEC3F_SERIALIZER(SunColor, osg::Vec3f(1.0f, 1.0f, 0.9f));
    ADD_PRECISE_VEC3F_SERIALIZER(AmbientColor, osg::Vec3f(0.35f, 0.38f, 0.45f));
    ADD_PRECISE_FLOAT_SERIALIZER(Exposure, 1.0f);
}

