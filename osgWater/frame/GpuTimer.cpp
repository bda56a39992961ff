#include "frame/GpuTimer.h"
#include <osg/GLExtensions>
#include <osg/RenderInfo>
#include <osg/State>
#include <osg/Notify>

using namespace osgWater;

#ifndef GL_TIMESTAMP
#define GL_TIMESTAMP 0x8E28
#endif
#ifndef GL_QUERY_RESULT_AVAILABLE
#define GL_QUERY_RESULT_AVAILABLE 0x8867
#endif
#ifndef GL_QUERY_RESULT
#define GL_QUERY_RESULT 0x8866
#endif

namespace {
struct Begin : public osg::Camera::DrawCallback {
    osg::observer_ptr<GpuTimer> timer;
    explicit Begin(GpuTimer* t) : timer(t) {}
    void operator()(osg::RenderInfo& ri) const override { if (osg::ref_ptr<GpuTimer> t = timer.get()) t->begin(ri); }
};
struct End : public osg::Camera::DrawCallback {
    osg::observer_ptr<GpuTimer> timer;
    explicit End(GpuTimer* t) : timer(t) {}
    void operator()(osg::RenderInfo& ri) const override { if (osg::ref_ptr<GpuTimer> t = timer.get()) t->end(ri); }
};
struct TimedDraw : public osg::Drawable::DrawCallback {
    osg::observer_ptr<GpuTimer> timer;
    explicit TimedDraw(GpuTimer* t) : timer(t) {}
    void drawImplementation(osg::RenderInfo& ri, const osg::Drawable* drawable) const override
    {
        osg::ref_ptr<GpuTimer> t = timer.get();
        if (t) t->begin(ri);
        drawable->drawImplementation(ri);
        if (t) t->end(ri);
    }
};
}

GpuTimer::GpuTimer() : _ms(-1.0) {}

void GpuTimer::attach(osg::Drawable* drawable)
{
    drawable->setDrawCallback(new TimedDraw(this));
}

void GpuTimer::setEnabled(bool on)
{
    if (!on) _ms = -1.0;
    _enabled = on;
}

void GpuTimer::attach(osg::Camera* camera)
{
    camera->setInitialDrawCallback(new Begin(this));
    camera->setFinalDrawCallback(new End(this));
}

void GpuTimer::attach(osg::Camera* first, osg::Camera* last)
{
    first->setInitialDrawCallback(new Begin(this));
    last->setFinalDrawCallback(new End(this));
}

void GpuTimer::detach(osg::Camera* camera)
{
    camera->setInitialDrawCallback(nullptr);
    camera->setFinalDrawCallback(nullptr);
}

void GpuTimer::begin(osg::RenderInfo& ri)
{
    if (!_enabled) return;
    Query& q = _queries[ri.getContextID()];
    if (q.failed) return;
    osg::GLExtensions* ext = ri.getState()->get<osg::GLExtensions>();
    if (!ext || !ext->isTimerQuerySupported || !ext->glGenQueries || !ext->glQueryCounter) {
        OSG_NOTICE << "osgWater::GpuTimer: no GL timer queries here, pass times are not measured" << std::endl;
        q.failed = true;
        return;
    }
    if (q.ids[0] == 0) ext->glGenQueries(2, q.ids);
    if (q.pending) {
        GLint available = 0;
        ext->glGetQueryObjectiv(q.ids[1], GL_QUERY_RESULT_AVAILABLE, &available);
        if (!available) return; // last frame's result not there yet: skip this frame's measurement
        GLuint64 start = 0, stop = 0;
        ext->glGetQueryObjectui64v(q.ids[0], GL_QUERY_RESULT, &start);
        ext->glGetQueryObjectui64v(q.ids[1], GL_QUERY_RESULT, &stop);
        _ms = stop > start ? double(stop - start) * 1.0e-6 : 0.0;
        q.pending = false;
    }
    ext->glQueryCounter(q.ids[0], GL_TIMESTAMP);
    q.active = true;
}

void GpuTimer::end(osg::RenderInfo& ri)
{
    Query& q = _queries[ri.getContextID()];
    if (!q.active) return;
    osg::GLExtensions* ext = ri.getState()->get<osg::GLExtensions>();
    ext->glQueryCounter(q.ids[1], GL_TIMESTAMP);
    q.active = false;
    q.pending = true;
}
