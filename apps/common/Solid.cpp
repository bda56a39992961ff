#include "Solid.h"
#include <osg/Material>
#include <osg/ShapeDrawable>

namespace osgWaterApps {

osg::Geode* solid(const osg::Vec4& colour, std::initializer_list<osg::Shape*> shapes)
{
    osg::Geode* geode = new osg::Geode;
    for (osg::Shape* s : shapes) geode->addDrawable(new osg::ShapeDrawable(s));
    osg::ref_ptr<osg::Material> m = new osg::Material;
    m->setDiffuse(osg::Material::FRONT_AND_BACK, colour);
    m->setAmbient(osg::Material::FRONT_AND_BACK, colour);
    geode->getOrCreateStateSet()->setAttribute(m.get());
    return geode;
}

}
