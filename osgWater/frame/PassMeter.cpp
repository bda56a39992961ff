#include "frame/PassMeter.h"
#include <osg/GLExtensions>
#include <osg/RenderInfo>
#include <osg/State>
#include <osg/Notify>
#include "frame/QueryNames.h"
#include <algorithm>

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
#ifndef GL_FRAGMENT_SHADER_INVOCATIONS
#define GL_FRAGMENT_SHADER_INVOCATIONS 0x82F4
#endif

namespace {
// per context, whether a meter's fragment query is active there: GL allows one query of a kind at
// a time, and the meters of passes drawn inside another's span must not begin a second
int& countingOn(unsigned int contextID)
{
    static osg::buffered_value<int> counting;
    return counting[contextID];
}

// per context, whether it counts fragment shader invocations (0: not asked yet, 1 yes, 2 no)
bool countsFragments(osg::GLExtensions& ext, unsigned int contextID)
{
    static osg::buffered_value<int> counts;
    int& c = counts[contextID];
    if (c == 0) {
        const bool yes = ext.glBeginQuery && ext.glEndQuery &&
                         osg::isGLExtensionOrVersionSupported(contextID, "GL_ARB_pipeline_statistics_query", 4.6f);
        if (!yes) OSG_NOTICE << "osgWater::PassMeter: no pipeline statistics queries here, fragments are not counted" << std::endl;
        c = yes ? 1 : 2;
    }
    return c == 1;
}

struct Begin : public osg::Camera::DrawCallback {
    osg::observer_ptr<PassMeter> meter;
    explicit Begin(PassMeter* m) : meter(m) {}
    void operator()(osg::RenderInfo& ri) const override { if (osg::ref_ptr<PassMeter> m = meter.get()) m->begin(ri); }
};
struct End : public osg::Camera::DrawCallback {
    osg::observer_ptr<PassMeter> meter;
    explicit End(PassMeter* m) : meter(m) {}
    void operator()(osg::RenderInfo& ri) const override { if (osg::ref_ptr<PassMeter> m = meter.get()) m->end(ri); }
};
struct MeteredDraw : public osg::Drawable::DrawCallback {
    osg::observer_ptr<PassMeter> meter;
    explicit MeteredDraw(PassMeter* m) : meter(m) {}
    void drawImplementation(osg::RenderInfo& ri, const osg::Drawable* drawable) const override
    {
        osg::ref_ptr<PassMeter> m = meter.get();
        if (m) m->begin(ri);
        drawable->drawImplementation(ri);
        if (m) m->end(ri);
    }
};
}

PassMeasure PassMeasure::operator+(const PassMeasure& o) const
{
    auto sum = [](double a, double b) { return a >= 0.0 && b >= 0.0 ? a + b : std::max(a, b); };
    return { sum(milliseconds, o.milliseconds), sum(fragments, o.fragments) };
}

PassMeter::PassMeter() : _ms(-1.0), _fragments(-1.0) {}

PassMeter::~PassMeter()
{
    releaseGLObjects(nullptr);
}

void PassMeter::releaseGLObjects(osg::State* state) const
{
    releaseQueryNames(_queries, state);
}

void PassMeter::attach(osg::Drawable* drawable)
{
    drawable->setDrawCallback(new MeteredDraw(this));
}

void PassMeter::setEnabled(bool on)
{
    if (!on) {
        _ms = -1.0;
        _fragments = -1.0;
    }
    _enabled = on;
}

void PassMeter::attach(osg::Camera* camera)
{
    camera->setInitialDrawCallback(new Begin(this));
    camera->setFinalDrawCallback(new End(this));
}

void PassMeter::attach(osg::Camera* first, osg::Camera* last)
{
    first->setInitialDrawCallback(new Begin(this));
    last->setFinalDrawCallback(new End(this));
}

void PassMeter::detach(osg::Camera* camera)
{
    camera->setInitialDrawCallback(nullptr);
    camera->setFinalDrawCallback(nullptr);
}

void PassMeter::readLastFrame(osg::GLExtensions& ext, Query& q)
{
    GLint available = 0;
    ext.glGetQueryObjectiv(q.ids[1], GL_QUERY_RESULT_AVAILABLE, &available);
    if (available && q.counted) ext.glGetQueryObjectiv(q.ids[2], GL_QUERY_RESULT_AVAILABLE, &available);
    if (!available) return;
    GLuint64 start = 0, stop = 0;
    ext.glGetQueryObjectui64v(q.ids[0], GL_QUERY_RESULT, &start);
    ext.glGetQueryObjectui64v(q.ids[1], GL_QUERY_RESULT, &stop);
    _ms = stop > start ? double(stop - start) * 1.0e-6 : 0.0;
    if (q.counted) {
        GLuint64 fragments = 0;
        ext.glGetQueryObjectui64v(q.ids[2], GL_QUERY_RESULT, &fragments);
        _fragments = double(fragments);
    }
    q.pending = false;
}

void PassMeter::begin(osg::RenderInfo& ri)
{
    if (!_enabled) return;
    const unsigned int contextID = ri.getContextID();
    Query& q = _queries[contextID];
    if (q.failed) return;
    osg::GLExtensions* ext = ri.getState()->get<osg::GLExtensions>();
    if (!ext || !ext->isTimerQuerySupported || !ext->glGenQueries || !ext->glQueryCounter) {
        OSG_NOTICE << "osgWater::PassMeter: no GL timer queries here, pass times are not measured" << std::endl;
        q.failed = true;
        return;
    }
    if (q.ids[0] == 0) ext->glGenQueries(3, q.ids);
    if (q.pending) {
        readLastFrame(*ext, q);
        if (q.pending) return; // last frame's results not there yet: skip this frame's measurement
    }
    ext->glQueryCounter(q.ids[0], GL_TIMESTAMP);
    q.active = true;
    int& counting = countingOn(contextID);
    q.counting = !counting && countsFragments(*ext, contextID);
    if (q.counting) {
        ext->glBeginQuery(GL_FRAGMENT_SHADER_INVOCATIONS, q.ids[2]);
        counting = 1;
    }
}

void PassMeter::end(osg::RenderInfo& ri)
{
    const unsigned int contextID = ri.getContextID();
    Query& q = _queries[contextID];
    if (!q.active) return;
    osg::GLExtensions* ext = ri.getState()->get<osg::GLExtensions>();
    if (q.counting) {
        ext->glEndQuery(GL_FRAGMENT_SHADER_INVOCATIONS);
        countingOn(contextID) = 0;
    }
    ext->glQueryCounter(q.ids[1], GL_TIMESTAMP);
    q.active = false;
    q.pending = true;
    q.counted = q.counting;
    q.counting = false;
}
