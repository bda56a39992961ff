#include "node/WaterNodeImpl.h"
#include "offscreen/TextureReadback.h"
#include "Probe.h"
#include "../common/FrameTimer.h"
#include <osgWater/Offscreen>
#include <osg/GL>
#include <utility>

namespace bench {

namespace {

osg::Texture2D* floatTarget(int width, int height)
{
    osg::Texture2D* t = new osg::Texture2D;
    t->setTextureSize(width, height);
    t->setInternalFormat(GL_RGBA32F_ARB);
    t->setSourceFormat(GL_RGBA);
    t->setSourceType(GL_FLOAT);
    t->setFilter(osg::Texture::MIN_FILTER, osg::Texture::NEAREST);
    t->setFilter(osg::Texture::MAG_FILTER, osg::Texture::NEAREST);
    return t;
}

}

Probe::Probe(osgViewer::Viewer* shared) : _viewer(shared), _shared(true)
{
    _gc = shared->getCamera()->getGraphicsContext();
    const osg::Viewport* vp = shared->getCamera()->getViewport();
    if (!_gc.valid() || !vp) {
        _why = "the viewer has no context";
        return;
    }
    _target = floatTarget(int(vp->width()), int(vp->height()));
}

Probe::Probe(int width, int height)
{
    _gc = osgWater::createOffscreenContext(width, height, &_why);
    if (!_gc.valid()) return;
    _owned = new osgViewer::Viewer;
    _viewer = _owned.get();
    _viewer->setThreadingModel(osgViewer::ViewerBase::SingleThreaded);
    _viewer->setReleaseContextAtEndOfFrameHint(false);
    osg::Camera* cam = _viewer->getCamera();
    cam->setGraphicsContext(_gc.get());
    cam->setViewport(0, 0, width, height);
    cam->setRenderTargetImplementation(osg::Camera::FRAME_BUFFER_OBJECT);
    _target = floatTarget(width, height);
    cam->attach(osg::Camera::COLOR_BUFFER, _target.get());
    cam->attach(osg::Camera::DEPTH_BUFFER, GL_DEPTH_COMPONENT24);
    cam->setProjectionMatrixAsPerspective(45.0, double(width) / double(height), 0.1, 2000.0);
}

osg::ref_ptr<osg::Image> Probe::read(osg::Texture2D* texture)
{
    // the context stays current: the viewer does not release it between frames
    return osgWater::detail::readTexture(_gc.get(), texture, GL_RGBA, GL_FLOAT);
}

Estimate Probe::capture(osgWater::WaterNode& water, double t)
{
    Estimate e;
    osg::ref_ptr<osg::Texture> saved;
    if (_shared) {
        auto it = camera()->getBufferAttachmentMap().find(osg::Camera::COLOR_BUFFER);
        if (it != camera()->getBufferAttachmentMap().end()) saved = it->second._texture;
        camera()->attach(osg::Camera::COLOR_BUFFER, _target.get());
        camera()->dirtyAttachmentMap(); // the FBO is remade on the next frame
    }
    const osgWater::DebugOutput before = water.getDebugOutput();
    water.setDebugOutput(osgWater::DEBUG_NONE);
    _gc->makeCurrent(); // another viewer's context may be current
    _viewer->frame(t);
    _viewer->frame(t); // settle: passes sized and caustics chosen on the first frame
    e.color = read(_target.get());
    // one frame per debug output, read back into its image
    const std::pair<osgWater::DebugOutput, osg::ref_ptr<osg::Image> Estimate::*> outputs[] = {
        { osgWater::DEBUG_BOTTOM_HIT, &Estimate::bottom },     { osgWater::DEBUG_REFLECTION_LOOKUP, &Estimate::reflection },
        { osgWater::DEBUG_FRESNEL, &Estimate::fresnel },       { osgWater::DEBUG_DRAWN_SURFACE, &Estimate::drawn },
        { osgWater::DEBUG_SURFACE, &Estimate::shaded },        { osgWater::DEBUG_WORK, &Estimate::work },
        { osgWater::DEBUG_SLOPES, &Estimate::slopes } };
    for (const auto& [output, image] : outputs) {
        water.setDebugOutput(output);
        _viewer->frame(t);
        e.*image = read(_target.get());
    }
    water.setDebugOutput(before);
    if (saved.valid()) {
        camera()->attach(osg::Camera::COLOR_BUFFER, saved.get());
        camera()->dirtyAttachmentMap();
    }

    // the water is not transformed: its local frame is the world's
    e.eye = osg::Matrixd::inverse(camera()->getViewMatrix()).getTrans();
    e.view = camera()->getViewMatrix();
    e.projection = camera()->getProjectionMatrix();
    e.pixelsPerRadian = camera()->getProjectionMatrix()(1, 1) * 0.5 * camera()->getViewport()->height();
    e.level = water.getSurface()->getLevel();
    e.airIOR = water.getSettings()->getAirIOR();
    e.waterIOR = water.getSettings()->getWaterIOR();
    e.clearance = water.getSurface()->getMaxAmplitude() + water.getSettings()->getClipOffset();
    if (osgWater::ViewPasses* p = osgWater::internals(water).getViewPasses(camera())) {
        e.eyeBelow = p->getEyeBelow();
        e.refractionView = p->getRefractionCamera()->getViewMatrix();
        e.refractionEye = osg::Matrixd::inverse(e.refractionView).getTrans();
        e.reflectionMVP = p->getReflectionCamera()->getViewProjection();
        auto it = p->getReflectionCamera()->getBufferAttachmentMap().find(osg::Camera::COLOR_BUFFER);
        if (it != p->getReflectionCamera()->getBufferAttachmentMap().end() && it->second._texture.valid())
            e.reflectionSize = it->second._texture->getTextureWidth();
    }
    return e;
}

osg::ref_ptr<osg::Image> Probe::readCaustics(osgWater::WaterNode& water)
{
    osgWater::CausticsCamera* c = osgWater::internals(water).getCausticsCamera();
    // per pixel (procedural) the caustics are made in the scene program: no texture holds them
    if (!c || !water.getSettings()->getCausticsEnabled() || c->getLighting().procedural) return nullptr;
    osg::ref_ptr<osg::Image> img = read(c->getCausticsTexture());
    const float scale = c->getGather()->getValueScale(); // 16-bit targets store value / scale
    if (img.valid() && scale != 1.0f)
        for (int y = 0; y < img->t(); ++y)
            for (int x = 0; x < img->s(); ++x) reinterpret_cast<float*>(img->data(x, y))[0] *= scale;
    return img;
}

}
