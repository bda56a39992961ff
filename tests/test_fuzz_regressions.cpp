// Every input the fuzzer ever crashed on (tests/fuzz/regressions), and the seeds it starts from,
// replayed through the fuzz target's own checks in the ordinary build.
#include "fuzz/FuzzRead.h"
#include <gtest/gtest.h>
#include <osg/Notify>
#include <osgDB/FileUtils>
#include <fstream>
#include <sstream>

namespace {

std::vector<std::string> inputs(const std::string& dir)
{
    std::vector<std::string> files;
    for (const std::string& f : osgDB::getDirectoryContents(dir))
        if (f != "." && f != ".." && f != "README.md") files.push_back(dir + "/" + f);
    return files;
}

// The fuzz target silences OSG for the whole process (its init); a test of it puts OSG's notify
// level and handler back as they were, or every later test in the binary hears no warnings
struct FuzzTargetInScope {
    osg::NotifySeverity level = osg::getNotifyLevel();
    osg::ref_ptr<osg::NotifyHandler> handler = osg::getNotifyHandler();
    FuzzTargetInScope() { osgwater_fuzz::init(); }
    ~FuzzTargetInScope()
    {
        osg::setNotifyLevel(level);
        osg::setNotifyHandler(handler.get());
    }
};

std::string slurp(const std::string& path)
{
    std::ifstream in(path.c_str(), std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

}

TEST(FuzzRegressions, EveryKeptInputReadsWithoutBreakingAnInvariant)
{
    const FuzzTargetInScope target;
    const std::vector<std::string> files = inputs(OSGWATER_FUZZ_REGRESSIONS);
    ASSERT_FALSE(files.empty()) << "no inputs in " << OSGWATER_FUZZ_REGRESSIONS;
    for (const std::string& f : files) {
        const std::string bytes = slurp(f);
        EXPECT_EQ(osgwater_fuzz::readOne(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size()), "") << f;
    }
}

TEST(FuzzRegressions, TheSeedsReadAsWaterAndRoundTrip)
{
    // the checks must see WaterNodes: a seed that stopped reading would make the fuzzer blind
    const FuzzTargetInScope target;
    for (const std::string& f : inputs(OSGWATER_FUZZ_SEEDS)) {
        const std::string bytes = slurp(f);
        EXPECT_TRUE(osgwater_fuzz::isWater(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size())) << f;
        EXPECT_EQ(osgwater_fuzz::readOne(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size()), "") << f;
    }
}
