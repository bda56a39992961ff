/* osgWater - natural water for OpenSceneGraph */
#ifndef OSGWATER_REFRACTIONCAMERA
#define OSGWATER_REFRACTIONCAMERA 1

#include "frame/PassCamera.h"

namespace osgWater {

//! Thesis §5.1: draws the far side of the water (the lake bed when the eye is above) with the
//! clip plane just beyond the crests, back faces culled (fig. 3: a subgraph that turns
//! GL_CULL_FACE off, thin geometry seen from both sides, is drawn whole), a widened field of view and,
//! optionally, the camera rotated about O (eq. 1-2) and moved back to the eye's apparent position
//! seen from under the water (WaterSettings::setRefractionCameraApparentEye). Writes colour and a
//! depth texture; the water shader's bottom search reads both.
//! With WaterSettings::VIRTUAL_VERTICES, from above the water: the eye's own view (no rotation),
//! each vertex drawn at its virtual vertex (the scene program's OSGWATER_VIRTUAL_VERTICES); for the
//! debug output (PassContext::truePositions) the colour target becomes a float one holding the true
//! place of what is drawn.
class OSGWATER_EXPORT RefractionCamera : public PassCamera
{
public:
    RefractionCamera(osg::Group* scene, osg::StateSet* sceneState, int width, int height);

    void update(const PassContext& ctx);
    //! Whether the last update drew virtual vertices.
    bool getVirtualVertices() const { return _virtualVertices; }

    void resizeGLObjectBuffers(unsigned int maxSize) override;
    void releaseGLObjects(osg::State* state = 0) const override;

protected:
    virtual ~RefractionCamera() {}
    //! Renders colour into `texture` from the next frame on (the attachment's FBO is remade).
    void renderColorInto(osg::Texture2D* texture);

    osg::ref_ptr<osg::Texture2D> _shownColor, _truePositions; // the colour target, and the debug one (made on demand)
    bool _virtualVertices = false;
};

}

#endif
