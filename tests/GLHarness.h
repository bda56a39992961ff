// Headless rendering for the tests: a pbuffer context (Xvfb + Mesa on CI), a main camera that
// renders into a float texture, and read-back of any texture of that context.
#pragma once
#include <osgViewer/Viewer>
#include <osg/Texture2D>
#include <osg/Geometry>
#include <osg/Image>
#include <gtest/gtest.h>
#include <osgWater/WaterSettings>
#include <osgWater/WaterSurface>
#include <osgWater/WaterNode>
#include <functional>
#include <set>
#include <cstdlib>
#include <ostream>
#include <string>

namespace testing_gl {

//! A pbuffer context, or nullptr with the reason in `why`.
osg::ref_ptr<osg::GraphicsContext> createPbuffer(int width, int height, std::string& why);

//! GL context missing: a failure when CI is set (never a silent green), a skip on a developer's machine.
#define REQUIRE_GL(harness)                                                                          \
    do {                                                                                             \
        if (!(harness).ok()) {                                                                       \
            if (std::getenv("CI")) FAIL() << "CI is set and no GL context: " << (harness).why();     \
            GTEST_SKIP() << "no GL context (" << (harness).why() << "); set DISPLAY or use xvfb-run"; \
        }                                                                                            \
    } while (0)

//! Whether a GL context could be made, and why not: what REQUIRE_GL asks of tests that make their
//! own contexts.
struct ContextProbe {
    bool v;
    std::string w;
    bool ok() const { return v; }
    const std::string& why() const { return w; }
};

class Harness
{
public:
    //! A main view of width x height into a float target (or `targetFormat`: GL_SRGB8_ALPHA8 stores
    //! display values as a window's framebuffer usually does).
    Harness(int width, int height, GLenum targetFormat = GL_RGBA32F_ARB);
    bool ok() const { return _gc.valid(); }
    const std::string& why() const { return _why; }
    osgViewer::Viewer* viewer() { return _viewer.get(); }
    osg::Camera* camera() { return _viewer->getCamera(); }
    osg::GraphicsContext* context() { return _gc.get(); }
    int width() const { return _w; }
    int height() const { return _h; }

    void setScene(osg::Node* node) { _viewer->setSceneData(node); }
    void lookAt(const osg::Vec3d& eye, const osg::Vec3d& center, double fovy = 45.0);
    void frame(double simulationTime);
    //! Pixel (column, row from the bottom) where a local point lands in the main view.
    osg::Vec2d pixelOf(const osg::Vec3d& p) const;
    //! The view's eye, and the unit ray from it through pixel (x, y)'s centre (column, row from the
    //! bottom), in the scene's frame.
    osg::Vec3d eye() const;
    osg::Vec3d pixelRay(int x, int y) const;
    //! The main camera's float colour target, read back after the last frame.
    osg::ref_ptr<osg::Image> readColor() { return readTexture(_target.get()); }
    //! Any texture on this context as float RGBA (depth textures: depth in every channel), at a
    //! mipmap level.
    osg::ref_ptr<osg::Image> readTexture(osg::Texture2D* texture, int level = 0);

private:
    int _w, _h;
    std::string _why;
    osg::ref_ptr<osg::GraphicsContext> _gc;
    osg::ref_ptr<osgViewer::Viewer> _viewer;
    osg::ref_ptr<osg::Texture2D> _target;
};

//! Binds a float RGBA texture target (or one of `format`) to a camera (FBO) on the given context.
osg::Texture2D* attachFloatTarget(osg::Camera* camera, osg::GraphicsContext* gc, int w, int h,
                                  GLenum format = GL_RGBA32F_ARB);
osg::ref_ptr<osg::Image> readTexture(osg::GraphicsContext* gc, osg::Texture2D* texture, int level = 0);

// --- GL objects ----------------------------------------------------------------------------------
//! Live GL objects of one context, counted by name (glIs*).
struct GLCounts {
    int textures = 0, framebuffers = 0, renderbuffers = 0, buffers = 0, programs = 0, queries = 0;
    bool operator==(const GLCounts& o) const
    {
        return textures == o.textures && framebuffers == o.framebuffers && renderbuffers == o.renderbuffers &&
               buffers == o.buffers && programs == o.programs && queries == o.queries;
    }
};
std::ostream& operator<<(std::ostream& os, const GLCounts& c);
//! Every name up to kNames is tested: Mesa hands out names from 1 upwards and reuses freed ones
//! (the highest live name is returned in `highest`, to check against the bound).
const GLuint kNames = 1u << 16;
//! Makes the context current, deletes what OSG was told to release (OSG otherwise deletes it in
//! later frames, within a time budget), then counts the objects left.
GLCounts countGLObjects(osg::GraphicsContext* gc, GLuint& highest);

// --- analytic test scenes ------------------------------------------------------------------------
//! A quad from four corners lit by the kit's scene program with its default material (diffuse
//! 0.8, ambient 0.2, white), normal (b - a) x (d - a).
osg::Geode* litQuad(const osg::Vec3& a, const osg::Vec3& b, const osg::Vec3& c, const osg::Vec3& d);
//! An unlit (emissive) quad from four corners: its pixels are exactly `color`.
osg::Geode* emissiveQuad(const osg::Vec3& a, const osg::Vec3& b, const osg::Vec3& c, const osg::Vec3& d,
                         const osg::Vec4& color);
//! A texture of columns x rows opaque texels, texel (i, j) = `texel(i, j)`, filtered nearest.
osg::Texture2D* nearestTexture(int columns, int rows, const std::function<osg::Vec3ub(int, int)>& texel,
                               osg::Texture::WrapMode wrap);
//! A horizontal square at height z, side `size`, with an unlit black/white checkerboard of
//! `cell` metres (cell (i, j) white when i + j is even; nearest filtering), drawn as
//! `quadsPerSide` x `quadsPerSide` quads (geometry moved per vertex needs more than one).
osg::Geode* checkerPlane(float z, float size, float cell, int quadsPerSide = 1);
//! Checker colour (1 white, 0 black) at (x, y) for a board made by checkerPlane.
float checkerAt(double x, double y, float cell);

inline const float* pixel(const osg::Image* img, int x, int y)
{
    return reinterpret_cast<const float*>(img->data(x, y));
}
bool allFinite(const osg::Image* img);
//! Writes an 8-bit PNG of a float image to $OSGWATER_TEST_DUMP (debugging aid).
void dumpImage(const osg::Image* img, const std::string& name);

//! The water models render tests run under: the thesis's one k and colour, then every preset of
//! WaterTypes by name. INSTANTIATE_TEST_SUITE_P(Models, Suite, waterModels(), waterModelTestName).
::testing::internal::ParamGenerator<std::string> waterModels();
std::string waterModelTestName(const ::testing::TestParamInfo<std::string>& info);

//! A wave of the sum of sines, for surfaces built in tests.
osgWater::Wave makeWave(float dx, float dy, float wavelength, float amplitude);

//! Linear light as the view shows it: encoded to sRGB (exposure 1, the exact curve).
osg::Vec3 shown(const osg::Vec3& linear);

//! The emissive bed colour of flatWaterOverBed.
const osg::Vec3 kBedGrey(0.6f, 0.5f, 0.4f);
//! Flat water 400 m across at z = 0 over a uniform emissive bed of kBedGrey `depth` metres below: the
//! scene compareFlatWaterWithOptics checks (settings at their defaults).
osg::ref_ptr<osgWater::WaterNode> flatWaterOverBed(float depth);

//! The Optics mirror against a rendered image of flat water at `level` over a uniform emissive bed
//! of colour `bed` at `bedZ`, with the clear colour (the sky) reflected: each `step`-th pixel whose
//! ray, taken into the water's frame by `toWater`, meets the surface at a U that `keep` accepts is
//! compared with eq. 9 of eq. 5 along the exact refracted path (the settings' Fresnel model and water
//! model per channel, the path in the water's metres), in linear light: the bed and the sky decoded
//! from sRGB, the mix encoded. Rays within 0.05 of level are left out. What the reflected ray sees is
//! the clear colour, or what `reflected` says (a display value) for the ray leaving U along Rr.
struct MirrorComparison {
    int checked = 0;      //!< pixels compared
    double worst = 0.0;   //!< largest channel difference
    osg::Vec2i worstPixel; //!< where it is (column, row from the bottom)
    bool bedMissed = false; //!< a refracted ray that never reached the bed (a bad test scene)
    std::set<int> renderedLevels, expectedLevels; //!< the 8-bit levels of green the pixels show, and should
};
using ReflectedColour = std::function<osg::Vec3(const osg::Vec3d& U, const osg::Vec3d& Rr)>;
MirrorComparison compareFlatWaterWithOptics(Harness& h, const osg::Image* img, const osgWater::WaterSettings& s,
                                            const osg::Matrixd& toWater, double level, double bedZ,
                                            const osg::Vec3& bed, int step,
                                            const std::function<bool(const osg::Vec3d&)>& keep = nullptr,
                                            const ReflectedColour& reflected = nullptr);

}
