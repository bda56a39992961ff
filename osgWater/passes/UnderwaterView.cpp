#include "passes/UnderwaterView.h"
#include "shaders/ProgramLibrary.h"
#include "frame/ScreenTriangle.h"
#include "shaders/Shaders.h"
#include "frame/PassTable.h"
#include "frame/PassMath.h"
#include "frame/PassCamera.h"
#include <osg/Depth>
#include <osg/CullFace>

using namespace osgWater;

// At draw time the projection holds the near plane OSG computed for this frame: a cap whose near
// plane cannot reach the water would run its full-screen shader only to discard every pixel.
class UnderwaterView::CapSkip : public osg::Drawable::DrawCallback
{
public:
    explicit CapSkip(const UnderwaterView* owner) : _owner(owner) {}
    void drawImplementation(osg::RenderInfo& ri, const osg::Drawable* drawable) const override
    {
        const osg::State& state = *ri.getState();
        if (_owner->capNeeded(state.getModelViewMatrix(), state.getProjectionMatrix())) {
            ++_owner->_capDraws;
            _owner->_capMeter->begin(ri);
            drawable->drawImplementation(ri);
            _owner->_capMeter->end(ri);
        } else {
            ++_owner->_capSkips;
        }
    }
private:
    const UnderwaterView* _owner; // owns the cap, so outlives it
};

UnderwaterView::UnderwaterView(ProgramLibrary& programs)
{
    // the cap is the first surface on its rays: drawn after everything else, over it
    _cap = makeScreenTriangle(-1.0f, "osgWater.nearPlaneCap");
    osg::StateSet* cap = _cap->getOrCreateStateSet();
    cap->setAttribute(programs.get("osgWater.cap", "screen.vert", "cap.frag"));
    cap->setAttributeAndModes(new osg::Depth(osg::Depth::ALWAYS, 0.0, 1.0, false));
    cap->setMode(GL_CULL_FACE, osg::StateAttribute::OFF);
    setUpPassBin(cap, PASS_CAP);
    _capMeter = new PassMeter; // begun and ended by CapSkip when it draws
    _cap->getDrawable(0)->setDrawCallback(new CapSkip(this));

    // at the far plane, only where nothing was drawn (depth still clear)
    // (just inside the far plane: a fragment exactly on it may be clipped)
    _backdrop = makeScreenTriangle(1.0f - 1.0e-5f, "osgWater.underwaterBackdrop");
    osg::StateSet* bd = _backdrop->getOrCreateStateSet();
    bd->setAttribute(programs.get("osgWater.backdrop", "screen.vert", "backdrop.frag"));
    bd->setAttributeAndModes(new osg::Depth(osg::Depth::LEQUAL, 0.0, 1.0, false));
    bd->setMode(GL_CULL_FACE, osg::StateAttribute::OFF);
    setUpPassBin(bd, PASS_BACKDROP);
    _backdropMeter = new PassMeter;
    _backdropMeter->attach(_backdrop->getDrawable(0));
    setTimingEnabled(false);
}

void UnderwaterView::setTimingEnabled(bool on)
{
    _capMeter->setEnabled(on);
    _backdropMeter->setEnabled(on);
}

void UnderwaterView::setWaveBand(double level, double waveBound)
{
    _level = level;
    _waveBound = waveBound;
}

bool UnderwaterView::capNeeded(const osg::Matrixd& modelView, const osg::Matrixd& projection) const
{
    return !_skipping || nearPlaneReachesWater(modelView, projection, _level, _waveBound);
}

void UnderwaterView::resizeGLObjectBuffers(unsigned int maxSize)
{
    _cap->resizeGLObjectBuffers(maxSize);
    _backdrop->resizeGLObjectBuffers(maxSize);
}

void UnderwaterView::releaseGLObjects(osg::State* state) const
{
    _cap->releaseGLObjects(state);
    _backdrop->releaseGLObjects(state);
    for (const PassMeter* m : { _capMeter.get(), _backdropMeter.get() }) m->releaseGLObjects(state);
}
