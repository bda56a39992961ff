/* osgWater - natural water for OpenSceneGraph */
#ifndef OSGWATER_PROGRAMLIBRARY
#define OSGWATER_PROGRAMLIBRARY 1

#include <osgWater/Export>
#include <osg/Program>
#include <OpenThreads/Mutex>
#include <map>
#include <string>

namespace osgWater {

//! One water's programs: each (name, vertex shader, fragment shader) made once and shared by every
//! pass, view and remade pass that asks for it (the sun's depth and shade maps and the glow's
//! occluders share the depth program; a view's glow passes remade for a new size keep theirs).
//! Per water, not per process: each water's override fallbacks and released variants stay its own.
class OSGWATER_EXPORT ProgramLibrary : public osg::Referenced
{
public:
    //! The program (a FallbackProgram: see createProgram()), made on the first call.
    osg::Program* get(const std::string& name, const std::string& vert, const std::string& frag);
    //! Programs made so far.
    size_t size() const;

    void resizeGLObjectBuffers(unsigned int maxSize);
    void releaseGLObjects(osg::State* state) const;

protected:
    virtual ~ProgramLibrary() {}
    mutable OpenThreads::Mutex _mutex; // views may cull, and make passes, in parallel
    std::map<std::string, osg::ref_ptr<osg::Program>> _programs;
};

}

#endif
