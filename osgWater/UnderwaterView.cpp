#include <osgWater/UnderwaterView>
#include <osgWater/ScreenTriangle>
#include <osgWater/Shaders>
#include <osgWater/PassTable>
#include <osg/Depth>
#include <osg/CullFace>

using namespace osgWater;

UnderwaterView::UnderwaterView()
{
    // the cap is the first surface on its rays: drawn after everything else, over it
    _cap = makeScreenTriangle(-1.0f, "osgWater.nearPlaneCap");
    osg::StateSet* cap = _cap->getOrCreateStateSet();
    cap->setAttribute(createProgram("osgWater.cap", "screen.vert", "cap.frag"));
    cap->setAttributeAndModes(new osg::Depth(osg::Depth::ALWAYS, 0.0, 1.0, false));
    cap->setMode(GL_CULL_FACE, osg::StateAttribute::OFF);
    cap->setRenderBinDetails(renderBin(PASS_CAP), "RenderBin");

    // at the far plane, only where nothing was drawn (depth still clear)
    // (just inside the far plane: a fragment exactly on it may be clipped)
    _backdrop = makeScreenTriangle(1.0f - 1.0e-5f, "osgWater.underwaterBackdrop");
    osg::StateSet* bd = _backdrop->getOrCreateStateSet();
    bd->setAttribute(createProgram("osgWater.backdrop", "screen.vert", "backdrop.frag"));
    bd->setAttributeAndModes(new osg::Depth(osg::Depth::LEQUAL, 0.0, 1.0, false));
    bd->setMode(GL_CULL_FACE, osg::StateAttribute::OFF);
    bd->setRenderBinDetails(renderBin(PASS_BACKDROP), "RenderBin");
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
}
