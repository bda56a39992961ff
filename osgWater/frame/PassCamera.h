/* osgWater - natural water for OpenSceneGraph */
#ifndef OSGWATER_PASSCAMERA
#define OSGWATER_PASSCAMERA 1

#include <osgWater/Export>
#include "frame/DrawNodes.h"
#include "frame/PassTable.h"
#include "frame/SceneLighting.h"
#include <osg/Camera>
#include <osg/Plane>
#include <osg/Texture2D>

namespace osgWater {

class WaterSettings;

//! A square texture target for a pass (edges clamped; linear or nearest filtering).
OSGWATER_EXPORT osg::Texture2D* makeTargetTexture(int size, GLenum internalFormat, GLenum format, GLenum type,
                                                  bool linear);
//! The same, width x height.
OSGWATER_EXPORT osg::Texture2D* makeTargetTexture(int width, int height, GLenum internalFormat, GLenum format,
                                                  GLenum type, bool linear);
//! Makes `camera` the pre-render FBO pass `pass` of width x height pixels, drawn in the pass
//! table's order, with absolute matrices the kit sets itself (no near/far computation), and
//! marks it as a water pass (see isWaterPass).
OSGWATER_EXPORT void setUpPassTarget(osg::Camera* camera, int width, int height, PassId pass);
//! Puts what `ss` draws in the render bin of a view-stage row (underlay or overlay), a bin of the
//! view's render stage however the WaterNode's parents nest bins.
OSGWATER_EXPORT void setUpPassBin(osg::StateSet* ss, PassId pass);

//! True for a camera set up by setUpPassTarget: a pass of some WaterNode. A WaterNode culled
//! by one is inside another water's pass and draws itself as a guest (no passes of its own).
OSGWATER_EXPORT bool isWaterPass(const osg::Camera* camera);
//! Whether `camera` draws the scene's colours: a view (not a water pass), or the environment,
//! reflection or refraction pass; not the sun's depth, the photons, nor the glow's occluders.
OSGWATER_EXPORT bool drawsSceneColours(const osg::Camera* camera);
//! Whether `camera` can see the sky: it draws the scene's colours, and if it is a PassCamera its
//! keep plane keeps the zenith's side (a refraction pass from above keeps only what lies under the
//! water, where no ray of it meets the sky).
OSGWATER_EXPORT bool seesTheSky(const osg::Camera* camera);

//! Releases a pass camera's GL objects on `state` (all contexts when null): its render stage (FBO,
//! renderbuffers), its StateSet and the textures it renders into.
OSGWATER_EXPORT void releasePassGLObjects(const osg::Camera* camera, osg::State* state);
//! Resizes the same objects' per-context buffers.
OSGWATER_EXPORT void resizePassGLObjectBuffers(osg::Camera* camera, unsigned int maxSize);

//! What a pass needs to know about the view it serves, gathered once per view and frame.
struct OSGWATER_EXPORT PassContext {
    osg::Matrixd view;            //!< water-local frame -> main eye space
    osg::Matrixd projection;      //!< the main camera's projection
    osg::BoundingSphere scene;    //!< bound of the reflected/refracted scene (local frame)
    double level = 0.0;           //!< water plane z
    double clearance = 0.0;       //!< wave amplitude + clip offset: the planes clear the crests
    double fovExtension = 1.5;
    bool eyeBelow = false;
    bool eyeAmongWaves = false;   //!< the eye within the waves' height of the level: a crest can
                                  //!< stand above all the refraction pass sees
    bool truePositions = false;   //!< the debug output shows the refracted ray's point: a refraction pass
                                  //!< drawing virtual vertices writes their true places (a float target)
    osg::Vec4 clearColor;         //!< the view's background as linear light (the view's own is a display value)
    const WaterSettings* settings = nullptr;
};

//! A render-to-texture pre-render camera that draws the water's scene (the WaterNode's children)
//! clipped by one plane. It owns only its set-up (FBO, attachments, clip plane, culling plane);
//! the matrices come from free functions in PassMath, the lighting from SceneLighting.
class OSGWATER_EXPORT PassCamera : public osg::Camera
{
public:
    //! `scene`: the group whose children are drawn (its own traverse is bypassed); `sceneStates`:
    //! pushed above the children (the kit's scene program first). No colour target: a pass that
    //! needs one calls attachColorTexture().
    PassCamera(osg::Group* scene, std::initializer_list<osg::StateSet*> sceneStates, int width, int height,
               PassId pass);

    //! Keep the side a x + b y + c z + d >= 0 of this local plane: it clips (gl_ClipDistance[0])
    //! and culls (subgraphs wholly on the other side are never traversed).
    void setKeepPlane(const osg::Plane& localPlane);
    const osg::Plane& getKeepPlane() const { return _keepPlane; }

    //! This frame's lighting in this pass's eye space, clipped by the keep plane (after the matrices).
    void applyLighting(const SceneLighting& lighting);
    //! Makes this a depth-only pass: its depth texture is the target, no colour, no colour clear.
    void setDepthOnly();

    osg::Texture2D* getColorTexture() const { return _color.get(); }
    //! The depth target a depth search reads (nullptr for a pass without one).
    osg::Texture2D* getDepthTexture() const { return _depth.get(); }
    //! The target's size in texels.
    int getTargetWidth() const { return _width; }
    int getTargetHeight() const { return _height; }
    PassId getPass() const { return _pass; }

    void resizeGLObjectBuffers(unsigned int maxSize) override;
    void releaseGLObjects(osg::State* state = 0) const override;

protected:
    virtual ~PassCamera() {}
    //! The colour target; `mipmapped`: with every mip level, made after each draw (a lookup that
    //! reads the target blurred).
    void attachColorTexture(bool mipmapped = false);
    //! A depth texture as the depth target, for a search in this pass's eye space.
    void attachDepthTexture();

    PassId _pass;
    int _width, _height;
    osg::Plane _keepPlane;
    osg::ref_ptr<DrawNodes> _draw;
    osg::ref_ptr<osg::Texture2D> _color, _depth;
};

}

#endif
