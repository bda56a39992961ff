/* osgWater - natural water for OpenSceneGraph */
#ifndef OSGWATER_REFLECTIONCAMERA
#define OSGWATER_REFLECTIONCAMERA 1

#include "frame/PassCamera.h"

namespace osgWater {

//! Thesis §5.2: the main camera mirrored in the water plane, drawing the eye's side of the scene
//! (clip plane just beyond the wave troughs), with a widened field of view, into a colour texture
//! and a depth texture (the reflected rays' search reads it).
class OSGWATER_EXPORT ReflectionCamera : public PassCamera
{
public:
    ReflectionCamera(osg::Group* scene, osg::StateSet* sceneState, int width, int height);

    //! Sets this frame's mirrored view, extended projection and clip plane.
    void update(const PassContext& ctx);

    //! Local frame -> clip space of this pass, as used by the water shader's lookups.
    osg::Matrixd getViewProjection() const { return getViewMatrix() * getProjectionMatrix(); }

protected:
    virtual ~ReflectionCamera() {}
};

}

#endif
