/* osgWater - natural water for OpenSceneGraph */
#ifndef OSGWATER_SHADERCONTRACT
#define OSGWATER_SHADERCONTRACT 1

#include <osgWater/Export>
#include <string>
#include <vector>

//! The C++/GLSL contract for the settings the shaders switch on: each enum value the C++ side
//! hands to a shader as a define (OSGWATER_REFRACTION, OSGWATER_FRESNEL, ...) has a named define in
//! the generated include "contract.glsl", made here from the settings' own name tables, so that no
//! shader compares a define with a literal that stands for a C++ ordinal.
//!
//!     #pragma include "contract.glsl"
//!     #if OSGWATER_REFRACTION == OSGWATER_REFRACTION_VIRTUAL_VERTICES
namespace osgWater {

//! One named value: OSGWATER_<switch>_<NAME>, the enum's value.
struct ShaderConstant {
    std::string define;
    int value;
};

//! The name of the generated include.
OSGWATER_EXPORT const char* shaderContractFile();
//! Every named value: the refraction and reflection lookups, the Fresnel models, the underwater
//! models (each from WaterSettings' names) and the debug outputs.
OSGWATER_EXPORT const std::vector<ShaderConstant>& shaderConstants();
//! The text of "contract.glsl": one #define per named value.
OSGWATER_EXPORT const std::string& shaderContractSource();

}

#endif
