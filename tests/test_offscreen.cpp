// The kit's off-screen helper as a user calls it, with the public API alone: a frame read back as a
// window shows it, and a water scene rendered frame after frame with no X error printed.
#include <osgWater/Offscreen>
#include <osgWater/WaterNode>
#include <osg/Geode>
#include <osg/Geometry>
#include <osg/Notify>
#include <gtest/gtest.h>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <unistd.h>

namespace {

// what the process prints on stdout and stderr while it lives (Xlib and OSG's X error handlers
// print to either), kept in a file and handed back as text
class PrintedOutput
{
public:
    PrintedOutput() : _file(std::string(OSGWATER_TEST_TMP) + "/offscreen_" + std::to_string(getpid()) + ".txt")
    {
        flush();
        _out = dup(1);
        _err = dup(2);
        FILE* f = std::fopen(_file.c_str(), "w");
        dup2(fileno(f), 1);
        dup2(fileno(f), 2);
        std::fclose(f);
    }
    std::string text()
    {
        restore();
        std::ifstream in(_file);
        std::stringstream s;
        s << in.rdbuf();
        return s.str();
    }
    ~PrintedOutput()
    {
        restore();
        std::remove(_file.c_str());
    }

private:
    static void flush()
    {
        std::cout.flush();
        std::cerr.flush();
        std::fflush(nullptr);
    }
    void restore()
    {
        if (_out < 0) return;
        flush();
        dup2(_out, 1);
        dup2(_err, 2);
        close(_out);
        close(_err);
        _out = _err = -1;
    }
    std::string _file;
    int _out = -1, _err = -1;
};

osg::Node* sandyBed(float depth)
{
    osg::Geometry* g = osg::createTexturedQuadGeometry(osg::Vec3(-20, -20, -depth), osg::Vec3(40, 0, 0), osg::Vec3(0, 40, 0));
    osg::Vec4Array* colour = new osg::Vec4Array(1);
    (*colour)[0].set(0.8f, 0.7f, 0.5f, 1.0f);
    g->setColorArray(colour, osg::Array::BIND_OVERALL);
    osg::Geode* geode = new osg::Geode;
    geode->addDrawable(g);
    return geode;
}

}

TEST(Offscreen, AWaterSceneRendersWithNoXErrorAndTheFrameIsWhatAWindowShows)
{
    const int w = 160, h = 120;
    osgViewer::Viewer viewer;
    std::string error;
    ASSERT_TRUE(osgWater::setUpOffscreen(viewer, w, h, &error)) << error;
    viewer.getCamera()->setViewMatrixAsLookAt(osg::Vec3d(0, -12, 10), osg::Vec3d(0, 0, 0), osg::Vec3d(0, 0, 1));

    // the clear colour alone reads back as a window shows it: 8-bit display values
    viewer.getCamera()->setClearColor(osg::Vec4(0.5f, 0.25f, 0.75f, 1.0f));
    viewer.setSceneData(new osg::Group);
    osg::ref_ptr<osg::Image> cleared = osgWater::renderOffscreenFrame(viewer, 0.0);
    ASSERT_TRUE(cleared.valid());
    ASSERT_EQ(cleared->s(), w);
    ASSERT_EQ(cleared->t(), h);
    const unsigned char* c = cleared->data(w / 2, h / 2);
    EXPECT_NEAR(c[0], 128, 1);
    EXPECT_NEAR(c[1], 64, 1);
    EXPECT_NEAR(c[2], 191, 1);

    // water over a bed, frame after frame: the centre is water, and nothing is printed of X
    osg::ref_ptr<osgWater::WaterNode> water = new osgWater::WaterNode;
    water->addChild(sandyBed(2.0f));
    std::string printed;
    osg::ref_ptr<osg::Image> frame;
    {
        PrintedOutput output;
        viewer.setSceneData(water.get());
        for (int i = 0; i < 4; ++i) frame = osgWater::renderOffscreenFrame(viewer, 1.0 + 0.1 * i);
        OSG_WARN << "what OSG prints is seen here" << std::endl;
        printed = output.text();
    }
    ASSERT_TRUE(frame.valid());
    const unsigned char* p = frame->data(w / 2, h / 2);
    EXPECT_GT(std::abs(int(p[0]) - 128) + std::abs(int(p[1]) - 64) + std::abs(int(p[2]) - 191), 30)
        << "the centre shows the clear colour, not the water";
    EXPECT_NE(printed.find("what OSG prints is seen here"), std::string::npos) << "the output was not captured";
    for (const char* sign : { "BadMatch", "X Error", "X error", "GLX" })
        EXPECT_EQ(printed.find(sign), std::string::npos) << "printed while rendering: " << printed;

    // a viewer the helper did not set up has no frame to read
    osgViewer::Viewer windowed;
    EXPECT_FALSE(osgWater::renderOffscreenFrame(windowed, 0.0).valid());
}
