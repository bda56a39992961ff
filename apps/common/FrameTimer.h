// Frame timing and screenshots shared by the demo applications.
#pragma once
#include <osgViewer/Viewer>
#include <osg/Image>
#include <string>
#include <vector>

namespace osgWaterApps {

//! Finishes the GL work of each frame, so wall time measures the GPU too (final draw callback).
class FinishFrame : public osg::Camera::DrawCallback
{
public:
    void operator()(osg::RenderInfo& renderInfo) const override;
};

//! Renders one more frame at time t and reads it back from the headless camera's colour texture.
//! A texture of a headless viewer's context as an 8-bit image (depth textures as luminance).
osg::ref_ptr<osg::Image> readTexture(osg::GraphicsContext* gc, osg::Texture* texture);
osg::ref_ptr<osg::Image> captureFrame(osgViewer::Viewer& viewer, double t);
//! (Windows use osgViewer::ScreenCaptureHandler instead.)

double median(std::vector<double> v);
//! The median over consecutive blocks of `block` frame times of each block's mean: work done every
//! few frames (caustics rendered again only when the waves moved them) counts at its average cost,
//! which a median of single frames would hide, while a slow block still cannot sway the result.
double medianOfBlockMeans(const std::vector<double>& ms, size_t block);

//! A pbuffer context of this size (needs an X display: Xvfb on a headless machine), or nullptr.
osg::ref_ptr<osg::GraphicsContext> createPbuffer(int width, int height);

//! Puts the viewer's camera on a pbuffer (headless) or in a window.
bool setUpViewer(osgViewer::Viewer& viewer, bool headless, int width, int height);

}
