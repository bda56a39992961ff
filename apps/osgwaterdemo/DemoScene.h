// A small procedural lake for the demo: basin with a sloping shore, a post crossing the water,
// trees on the shore, a submerged rock. (The full OBJ lake is the lake demo's.)
#pragma once
#include <osg/Group>

osg::ref_ptr<osg::Group> createDemoScene();
