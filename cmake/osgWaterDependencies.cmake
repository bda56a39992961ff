# The kit's public dependency on OpenSceneGraph as one target, made the same way in the build and in
# an installed package: the exported osgWater::osgWater names this target, never the paths that
# FindOpenSceneGraph found on the machine that built it, so an installed prefix can be moved and
# still finds the OSG of the machine it is used on.
if(NOT TARGET osgWater::OpenSceneGraph)
  add_library(osgWater::OpenSceneGraph INTERFACE IMPORTED)
  set_target_properties(osgWater::OpenSceneGraph PROPERTIES
    INTERFACE_LINK_LIBRARIES "${OPENSCENEGRAPH_LIBRARIES}"
    INTERFACE_INCLUDE_DIRECTORIES "${OPENSCENEGRAPH_INCLUDE_DIRS}")
endif()
