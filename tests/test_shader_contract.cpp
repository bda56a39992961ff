// The C++/GLSL contract: the shaders switch on settings through named values that the library
// makes from its enums (contract.glsl), never through literals that stand for a C++ ordinal.
#include "shaders/ShaderContract.h"
#include "shaders/Shaders.h"
#include <osgWater/Statistics>
#include <osgWater/WaterSettings>
#include <gtest/gtest.h>
#include <dirent.h>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using namespace osgWater;

namespace {

// the #defines of the generated include, parsed from its text
std::map<std::string, int> contractDefines()
{
    std::map<std::string, int> defines;
    std::istringstream in(shaderContractSource());
    std::string hash, name;
    int value;
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream l(line);
        if (l >> hash >> name >> value && hash == "#define") defines[name] = value;
    }
    return defines;
}

std::vector<std::string> shaderFiles()
{
    std::vector<std::string> files;
    if (DIR* d = opendir(OSGWATER_SHADER_DIR)) {
        while (dirent* e = readdir(d)) {
            const std::string n = e->d_name;
            if (n.size() > 5 && (n.find(".vert") != std::string::npos || n.find(".frag") != std::string::npos ||
                                 n.find(".glsl") != std::string::npos))
                files.push_back(n);
        }
        closedir(d);
    }
    return files;
}

std::string readFile(const std::string& name)
{
    std::ifstream in((std::string(OSGWATER_SHADER_DIR) + "/" + name).c_str());
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

}

// Each named value is its C++ enum's: stated here independently of the library's table, so a
// value or a name that drifts fails
TEST(ShaderContract, EveryNamedValueIsItsEnumsValue)
{
    const std::map<std::string, int> expected = {
        { "OSGWATER_REFRACTION_ONE_STEP", WaterSettings::ONE_STEP },
        { "OSGWATER_REFRACTION_ITERATIVE", WaterSettings::ITERATIVE },
        { "OSGWATER_REFRACTION_PLANE", WaterSettings::PLANE_OFFSET },
        { "OSGWATER_REFRACTION_BRACKETED", WaterSettings::BRACKETED },
        { "OSGWATER_REFRACTION_VIRTUAL_VERTICES", WaterSettings::VIRTUAL_VERTICES },
        { "OSGWATER_REFLECTION_OFFSET", WaterSettings::REFLECTION_OFFSET },
        { "OSGWATER_REFLECTION_PLANE", WaterSettings::REFLECTION_PLANE },
        { "OSGWATER_REFLECTION_SEARCH", WaterSettings::REFLECTION_SEARCH },
        { "OSGWATER_FRESNEL_SCHLICK", WaterSettings::FRESNEL_SCHLICK },
        { "OSGWATER_FRESNEL_POWER", WaterSettings::FRESNEL_POWER },
        { "OSGWATER_FRESNEL_EXACT", WaterSettings::FRESNEL_EXACT },
        { "OSGWATER_FRESNEL_RECIPROCAL", WaterSettings::FRESNEL_RECIPROCAL },
        { "OSGWATER_UNDERWATER_PHYSICAL", WaterSettings::UNDERWATER_PHYSICAL },
        { "OSGWATER_UNDERWATER_THESIS", WaterSettings::UNDERWATER_THESIS },
        { "OSGWATER_TONE_CLIP", WaterSettings::TONE_CLIP },
        { "OSGWATER_TONE_ACES", WaterSettings::TONE_ACES },
        { "OSGWATER_DEBUG_NONE", DEBUG_NONE },
        { "OSGWATER_DEBUG_BOTTOM_HIT", DEBUG_BOTTOM_HIT },
        { "OSGWATER_DEBUG_REFLECTION_LOOKUP", DEBUG_REFLECTION_LOOKUP },
        { "OSGWATER_DEBUG_FRESNEL", DEBUG_FRESNEL },
        { "OSGWATER_DEBUG_SURFACE", DEBUG_SURFACE },
        { "OSGWATER_DEBUG_DRAWN_SURFACE", DEBUG_DRAWN_SURFACE },
        { "OSGWATER_DEBUG_SLOPES", DEBUG_SLOPES },
        { "OSGWATER_DEBUG_WORK", DEBUG_WORK },
    };
    EXPECT_EQ(contractDefines(), expected);
    // and the table the text is made from says the same
    for (const ShaderConstant& c : shaderConstants()) {
        auto it = expected.find(c.define);
        ASSERT_NE(it, expected.end()) << c.define;
        EXPECT_EQ(c.value, it->second) << c.define;
    }
}

// No shader compares a switch with a number, and every named value a shader uses exists (an
// unknown name would make the comparison quietly false)
TEST(ShaderContract, ShadersCompareSwitchesWithNamedValuesOnly)
{
    const std::vector<std::string> files = shaderFiles();
    ASSERT_GE(files.size(), 20u) << "the shader folder " << OSGWATER_SHADER_DIR;
    const std::map<std::string, int> defines = contractDefines();
    const std::regex literal(R"(OSGWATER_(REFRACTION|REFLECTION|FRESNEL|UNDERWATER|TONE|DEBUG)\s*[=!]=\s*[0-9])");
    const std::regex named(R"(OSGWATER_(REFRACTION|REFLECTION|FRESNEL|UNDERWATER|TONE|DEBUG)\s*[=!]=\s*(OSGWATER_\w+))");
    int comparisons = 0;
    for (const std::string& f : files) {
        const std::string text = readFile(f);
        EXPECT_FALSE(std::regex_search(text, literal)) << f << " compares a switch with a literal";
        for (std::sregex_iterator it(text.begin(), text.end(), named), end; it != end; ++it, ++comparisons)
            EXPECT_EQ(defines.count((*it)[2].str()), 1u) << f << ": " << (*it)[2].str() << " is not in contract.glsl";
    }
    EXPECT_GE(comparisons, 15) << "the water shader's switches";
}

// The shaders that compare switches have the contract in their expanded source, before the first
// comparison
TEST(ShaderContract, TheExpandedShadersIncludeTheContractBeforeUsingIt)
{
    for (const char* name : { "water.frag", "cap.frag", "scene.frag", "photon.frag", "procedural.frag", "guest.frag" }) {
        const std::string src = shaderSource(name, true);
        const size_t contract = src.find("#define OSGWATER_REFRACTION_ONE_STEP");
        const size_t use = src.find("== OSGWATER_");
        ASSERT_NE(contract, std::string::npos) << name;
        if (use != std::string::npos) EXPECT_LT(contract, use) << name;
        // included once, however many includes ask for it
        EXPECT_EQ(src.find("#define OSGWATER_REFRACTION_ONE_STEP", contract + 1), std::string::npos) << name;
    }
}

namespace {

// every string literal in the library's sources
std::set<std::string> librarySourceLiterals()
{
    std::set<std::string> literals;
    const std::regex literal(R"re("([A-Za-z_][A-Za-z_0-9]*)")re");
    std::vector<std::string> dirs = { OSGWATER_LIBRARY_SOURCE_DIR };
    while (!dirs.empty()) {
        const std::string dir = dirs.back();
        dirs.pop_back();
        DIR* d = opendir(dir.c_str());
        if (!d) continue;
        while (dirent* e = readdir(d)) {
            const std::string n = e->d_name, path = dir + "/" + n;
            if (n == "." || n == "..") continue;
            if (e->d_type == DT_DIR) { dirs.push_back(path); continue; }
            std::ifstream in(path.c_str());
            std::stringstream ss;
            ss << in.rdbuf();
            const std::string text = ss.str();
            for (std::sregex_iterator it(text.begin(), text.end(), literal), end; it != end; ++it) literals.insert((*it)[1]);
        }
        closedir(d);
    }
    return literals;
}

}

// Every uniform a shader declares is one the library sets by name (whole, or a pass's prefix and a
// suffix), and every uniform name the library sets is declared by a shader: a name misspelt on
// either side fails here, not as a black or silently wrong picture
TEST(ShaderContract, EveryDeclaredUniformIsSetByTheLibraryAndBack)
{
    const std::set<std::string> literals = librarySourceLiterals();
    ASSERT_GE(literals.size(), 100u) << OSGWATER_LIBRARY_SOURCE_DIR;
    const std::regex declaration(R"(uniform\s+\w+\s+(osgWater_\w+))");
    std::set<std::string> declared;
    for (const std::string& f : shaderFiles()) {
        const std::string text = readFile(f);
        for (std::sregex_iterator it(text.begin(), text.end(), declaration), end; it != end; ++it)
            declared.insert((*it)[1]);
    }
    ASSERT_GE(declared.size(), 60u);
    auto setByLibrary = [&](const std::string& u) {
        if (literals.count(u)) return true;
        for (const std::string& prefix : literals)
            if (prefix.size() < u.size() && u.compare(0, prefix.size(), prefix) == 0 &&
                literals.count(u.substr(prefix.size())))
                return true;
        return false;
    };
    for (const std::string& u : declared) EXPECT_TRUE(setByLibrary(u)) << u << " is declared but never set";
    for (const std::string& l : literals) {
        if (l.compare(0, 9, "osgWater_") != 0) continue;
        bool used = declared.count(l) > 0;
        for (const std::string& u : declared) used = used || u.compare(0, l.size(), l) == 0;
        EXPECT_TRUE(used) << l << " is set by the library but no shader declares it";
    }
}
