// The renderer's side of the measurement: a headless viewer drawing into a float target, from
// which the water shader's debug outputs (bottom estimate, reflection lookup, Fresnel weight), the
// colour and the caustics texture are read back for one view.
#pragma once
#include "Metrics.h"
#include <osgWater/WaterNode>
#include <osgViewer/Viewer>
#include <string>

namespace bench {

class Probe
{
public:
    //! A pbuffer viewer of this size (false from ok() with the reason in why()).
    Probe(int width, int height);
    //! Captures with an existing headless viewer: its colour attachment is swapped for a float
    //! target while capturing and put back afterwards (one context: two viewers sharing a scene
    //! graph on two contexts raised GL errors in Mesa).
    explicit Probe(osgViewer::Viewer* shared);
    bool ok() const { return _target.valid(); }
    const std::string& why() const { return _why; }
    osgViewer::Viewer* viewer() { return _viewer; }
    osg::Camera* camera() { return _viewer->getCamera(); }
    osg::GraphicsContext* context() { return _gc.get(); }

    //! Renders the view at time t once per debug output and reads everything back.
    Estimate capture(osgWater::WaterNode& water, double t);
    //! The caustics texture of the last capture (float, red = value), or null without caustics.
    osg::ref_ptr<osg::Image> readCaustics(osgWater::WaterNode& water);
    //! A float RGBA copy of any texture of this context.
    osg::ref_ptr<osg::Image> read(osg::Texture2D* texture);

private:
    std::string _why;
    osg::ref_ptr<osg::GraphicsContext> _gc;
    osg::ref_ptr<osgViewer::Viewer> _owned;
    osgViewer::Viewer* _viewer = nullptr;
    osg::ref_ptr<osg::Texture2D> _target;
    bool _shared = false;
};

}
