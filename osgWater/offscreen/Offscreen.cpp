// Rendering with no window: a pbuffer context whose camera draws into an FBO (the only set-up that
// Mesa's software path runs without X errors), and the frame read back from the FBO's texture.
#include <algorithm>
#include <osgWater/Offscreen>
#include "offscreen/TextureReadback.h"
#include <OpenThreads/Thread>
#include <osg/GL>
#include <osg/Texture2D>
#include <cstdlib>

namespace osgWater {

namespace {
const char* const kNoContext = "cannot create an off-screen (pbuffer) GL context";
}

osg::ref_ptr<osg::GraphicsContext> createOffscreenContext(int width, int height, std::string* error)
{
    if (!std::getenv("DISPLAY")) {
        if (error) *error = std::string(kNoContext) + ": DISPLAY is not set (on a machine without a display, run under xvfb-run)";
        return nullptr;
    }
    osg::ref_ptr<osg::GraphicsContext::Traits> traits = new osg::GraphicsContext::Traits;
    traits->readDISPLAY();
    traits->setUndefinedScreenDetailsToDefaultScreen();
    traits->width = width;
    traits->height = height;
    traits->red = traits->green = traits->blue = traits->alpha = 8;
    traits->depth = 24;
    traits->pbuffer = true;
    traits->doubleBuffer = false;
    for (int attempt = 0; attempt < 4; ++attempt) {
        osg::ref_ptr<osg::GraphicsContext> gc = osg::GraphicsContext::createGraphicsContext(traits.get());
        if (gc.valid() && gc->realize()) return gc;
        OpenThreads::Thread::microSleep(250000);
    }
    if (error) *error = std::string(kNoContext) + " on DISPLAY=" + std::getenv("DISPLAY");
    return nullptr;
}

bool setUpOffscreen(osgViewer::Viewer& viewer, int width, int height, std::string* error)
{
    osg::ref_ptr<osg::GraphicsContext> gc = createOffscreenContext(width, height, error);
    if (!gc.valid()) return false;
    osg::Camera* camera = viewer.getCamera();
    camera->setGraphicsContext(gc.get());
    camera->setViewport(0, 0, width, height);
    // an FBO, not the pbuffer itself: Mesa's software path pushes a drawn front buffer to the X
    // drawable (MIT-SHM PutImage), which a pbuffer rejects with BadMatch
    camera->setRenderTargetImplementation(osg::Camera::FRAME_BUFFER_OBJECT);
    osg::Texture2D* target = new osg::Texture2D;
    target->setTextureSize(width, height);
    target->setInternalFormat(GL_SRGB8_ALPHA8); // display values, as a window's
    target->setFilter(osg::Texture::MIN_FILTER, osg::Texture::NEAREST);
    target->setFilter(osg::Texture::MAG_FILTER, osg::Texture::NEAREST);
    camera->attach(osg::Camera::COLOR_BUFFER, target);
    camera->attach(osg::Camera::DEPTH_BUFFER, GL_DEPTH_COMPONENT24);
    camera->setProjectionMatrixAsPerspective(45.0, double(width) / double(height), 0.1, 2000.0);
    viewer.setThreadingModel(osgViewer::ViewerBase::SingleThreaded);
    viewer.setReleaseContextAtEndOfFrameHint(false); // releasing a pbuffer's context each frame is an X BadMatch
    return true;
}

osg::ref_ptr<osg::Image> renderOffscreenFrame(osgViewer::Viewer& viewer, double time)
{
    osg::Camera* camera = viewer.getCamera();
    const auto colour = camera->getBufferAttachmentMap().find(osg::Camera::COLOR_BUFFER);
    if (colour == camera->getBufferAttachmentMap().end() || !colour->second._texture.valid() || !camera->getGraphicsContext())
        return nullptr;
    viewer.frame(time);
    // the context stays current: the off-screen viewer does not release it between frames
    return detail::readTexture(camera->getGraphicsContext(), colour->second._texture.get(), GL_RGB, GL_UNSIGNED_BYTE);
}

namespace detail {

osg::ref_ptr<osg::Image> readTexture(osg::GraphicsContext* gc, osg::Texture* texture, GLenum format, GLenum type, int level)
{
    gc->makeCurrent();
    osg::Texture::TextureObject* to = texture ? texture->getTextureObject(gc->getState()->getContextID()) : nullptr;
    if (!to) return nullptr;
    osg::ref_ptr<osg::Image> image = new osg::Image;
    image->allocateImage(std::max(texture->getTextureWidth() >> level, 1), std::max(texture->getTextureHeight() >> level, 1),
                         1, format, type);
    GLint bound = 0; // restored: osg::State believes it is still bound
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
    glBindTexture(GL_TEXTURE_2D, to->id());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTexImage(GL_TEXTURE_2D, level, format, type, image->data());
    glBindTexture(GL_TEXTURE_2D, GLuint(bound));
    return image;
}

}

}
