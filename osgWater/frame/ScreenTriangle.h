/* osgWater - natural water for OpenSceneGraph */
#ifndef OSGWATER_SCREENTRIANGLE
#define OSGWATER_SCREENTRIANGLE 1

#include <osgWater/Export>
#include <osg/Geode>
#include <osg/Geometry>

namespace osgWater {

//! One triangle that covers the viewport, for the screen passes (shaders/screen.vert), at NDC depth
//! `ndcDepth` (-1 near, +1 far). It is never culled and never widens the computed near/far range.
OSGWATER_EXPORT osg::Geode* makeScreenTriangle(float ndcDepth, const char* name);
//! Makes `g`, whose vertices are in NDC, a screen pass's geometry as the triangle is: drawn each
//! frame from a vertex buffer, never culled, no bound for the near/far range.
OSGWATER_EXPORT void setUpScreenGeometry(osg::Geometry* g);

}

#endif
