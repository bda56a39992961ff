// Shader overrides come only from osgWater/shaders/<name> in a directory of the OSG data path:
// never from a bare name, never from the working directory (any project may keep a scene.frag).
#include "shaders/Shaders.h"
#include <osgDB/FileUtils>
#include <gtest/gtest.h>
#include <fstream>
#include <string>
#include <unistd.h>

using namespace osgWater;

namespace {

const char* kHostile = "#version 130\nvoid main() { gl_FragColor = vec4(1.0, 0.0, 1.0, 1.0); } // hostile\n";
const char* kNames[] = { "scene.frag", "water.frag", "blur.frag", "caustics.glsl", "scene.vert" };

void write(const std::string& path, const std::string& text)
{
    std::ofstream(path.c_str()) << text;
}

// runs the body in `dir` as the working directory, then goes back
template<class F> void inDirectory(const std::string& dir, F body)
{
    char previous[4096];
    ASSERT_NE(getcwd(previous, sizeof previous), nullptr);
    ASSERT_EQ(chdir(dir.c_str()), 0);
    body();
    ASSERT_EQ(chdir(previous), 0);
}

}

TEST(ShaderOverrides, FilesInTheWorkingDirectoryChangeNothing)
{
    const std::string dir = std::string(OSGWATER_TEST_TMP) + "/hostile-cwd";
    osgDB::makeDirectory(dir + "/osgWater/shaders");
    for (const char* n : kNames) {
        write(dir + "/" + n, kHostile);
        write(dir + "/osgWater/shaders/" + n, kHostile); // relative to the working directory: not the data path
    }
    inDirectory(dir, [] {
        for (const char* n : kNames) {
            std::string from;
            EXPECT_EQ(shaderSource(n, false, &from), shaderSource(n, true)) << n;
            EXPECT_EQ(from, "") << n;
        }
        osg::ref_ptr<osg::Program> p = createProgram("test", "scene.vert", "scene.frag");
        EXPECT_EQ(static_cast<FallbackProgram*>(p.get())->getOverrideFile(), "");
    });
}

TEST(ShaderOverrides, AFileUnderOsgWaterShadersOnTheDataPathOverridesABareOneDoesNot)
{
    const std::string dir = std::string(OSGWATER_TEST_TMP) + "/override-path";
    osgDB::makeDirectory(dir + "/osgWater/shaders");
    write(dir + "/water.frag", kHostile); // a bare name on the data path: not an override
    write(dir + "/osgWater/shaders/caustics.glsl", "// caustics override\nfloat owUnderwaterSun(float ndl) { return 1.0; }\n");
    osgDB::getDataFilePathList().push_front(dir);
    EXPECT_EQ(shaderSource("water.frag"), shaderSource("water.frag", true));
    std::string from;
    const std::string scene = shaderSource("scene.frag", false, &from); // includes caustics.glsl
    EXPECT_NE(scene.find("// caustics override"), std::string::npos);
    EXPECT_EQ(from, dir + "/osgWater/shaders/caustics.glsl");
    osgDB::getDataFilePathList().pop_front();
    EXPECT_EQ(shaderSource("scene.frag"), shaderSource("scene.frag", true)) << "gone with the data path entry";
}
