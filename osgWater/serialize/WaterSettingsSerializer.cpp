// osgDB wrappers for WaterNode, WaterSettings and WaterSurface, registered when the library loads.
// osgDB finds them for a class "osgWater::X" by loading the node kit library libosgWater (from
// OSG_LIBRARY_PATH or the system library path), so stock osgviewer / osgconv read .osgt/.osgb.
// Reading goes through the clamping setters: bad values are clamped with a warning. Text files
// carry only the values that differ from the defaults, so missing fields take defaults; numbers are
// written with the digits they need to read back exactly, and text that does not parse as its
// field's type is reported and left out (FieldSerializers.h). Fields are read in any order, and
// unknown ones reported and skipped (OtherFields.h).
#include <osgWater/WaterSettings>
#include "serialize/FieldSerializers.h"
#include "serialize/LayoutVersion.h"
#include "serialize/OtherFields.h"
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
        detail::reportField(is, s, "Quality", "\"" + name + "\" is not one of " + WaterSettings::qualityNames() +
                                                  "; keeping the settings as they are");
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
    ADD_FLOAT_FIELD(AirIOR, 1.0f);
    ADD_FLOAT_FIELD(WaterIOR, 1.333f);
    ADD_VEC3F_FIELD(WaterColor, osg::Vec3f(0.0f, 0.2f, 0.1f));
    ADD_FLOAT_FIELD(Attenuation, 0.5f);
    BEGIN_ENUM_FIELD(WaterModel, WATER_THESIS);
        ADD_ENUM_VALUE(WATER_THESIS);
        ADD_ENUM_VALUE(WATER_PER_CHANNEL);
    END_ENUM_FIELD();
    ADD_VEC3F_FIELD(Absorption, osgWater::WaterSettings::defaultAbsorption());
    ADD_VEC3F_FIELD(Scattering, osgWater::WaterSettings::defaultScattering());
    ADD_VEC3F_FIELD(Backscattering, osgWater::WaterSettings::defaultBackscattering());
    BEGIN_ENUM_FIELD(FresnelModel, FRESNEL_EXACT);
        ADD_ENUM_VALUE(FRESNEL_SCHLICK);
        ADD_ENUM_VALUE(FRESNEL_POWER);
        ADD_ENUM_VALUE(FRESNEL_EXACT);
        ADD_ENUM_VALUE(FRESNEL_RECIPROCAL);
    END_ENUM_FIELD();
    ADD_FLOAT_FIELD(FresnelExponent, 5.0f);
    ADD_FLOAT_FIELD(FresnelReciprocalPower, 6.62f);
    ADD_FLOAT_FIELD(ReflectionScale, 1.0f);
    BEGIN_ENUM_FIELD(ReflectionLookup, REFLECTION_SEARCH);
        ADD_ENUM_VALUE(REFLECTION_OFFSET);
        ADD_ENUM_VALUE(REFLECTION_PLANE);
        ADD_ENUM_VALUE(REFLECTION_SEARCH);
    END_ENUM_FIELD();
    ADD_FLOAT_FIELD(ReflectionPlaneHeight, 0.0f);
    BEGIN_ENUM_FIELD(RefractionLookup, ITERATIVE);
        ADD_ENUM_VALUE(ONE_STEP);
        ADD_ENUM_VALUE(ITERATIVE);
        ADD_ENUM_VALUE(PLANE_OFFSET);
        ADD_ENUM_VALUE(BRACKETED);
        ADD_ENUM_VALUE(VIRTUAL_VERTICES);
    END_ENUM_FIELD();
    ADD_FLOAT_FIELD(RefractionPlaneDepth, 0.0f);
    ADD_INT_FIELD(SearchSteps, 3);
    ADD_FLOAT_FIELD(ErrorBudget, 0.25f);
    ADD_FLOAT_FIELD(OneStepScale, 1.0f);
    ADD_FLOAT_FIELD(OneStepMaxDepth, 20.0f);
    ADD_FLOAT_FIELD(UnderwaterLookupScale, 1.5f);
    ADD_FLOAT_FIELD(FovExtensionNear, 1.5f);
    ADD_FLOAT_FIELD(FovExtensionFar, 1.2f);
    ADD_FLOAT_FIELD(FovExtensionFalloff, 10.0f);
    ADD_FLOAT_FIELD(ClipOffset, 0.05f);
    ADD_INT_FIELD(ReflectionTextureSize, 512);
    ADD_INT_FIELD(RefractionTextureSize, 512);
    ADD_FLOAT_FIELD(PassTargetScale, 0.0f);
    ADD_BOOL_FIELD(RefractionCameraRotation, true);
    ADD_BOOL_FIELD(RefractionCameraApparentEye, true);
    ADD_BOOL_FIELD(ReflectionEnabled, true);
    ADD_BOOL_FIELD(RefractionEnabled, true);
    ADD_BOOL_FIELD(CausticsEnabled, true);
    ADD_INT_FIELD(CausticsResolution, 256);
    ADD_INT_FIELD(PhotonGridSize, 512);
    ADD_FLOAT_FIELD(CausticsIntensity, 1.0f);
    ADD_BOOL_FIELD(CausticsFiltering, true);
    ADD_BOOL_FIELD(CausticsFocused, true);
    BEGIN_ENUM_FIELD(CausticsGather, GATHER_AUTO);
        ADD_ENUM_VALUE(GATHER_AUTO);
        ADD_ENUM_VALUE(GATHER_POINTS_COPY);
        ADD_ENUM_VALUE(GATHER_POINTS_TEXTURE);
        ADD_ENUM_VALUE(GATHER_CPU);
    END_ENUM_FIELD();
    BEGIN_ENUM_FIELD(CausticsMethod, CAUSTICS_PHOTONS);
        ADD_ENUM_VALUE(CAUSTICS_PHOTONS);
        ADD_ENUM_VALUE(CAUSTICS_AREA_MESH);
        ADD_ENUM_VALUE(CAUSTICS_PROCEDURAL);
        ADD_ENUM_VALUE(CAUSTICS_PROCEDURAL_SCREEN);
    END_ENUM_FIELD();
    ADD_BOOL_FIELD(CausticsSupersampling, false);
    ADD_BOOL_FIELD(ReflectiveCaustics, false);
    ADD_FLOAT_FIELD(CausticsTileSize, 0.0f);
    ADD_BOOL_FIELD(EnvironmentMapEnabled, false);
    ADD_INT_FIELD(EnvironmentMapSize, 256);
    ADD_FLOAT_FIELD(CausticsMotionTolerance, 0.5f);
    BEGIN_ENUM_FIELD(UnderwaterModel, UNDERWATER_PHYSICAL);
        ADD_ENUM_VALUE(UNDERWATER_PHYSICAL);
        ADD_ENUM_VALUE(UNDERWATER_THESIS);
    END_ENUM_FIELD();
    ADD_BOOL_FIELD(GlowEnabled, true);
    ADD_FLOAT_FIELD(GlowIntensity, 1.0f);
    ADD_FLOAT_FIELD(GlowRadius, 3.0f);
    ADD_FLOAT_FIELD(GlowResolution, 0.25f);
    ADD_FLOAT_FIELD(GlowExponent, 200.0f);
    ADD_VEC3F_FIELD(SunDirection, osgWater::WaterSettings::defaultSunDirection());
    ADD_VEC3F_FIELD(SunColor, osg::Vec3f(1.0f, 1.0f, 0.9f));
    ADD_VEC3F_FIELD(AmbientColor, osg::Vec3f(0.35f, 0.38f, 0.45f));
    ADD_FLOAT_FIELD(Exposure, 1.0f);
    BEGIN_ENUM_FIELD(ToneCurve, TONE_CLIP);
        ADD_ENUM_VALUE(TONE_CLIP);
        ADD_ENUM_VALUE(TONE_ACES);
    END_ENUM_FIELD();
    ADD_OTHER_FIELDS_SERIALIZER("osgWater::WaterSettings");
}

