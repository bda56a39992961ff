#include "shaders/ProgramLibrary.h"
#include "shaders/Shaders.h"
#include <OpenThreads/ScopedLock>

using namespace osgWater;

osg::Program* ProgramLibrary::get(const std::string& name, const std::string& vert, const std::string& frag)
{
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_mutex);
    osg::ref_ptr<osg::Program>& program = _programs[name + '\n' + vert + '\n' + frag];
    if (!program.valid()) program = createProgram(name, vert, frag);
    return program.get();
}

size_t ProgramLibrary::size() const
{
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_mutex);
    return _programs.size();
}

void ProgramLibrary::resizeGLObjectBuffers(unsigned int maxSize)
{
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_mutex);
    for (auto& p : _programs) p.second->resizeGLObjectBuffers(maxSize);
}

void ProgramLibrary::releaseGLObjects(osg::State* state) const
{
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_mutex);
    for (const auto& p : _programs) p.second->releaseGLObjects(state);
}
