#include "FrameTimer.h"
#include <osg/GL>
#include <OpenThreads/Thread>
#include <osg/Texture2D>
#include <algorithm>
#include <iostream>

namespace osgWaterApps {

void FinishFrame::operator()(osg::RenderInfo&) const
{
    glFinish();
}

osg::ref_ptr<osg::Image> readTexture(osg::GraphicsContext* gc, osg::Texture* texture)
{
    gc->makeCurrent(); // stays current: the headless viewer does not release it between frames
    osg::Texture::TextureObject* to = texture->getTextureObject(gc->getState()->getContextID());
    if (!to) return nullptr;
    const bool depth = texture->getInternalFormat() == GL_DEPTH_COMPONENT24 || texture->getInternalFormat() == GL_DEPTH_COMPONENT;
    osg::ref_ptr<osg::Image> image = new osg::Image;
    image->allocateImage(texture->getTextureWidth(), texture->getTextureHeight(), 1, depth ? GL_LUMINANCE : GL_RGB,
                         GL_UNSIGNED_BYTE);
    GLint bound = 0; // restore it: osg::State believes it is still bound
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
    glBindTexture(GL_TEXTURE_2D, to->id());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTexImage(GL_TEXTURE_2D, 0, depth ? GL_DEPTH_COMPONENT : GL_RGB, GL_UNSIGNED_BYTE, image->data());
    glBindTexture(GL_TEXTURE_2D, GLuint(bound));
    return image;
}

osg::ref_ptr<osg::Image> captureFrame(osgViewer::Viewer& viewer, double t)
{
    viewer.frame(t);
    osg::Camera* camera = viewer.getCamera();
    auto it = camera->getBufferAttachmentMap().find(osg::Camera::COLOR_BUFFER);
    if (it == camera->getBufferAttachmentMap().end() || !it->second._texture.valid()) return nullptr;
    return readTexture(camera->getGraphicsContext(), it->second._texture.get());
}

double median(std::vector<double> v)
{
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double medianOfBlockMeans(const std::vector<double>& ms, size_t block)
{
    block = std::max<size_t>(block, 1);
    std::vector<double> means;
    for (size_t i = 0; i + block <= ms.size(); i += block) {
        double sum = 0.0;
        for (size_t j = i; j < i + block; ++j) sum += ms[j];
        means.push_back(sum / double(block));
    }
    return means.empty() ? median(ms) : median(means);
}

osg::ref_ptr<osg::GraphicsContext> createPbuffer(int width, int height)
{
    osg::ref_ptr<osg::GraphicsContext::Traits> traits = new osg::GraphicsContext::Traits;
    traits->readDISPLAY();
    traits->setUndefinedScreenDetailsToDefaultScreen();
    traits->width = width;
    traits->height = height;
    traits->red = traits->green = traits->blue = traits->alpha = 8;
    traits->depth = 24;
    traits->pbuffer = true;
    traits->doubleBuffer = false;
    // several processes creating pbuffers on one Xvfb at once (ctest -j) now and then get a
    // transient GLX failure: try a few times before giving up
    for (int attempt = 0; attempt < 4; ++attempt) {
        osg::ref_ptr<osg::GraphicsContext> gc = osg::GraphicsContext::createGraphicsContext(traits.get());
        if (gc.valid() && gc->realize()) return gc;
        OpenThreads::Thread::microSleep(250000);
    }
    return nullptr;
}

bool setUpViewer(osgViewer::Viewer& viewer, bool headless, int width, int height)
{
    osg::Camera* camera = viewer.getCamera();
    if (headless) {
        osg::ref_ptr<osg::GraphicsContext> gc = createPbuffer(width, height);
        if (!gc.valid()) {
            std::cerr << "error: cannot create an off-screen (pbuffer) GL context; run under xvfb-run "
                         "on a machine without a display" << std::endl;
            return false;
        }
        camera->setGraphicsContext(gc.get());
        camera->setViewport(0, 0, width, height);
        // draw into an FBO, not the pbuffer itself: Mesa's software path pushes a drawn front
        // buffer to the X drawable (MIT-SHM PutImage), which a pbuffer rejects with BadMatch
        camera->setRenderTargetImplementation(osg::Camera::FRAME_BUFFER_OBJECT);
        osg::Texture2D* target = new osg::Texture2D;
        target->setTextureSize(width, height);
        target->setInternalFormat(GL_SRGB8_ALPHA8); // display values, as a window's; the glow adds in linear light
        target->setFilter(osg::Texture::MIN_FILTER, osg::Texture::NEAREST);
        target->setFilter(osg::Texture::MAG_FILTER, osg::Texture::NEAREST);
        camera->attach(osg::Camera::COLOR_BUFFER, target);
        camera->attach(osg::Camera::DEPTH_BUFFER, GL_DEPTH_COMPONENT24);
        viewer.setThreadingModel(osgViewer::ViewerBase::SingleThreaded);
        viewer.setReleaseContextAtEndOfFrameHint(false); // releasing a pbuffer context each frame is an X BadMatch
    } else {
        viewer.setUpViewInWindow(50, 50, width, height);
    }
    camera->setProjectionMatrixAsPerspective(45.0, double(width) / double(height), 0.1, 2000.0);
    return true;
}

}
