// Private to the library and its white-box users (the benchmark's probes): a 2D texture of a
// context read back into an image, the context left current and the texture binding restored.
#pragma once
#include <osgWater/Export>
#include <osg/GraphicsContext>
#include <osg/Image>
#include <osg/Texture>

namespace osgWater {
namespace detail {

//! Mip level `level` of `texture` as `format`/`type` pixels (GL_RGB/GL_UNSIGNED_BYTE,
//! GL_RGBA/GL_FLOAT, GL_DEPTH_COMPONENT/GL_FLOAT for a depth texture, ...), rows packed tight;
//! null where the texture has no GL object in this context yet.
OSGWATER_EXPORT osg::ref_ptr<osg::Image> readTexture(osg::GraphicsContext* gc, osg::Texture* texture, GLenum format,
                                                    GLenum type, int level = 0);

}
}
