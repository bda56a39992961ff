/* osgWater - natural water for OpenSceneGraph */
#ifndef OSGWATER_GLOWPASSES
#define OSGWATER_GLOWPASSES 1

#include "frame/PassCamera.h"
#include "frame/PassMeter.h"
#include "passes/GlowBands.h"
#include <osgWater/WaterSurface>
#include <osg/Geode>
#include <osg/Scissor>
#include <osg/Viewport>
#include <osg/Vec4i>

namespace osgWater {

class ProgramLibrary;

//! Glow of the sun's highlight on the water, one view's worth (thesis §9.3, blurred on the GPU
//! instead of the thesis's CPU): (1) the highlight pow(max(0, R.E), e) x sun colour of the surface
//! alone, the scene only as depth (occluders), into a target of a fraction of the view's size;
//! (2, 3) separable Gaussian blur, horizontal then vertical; (4) added to the view's image.
class OSGWATER_EXPORT GlowPasses : public osg::Referenced
{
public:
    //! `scene`: the WaterNode (its children are the occluders); targets are width x height texels.
    GlowPasses(osg::Group* scene, osg::StateSet* sceneState, osg::StateSet* waterState, ProgramLibrary& programs,
               int width, int height, bool floatTargets);

    bool matches(int width, int height, bool floatTargets) const
    { return width == _width && height == _height && floatTargets == _float; }

    //! Can the sun's highlight be in this view? False when the sun is down, the eye under water, or
    //! the highlight's cone (flat-water mirror direction widened by twice the steepest wave slope
    //! and the width of pow(R.E, e) above 1/1024) lies outside the view frustum.
    static bool highlightInView(const PassContext& ctx, const WaterSurface& surface);
    //! The part of the view the highlight can reach, in normalised device coordinates (x0, y0, x1,
    //! y1): the highlight's cone projected, within the water's box projected; the whole view
    //! (-1, -1, 1, 1) when either reaches behind the eye.
    static osg::Vec4d highlightRect(const PassContext& ctx, const WaterSurface& surface);

    //! Aims the highlight pass at this frame's view and updates the blur and composite uniforms.
    //! With `confine`, the highlight pass draws only the texels highlightRect() and the blur can
    //! reach (a sub-viewport and sub-frustum: occluders outside it are culled), and the blur and
    //! the composite are scissored to the blurred rectangle of `viewport` (the view's); the image
    //! is the same.
    void update(const PassContext& ctx, WaterSurface* surface, const osg::Viewport& viewport, bool confine = true);
    //! The glow target's texels that can be non-zero this frame (x, y, width, height).
    const osg::Vec4i& getGlowTexels() const { return _glowTexels; }
    //! The view's pixels the composite may add to (the blurred reach, in the viewport).
    const osg::Scissor* getCompositeScissor() const { return _compositeScissor.get(); }

    //! The camera of a glow row of the pass table (highlight, blur x, blur y), or nullptr.
    osg::Camera* getPassCamera(PassId pass) const;
    //! The full-screen triangle that adds the glow to the view (PASS_GLOW_COMPOSITE).
    osg::Geode* getComposite() const { return _composite.get(); }

    osg::Camera* getHighlightCamera() const { return _highlight.get(); }
    osg::Texture2D* getHighlightTexture() const { return _highlightTex.get(); }
    //! The blurred glow that is added to the image.
    osg::Texture2D* getGlowTexture() const { return _blurTex[1].get(); }
    int getWidth() const { return _width; }
    int getHeight() const { return _height; }

    //! GPU times, ms (negative until measured or while timing is off): the highlight pass, the two
    //! blur passes together, the composite.
    PassMeasure getHighlightMeasure() const { return _highlightMeter->getMeasure(); }
    PassMeasure getBlurMeasure() const { return _blurMeter->getMeasure(); }
    PassMeasure getCompositeMeasure() const { return _compositeMeter->getMeasure(); }
    void setTimingEnabled(bool on);

    //! Gaussian weights w_0..w_r of a blur of half-width `radius` texels (sigma = radius / 2),
    //! normalised so that w_0 + 2 sum w_i = 1.
    static std::vector<float> blurWeights(float radius);

    void resizeGLObjectBuffers(unsigned int maxSize);
    void releaseGLObjects(osg::State* state) const;

protected:
    virtual ~GlowPasses() {}
    void setBlurWeights(const std::vector<float>& weights);
    osg::Camera* makeBlurCamera(osg::Texture2D* input, osg::Texture2D* output, const osg::Vec2f& step, PassId pass,
                                osg::Geode* screen);

    int _width, _height;
    bool _float;
    float _radius = -1.0f; // the radius the blur weights were made for
    osg::ref_ptr<WaterSurface> _surface;
    osg::ref_ptr<osg::Camera> _highlight, _blur[2];
    osg::ref_ptr<osg::Texture2D> _highlightTex, _blurTex[2];
    osg::ref_ptr<osg::StateSet> _occluderState, _glowState, _blurState;
    osg::ref_ptr<osg::Geode> _composite;
    osg::ref_ptr<GlowBands> _bands; // where the composite adds the glow
    osg::ref_ptr<DrawNodes> _highlightDraw;
    osg::ref_ptr<osg::Scissor> _blurScissor, _compositeScissor;
    osg::Vec4i _glowTexels;
    osg::ref_ptr<PassMeter> _highlightMeter, _blurMeter, _compositeMeter;
};

}

#endif
