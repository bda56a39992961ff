#include "FrameTimer.h"
#include <osgWater/Offscreen>
#include <osg/GL>
#include <algorithm>
#include <iostream>

namespace osgWaterApps {

void FinishFrame::operator()(osg::RenderInfo&) const
{
    glFinish();
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

bool setUpViewer(osgViewer::Viewer& viewer, bool headless, int width, int height)
{
    osg::Camera* camera = viewer.getCamera();
    if (headless) {
        std::string error;
        if (!osgWater::setUpOffscreen(viewer, width, height, &error)) {
            std::cerr << "error: " << error << std::endl;
            return false;
        }
    } else {
        viewer.setUpViewInWindow(50, 50, width, height);
    }
    camera->setProjectionMatrixAsPerspective(45.0, double(width) / double(height), 0.1, 2000.0);
    return true;
}

}
