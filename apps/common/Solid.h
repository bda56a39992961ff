// Plain coloured solids for the demo's props (the buoy, the boat, the pond's basin).
#pragma once
#include <osg/Geode>
#include <osg/Shape>
#include <initializer_list>

namespace osgWaterApps {

//! A Geode of these shapes under one material of `colour` (diffuse and ambient).
osg::Geode* solid(const osg::Vec4& colour, std::initializer_list<osg::Shape*> shapes);

}
