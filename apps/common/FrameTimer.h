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

double median(std::vector<double> v);
//! The median over consecutive blocks of `block` frame times of each block's mean: work done every
//! few frames (caustics rendered again only when the waves moved them) counts at its average cost,
//! which a median of single frames would hide, while a slow block still cannot sway the result.
double medianOfBlockMeans(const std::vector<double>& ms, size_t block);

//! Puts the viewer's camera off-screen (osgWater::setUpOffscreen) or in a window.
bool setUpViewer(osgViewer::Viewer& viewer, bool headless, int width, int height);

}
