#include "GLHarness.h"
#include "offscreen/TextureReadback.h"
#include <osgWater/Offscreen>
#include <osgWater/WaterTypes>
#include "optics/Optics.h"
#include "optics/Srgb.h"
#include <algorithm>
#include "../apps/common/FrameTimer.h"
#include <osg/Material>
#include <osg/Texture2D>
#include <osg/GL>
#include <osg/Notify>
#include <osg/GLExtensions>
#include <osg/GLObjects>
#include <cstdio>
#include <osgDB/WriteFile>
#include <algorithm>
#include <cmath>

namespace testing_gl {

osg::ref_ptr<osg::GraphicsContext> createPbuffer(int width, int height, std::string& why)
{
    return osgWater::createOffscreenContext(width, height, &why); // the kit's own, as the demo's
}

osg::Texture2D* attachFloatTarget(osg::Camera* camera, osg::GraphicsContext* gc, int w, int h, GLenum format)
{
    osg::Texture2D* t = new osg::Texture2D;
    t->setName("mainTarget");
    t->setTextureSize(w, h);
    t->setInternalFormat(format);
    t->setSourceFormat(GL_RGBA);
    t->setSourceType(format == GL_SRGB8_ALPHA8 ? GL_UNSIGNED_BYTE : GL_FLOAT);
    t->setFilter(osg::Texture::MIN_FILTER, osg::Texture::NEAREST);
    t->setFilter(osg::Texture::MAG_FILTER, osg::Texture::NEAREST);
    camera->setGraphicsContext(gc);
    camera->setViewport(0, 0, w, h);
    camera->setRenderTargetImplementation(osg::Camera::FRAME_BUFFER_OBJECT);
    camera->attach(osg::Camera::COLOR_BUFFER, t);
    camera->attach(osg::Camera::DEPTH_BUFFER, GL_DEPTH_COMPONENT24);
    return t;
}

Harness::Harness(int width, int height, GLenum targetFormat) : _w(width), _h(height)
{
    _gc = createPbuffer(width, height, _why);
    if (!_gc.valid()) return;
    _viewer = new osgViewer::Viewer;
    _viewer->setThreadingModel(osgViewer::ViewerBase::SingleThreaded);
    _viewer->setReleaseContextAtEndOfFrameHint(false);
    _target = attachFloatTarget(_viewer->getCamera(), _gc.get(), width, height, targetFormat);
    _viewer->getCamera()->setClearColor(osg::Vec4(0.2f, 0.3f, 0.8f, 1.0f));
    _viewer->getCamera()->setComputeNearFarMode(osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR);
}

void Harness::lookAt(const osg::Vec3d& eye, const osg::Vec3d& center, double fovy)
{
    _viewer->getCamera()->setViewMatrixAsLookAt(eye, center, osg::Vec3d(0.0, 0.0, 1.0));
    _viewer->getCamera()->setProjectionMatrixAsPerspective(fovy, double(_w) / double(_h), 0.05, 500.0);
}

void Harness::frame(double simulationTime)
{
    _viewer->frame(simulationTime);
}

osg::Vec2d Harness::pixelOf(const osg::Vec3d& p) const
{
    const osg::Camera* cam = _viewer->getCamera();
    const osg::Vec4d c = osg::Vec4d(p, 1.0) * cam->getViewMatrix() * cam->getProjectionMatrix();
    return osg::Vec2d((c.x() / c.w() * 0.5 + 0.5) * _w, (c.y() / c.w() * 0.5 + 0.5) * _h);
}

osg::Vec3d Harness::eye() const
{
    return osg::Matrixd::inverse(_viewer->getCamera()->getViewMatrix()).getTrans();
}

osg::Vec3d Harness::pixelRay(int x, int y) const
{
    const osg::Camera* cam = _viewer->getCamera();
    const osg::Matrixd toScene = osg::Matrixd::inverse(cam->getViewMatrix() * cam->getProjectionMatrix() *
                                                       cam->getViewport()->computeWindowMatrix());
    osg::Vec3d d = osg::Vec3d(x + 0.5, y + 0.5, 1.0) * toScene - eye();
    d.normalize();
    return d;
}

osg::ref_ptr<osg::Image> readTexture(osg::GraphicsContext* gc, osg::Texture2D* texture, int level)
{
    gc->makeCurrent();
    const GLenum before = glGetError(); // errors the frame left behind are the frame's, not ours
    EXPECT_EQ(before, GLenum(GL_NO_ERROR)) << "GL error left by the frame before reading " << texture->getName();
    const GLint fmt = texture->getInternalFormat();
    const bool depth = fmt == GL_DEPTH_COMPONENT24 || fmt == GL_DEPTH_COMPONENT;
    osg::ref_ptr<osg::Image> img =
        osgWater::detail::readTexture(gc, texture, depth ? GL_DEPTH_COMPONENT : GL_RGBA, GL_FLOAT, level);
    if (!img) return nullptr;
    const GLenum err = glGetError();
    EXPECT_EQ(err, GLenum(GL_NO_ERROR)) << "reading back " << texture->getName();
    if (depth) { // every channel the depth, as the tests read colours
        osg::ref_ptr<osg::Image> rgba = new osg::Image;
        rgba->allocateImage(img->s(), img->t(), 1, GL_RGBA, GL_FLOAT);
        const float* d = reinterpret_cast<const float*>(img->data());
        float* p = reinterpret_cast<float*>(rgba->data());
        for (size_t i = 0; i < size_t(img->s()) * img->t(); ++i) p[4 * i] = p[4 * i + 1] = p[4 * i + 2] = p[4 * i + 3] = d[i];
        img = rgba;
    }
    // left current: the viewer (release hint off) does not make it current again
    if (std::getenv("OSGWATER_TEST_DUMP")) dumpImage(img.get(), texture->getName().empty() ? "texture" : texture->getName());
    return img;
}

void dumpImage(const osg::Image* img, const std::string& name)
{
    // 8-bit copy for looking at failures: OSGWATER_TEST_DUMP=<folder>; nothing without it
    const char* dir = std::getenv("OSGWATER_TEST_DUMP");
    if (!dir) return;
    static int counter = 0;
    osg::ref_ptr<osg::Image> out = new osg::Image;
    out->allocateImage(img->s(), img->t(), 1, GL_RGBA, GL_UNSIGNED_BYTE);
    for (int y = 0; y < img->t(); ++y)
        for (int x = 0; x < img->s(); ++x)
            for (int k = 0; k < 4; ++k)
                out->data(x, y)[k] = (unsigned char)(std::min(std::max(pixel(img, x, y)[k], 0.0f), 1.0f) * 255.0f + 0.5f);
    osgDB::writeImageFile(*out, std::string(dir) + "/" + std::to_string(counter++) + "_" + name + ".png");
}

osg::ref_ptr<osg::Image> Harness::readTexture(osg::Texture2D* texture, int level) { return testing_gl::readTexture(_gc.get(), texture, level); }

std::ostream& operator<<(std::ostream& os, const GLCounts& c)
{
    return os << c.textures << " textures, " << c.framebuffers << " framebuffers, " << c.renderbuffers
              << " renderbuffers, " << c.buffers << " buffers, " << c.programs << " programs, " << c.queries << " queries";
}

GLCounts countGLObjects(osg::GraphicsContext* gc, GLuint& highest)
{
    gc->makeCurrent();
    osg::flushAllDeletedGLObjects(gc->getState()->getContextID());
    // GL 2/3 entry points OSG does not wrap, loaded through OSG's own loader
    typedef GLboolean(GL_APIENTRY * IsObject)(GLuint);
    static IsObject isFramebuffer = nullptr, isRenderbuffer = nullptr, isBuffer = nullptr, isProgram = nullptr,
                    isQuery = nullptr;
    if (!isFramebuffer) {
        osg::setGLExtensionFuncPtr(isQuery, "glIsQuery", "glIsQueryARB");
        osg::setGLExtensionFuncPtr(isFramebuffer, "glIsFramebuffer", "glIsFramebufferEXT");
        osg::setGLExtensionFuncPtr(isRenderbuffer, "glIsRenderbuffer", "glIsRenderbufferEXT");
        osg::setGLExtensionFuncPtr(isBuffer, "glIsBuffer", "glIsBufferARB");
        osg::setGLExtensionFuncPtr(isProgram, "glIsProgram", "glIsProgramObjectARB");
    }
    GLCounts c;
    for (GLuint i = 1; i < kNames; ++i) {
        const bool t = glIsTexture(i), f = isFramebuffer && isFramebuffer(i), r = isRenderbuffer && isRenderbuffer(i),
                   b = isBuffer && isBuffer(i), p = isProgram && isProgram(i), q = isQuery && isQuery(i);
        c.textures += t;
        c.framebuffers += f;
        c.renderbuffers += r;
        c.buffers += b;
        c.programs += p;
        c.queries += q;
        if (t || f || r || b || p || q) highest = std::max(highest, i);
    }
    return c;
}

namespace {
osg::Material* unlit(const osg::Vec4& color)
{
    osg::Material* m = new osg::Material;
    m->setEmission(osg::Material::FRONT_AND_BACK, color);
    m->setAmbient(osg::Material::FRONT_AND_BACK, osg::Vec4(0, 0, 0, color.a()));
    m->setDiffuse(osg::Material::FRONT_AND_BACK, osg::Vec4(0, 0, 0, color.a()));
    return m;
}
}

osg::Geode* litQuad(const osg::Vec3& a, const osg::Vec3& b, const osg::Vec3& c, const osg::Vec3& d)
{
    osg::Geometry* g = new osg::Geometry;
    osg::Vec3Array* v = new osg::Vec3Array;
    v->push_back(a); v->push_back(b); v->push_back(c); v->push_back(d);
    g->setVertexArray(v);
    osg::Vec3Array* n = new osg::Vec3Array(1);
    (*n)[0] = (b - a) ^ (d - a);
    (*n)[0].normalize();
    g->setNormalArray(n, osg::Array::BIND_OVERALL);
    g->addPrimitiveSet(new osg::DrawArrays(GL_QUADS, 0, 4));
    osg::Geode* geode = new osg::Geode;
    geode->addDrawable(g);
    return geode;
}

osg::Geode* emissiveQuad(const osg::Vec3& a, const osg::Vec3& b, const osg::Vec3& c, const osg::Vec3& d,
                         const osg::Vec4& color)
{
    osg::Geode* geode = litQuad(a, b, c, d);
    geode->getOrCreateStateSet()->setAttribute(unlit(color));
    return geode;
}

osg::Texture2D* nearestTexture(int columns, int rows, const std::function<osg::Vec3ub(int, int)>& texel,
                               osg::Texture::WrapMode wrap)
{
    osg::ref_ptr<osg::Image> img = new osg::Image;
    img->allocateImage(columns, rows, 1, GL_RGBA, GL_UNSIGNED_BYTE);
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < columns; ++i) {
            unsigned char* p = img->data(i, j);
            const osg::Vec3ub c = texel(i, j);
            p[0] = c.x(); p[1] = c.y(); p[2] = c.z(); p[3] = 255;
        }
    osg::Texture2D* t = new osg::Texture2D(img.get());
    t->setFilter(osg::Texture::MIN_FILTER, osg::Texture::NEAREST);
    t->setFilter(osg::Texture::MAG_FILTER, osg::Texture::NEAREST);
    t->setWrap(osg::Texture::WRAP_S, wrap);
    t->setWrap(osg::Texture::WRAP_T, wrap);
    t->setResizeNonPowerOfTwoHint(false);
    return t;
}

osg::Geode* checkerPlane(float z, float size, float cell, int quadsPerSide)
{
    // one texel per cell, repeated: exact cell edges with nearest filtering
    osg::Texture2D* tex = nearestTexture(2, 2, [](int i, int j) {
        const unsigned char c = ((i + j) % 2 == 0) ? 255 : 0;
        return osg::Vec3ub(c, c, c);
    }, osg::Texture::REPEAT);

    const float h = 0.5f * size, step = size / float(std::max(quadsPerSide, 1));
    osg::Geometry* g = new osg::Geometry;
    osg::Vec3Array* v = new osg::Vec3Array;
    for (int j = 0; j < std::max(quadsPerSide, 1); ++j)
        for (int i = 0; i < std::max(quadsPerSide, 1); ++i) {
            const float x0 = -h + i * step, y0 = -h + j * step, x1 = x0 + step, y1 = y0 + step;
            v->push_back(osg::Vec3(x0, y0, z)); v->push_back(osg::Vec3(x1, y0, z));
            v->push_back(osg::Vec3(x1, y1, z)); v->push_back(osg::Vec3(x0, y1, z));
        }
    osg::Vec2Array* t = new osg::Vec2Array;
    // texture coordinate = position / (2 cell): one repeat of the 2x2 image per 2 cells
    for (const osg::Vec3& p : *v) t->push_back(osg::Vec2(p.x() / (2.0f * cell), p.y() / (2.0f * cell)));
    g->setVertexArray(v);
    g->setTexCoordArray(0, t);
    osg::Vec3Array* n3 = new osg::Vec3Array(1);
    (*n3)[0].set(0, 0, 1);
    g->setNormalArray(n3, osg::Array::BIND_OVERALL);
    g->addPrimitiveSet(new osg::DrawArrays(GL_QUADS, 0, GLsizei(v->size())));
    osg::Geode* geode = new osg::Geode;
    geode->addDrawable(g);
    geode->getOrCreateStateSet()->setAttribute(unlit(osg::Vec4(1, 1, 1, 1)));
    geode->getOrCreateStateSet()->setTextureAttribute(0, tex);
    return geode;
}

float checkerAt(double x, double y, float cell)
{
    const long i = long(std::floor(x / cell)), j = long(std::floor(y / cell));
    return ((i + j) % 2 == 0) ? 1.0f : 0.0f;
}

bool allFinite(const osg::Image* img)
{
    const float* p = reinterpret_cast<const float*>(img->data());
    const size_t n = size_t(img->s()) * img->t() * 4;
    for (size_t i = 0; i < n; ++i)
        if (!std::isfinite(p[i])) return false;
    return true;
}

osg::ref_ptr<osgWater::WaterNode> flatWaterOverBed(float depth)
{
    osg::ref_ptr<osgWater::WaterNode> water = new osgWater::WaterNode;
    water->getSurface()->setWaves({});
    water->getSurface()->setSize(400.0f);
    water->addChild(emissiveQuad(osg::Vec3(-100, -100, -depth), osg::Vec3(100, -100, -depth),
                                 osg::Vec3(100, 100, -depth), osg::Vec3(-100, 100, -depth), osg::Vec4(kBedGrey, 1.0f)));
    return water;
}

osg::Vec3 shown(const osg::Vec3& linear)
{
    const glm::vec3 e = osgWater::optics::encodeSrgb(glm::vec3(linear.x(), linear.y(), linear.z()));
    return osg::Vec3(e.x, e.y, e.z);
}

osgWater::Wave makeWave(float dx, float dy, float wavelength, float amplitude)
{
    osgWater::Wave w;
    w.direction.set(dx, dy);
    w.wavelength = wavelength;
    w.amplitude = amplitude;
    return w;
}

MirrorComparison compareFlatWaterWithOptics(Harness& h, const osg::Image* img, const osgWater::WaterSettings& s,
                                            const osg::Matrixd& toWater, double level, double bedZ,
                                            const osg::Vec3& bed, int step,
                                            const std::function<bool(const osg::Vec3d&)>& keep,
                                            const ReflectedColour& reflected)
{
    namespace optics = osgWater::optics;
    MirrorComparison r;
    const osg::Matrixd inv = osg::Matrixd::inverse(h.camera()->getViewMatrix() * h.camera()->getProjectionMatrix());
    const osg::Vec4 clear = h.camera()->getClearColor();
    // the sky (the clear colour) and the bed are display values; the water sums linear light
    const glm::vec3 sky = optics::decodeSrgb(glm::vec3(clear.r(), clear.g(), clear.b()));
    const glm::vec3 bedColour = optics::decodeSrgb(glm::vec3(bed.x(), bed.y(), bed.z()));
    const osg::Vec3 body = s.getBodyColor(), k = s.getViewExtinction();
    for (int y = step / 2; y < h.height(); y += step)
        for (int x = step / 2; x < h.width(); x += step) {
            const double nx = (x + 0.5) / h.width() * 2 - 1, ny = (y + 0.5) / h.height() * 2 - 1;
            const osg::Vec3d a = osg::Vec3d(nx, ny, -1) * inv * toWater, b = osg::Vec3d(nx, ny, 1) * inv * toWater;
            osg::Vec3d d = b - a;
            d.normalize();
            if (d.z() > -0.05) continue; // sky, or too grazing for a fair texel comparison
            const osg::Vec3d U = a + d * ((level - a.z()) / d.z());
            if (keep && !keep(U)) continue;
            const glm::vec3 I(d.x(), d.y(), d.z()), u(U.x(), U.y(), U.z());
            const glm::vec3 R = optics::refract(I, glm::vec3(0, 0, 1), s.getAirIOR() / s.getWaterIOR());
            glm::vec3 X;
            if (!optics::intersectPlaneZ(u, R, float(bedZ), X)) { r.bedMissed = true; continue; }
            const glm::vec3 refr = optics::waterTint(bedColour, glm::vec3(body.x(), body.y(), body.z()),
                                                     optics::attenuation(glm::vec3(k.x(), k.y(), k.z()), glm::length(X - u)));
            const float F = optics::fresnelModel(int(s.getFresnelModel()), -I.z, s.getAirIOR(), s.getWaterIOR(),
                                                 s.getFresnelModelExponent());
            glm::vec3 seen = sky;
            if (reflected) {
                const osg::Vec3 c = reflected(U, osg::Vec3d(d.x(), d.y(), -d.z()));
                seen = optics::decodeSrgb(glm::vec3(c.x(), c.y(), c.z()));
            }
            const glm::vec3 expect = optics::encodeSrgb(optics::fresnelMix(refr, seen, F));
            const float* c = pixel(img, x, y);
            for (int i = 0; i < 3; ++i)
                if (double(std::fabs(c[i] - expect[i])) > r.worst) {
                    r.worst = std::fabs(c[i] - expect[i]);
                    r.worstPixel.set(x, y);
                }
            r.renderedLevels.insert(int(std::lround(c[1] * 255.0f)));
            r.expectedLevels.insert(int(std::lround(expect[1] * 255.0f)));
            ++r.checked;
        }
    return r;
}

::testing::internal::ParamGenerator<std::string> waterModels()
{
    std::vector<std::string> names{ "thesis" };
    for (const osgWater::WaterType& t : osgWater::waterTypes()) names.push_back(t.name);
    return ::testing::ValuesIn(names);
}

std::string waterModelTestName(const ::testing::TestParamInfo<std::string>& info)
{
    std::string n = info.param; // test names take letters and digits only
    n.erase(std::remove(n.begin(), n.end(), '-'), n.end());
    return n;
}

}

namespace {
// Any shader that fails to compile or link fails the running test: a missing water program
// would otherwise leave plausible-looking (finite, scene-only) images behind.
class ShaderErrorsFail : public osg::NotifyHandler
{
public:
    void notify(osg::NotifySeverity severity, const char* message) override
    {
        const std::string m(message);
        if ((m.find("glCompileShader") != std::string::npos || m.find("glLinkProgram") != std::string::npos)
            && m.find("FAILED") != std::string::npos)
            ADD_FAILURE() << "GLSL error: " << m;
        if (severity <= osg::WARN) std::fputs(message, stderr);
    }
};
struct InstallHandler : public ::testing::Environment {
    void SetUp() override
    {
        osg::setNotifyLevel(osg::WARN);
        osg::setNotifyHandler(new ShaderErrorsFail);
    }
};
::testing::Environment* const installed = ::testing::AddGlobalTestEnvironment(new InstallHandler);
}
