#include "frame/ScreenTriangle.h"
#include <osg/Geometry>

using namespace osgWater;

namespace {

// an empty box: the triangle's clip-space vertices mean nothing to culling or near/far
struct NoBound : public osg::Drawable::ComputeBoundingBoxCallback
{
    osg::BoundingBox computeBound(const osg::Drawable&) const override { return osg::BoundingBox(); }
};

}

osg::Geode* osgWater::makeScreenTriangle(float z, const char* name)
{
    osg::ref_ptr<osg::Geometry> g = new osg::Geometry;
    osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array;
    v->push_back(osg::Vec3(-1.0f, -1.0f, z));
    v->push_back(osg::Vec3(3.0f, -1.0f, z));
    v->push_back(osg::Vec3(-1.0f, 3.0f, z));
    g->setVertexArray(v.get());
    g->addPrimitiveSet(new osg::DrawArrays(GL_TRIANGLES, 0, 3));
    setUpScreenGeometry(g.get());
    osg::Geode* geode = new osg::Geode;
    geode->setName(name);
    geode->addDrawable(g.get());
    geode->setCullingActive(false);
    return geode;
}

void osgWater::setUpScreenGeometry(osg::Geometry* g)
{
    g->setUseDisplayList(false);
    g->setUseVertexBufferObjects(true);
    g->setComputeBoundingBoxCallback(new NoBound);
    g->setCullingActive(false);
}
