#include "frame/DrawNodes.h"
#include <osgUtil/CullVisitor>

using namespace osgWater;

ScopedStateSets::ScopedStateSets(osgUtil::CullVisitor& cv, std::initializer_list<osg::StateSet*> states) : _cv(cv)
{
    for (osg::StateSet* ss : states)
        if (ss) {
            _cv.pushStateSet(ss);
            ++_pushed;
        }
}

ScopedStateSets::~ScopedStateSets()
{
    for (unsigned int i = 0; i < _pushed; ++i) _cv.popStateSet();
}

void DrawNodes::addNode(osg::Node* node, std::initializer_list<osg::StateSet*> states)
{
    Draw d;
    d.node = node;
    for (osg::StateSet* ss : states) d.states.push_back(ss);
    _draws.push_back(d);
}

void DrawNodes::addChildrenOf(osg::Group* group, std::initializer_list<osg::StateSet*> states)
{
    Draw d;
    d.childrenOf = group;
    for (osg::StateSet* ss : states) d.states.push_back(ss);
    _draws.push_back(d);
}

void DrawNodes::setNode(unsigned int index, osg::Node* node)
{
    if (index < _draws.size() && _draws[index].node != node) _draws[index].node = node;
}

void DrawNodes::operator()(osg::Node*, osg::NodeVisitor* nv)
{
    osgUtil::CullVisitor* cv = nv->asCullVisitor();
    if (!cv) return;
    osg::Polytope& frustum = cv->getCurrentCullingSet().getFrustum();
    if (!_cullByFrustum) frustum.set(osg::Polytope::PlaneList()); // this traversal's own culling set
    if (_cullByPlane) frustum.add(_plane);
    for (const Draw& d : _draws) {
        for (const osg::ref_ptr<osg::StateSet>& ss : d.states) cv->pushStateSet(ss.get());
        if (d.childrenOf) d.childrenOf->osg::Group::traverse(*nv);
        else if (d.node.valid()) d.node->accept(*nv);
        for (size_t i = 0; i < d.states.size(); ++i) cv->popStateSet();
    }
}

void DrawNodes::resizeGLObjectBuffers(unsigned int maxSize)
{
    for (Draw& d : _draws) {
        if (d.node.valid()) d.node->resizeGLObjectBuffers(maxSize);
        for (osg::ref_ptr<osg::StateSet>& ss : d.states) ss->resizeGLObjectBuffers(maxSize);
    }
}

void DrawNodes::releaseGLObjects(osg::State* state) const
{
    for (const Draw& d : _draws) {
        if (d.node.valid()) d.node->releaseGLObjects(state);
        for (const osg::ref_ptr<osg::StateSet>& ss : d.states) ss->releaseGLObjects(state);
    }
}
