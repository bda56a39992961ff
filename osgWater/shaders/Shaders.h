/* osgWater - natural water for OpenSceneGraph */
#ifndef OSGWATER_SHADERS
#define OSGWATER_SHADERS 1

#include <osgWater/Export>
#include <osg/Shader>
#include <osg/Program>
#include <OpenThreads/Mutex>
#include <atomic>
#include <string>

namespace osgWater {

//! Source of shader `name` (e.g. "water.frag"): the file osgWater/shaders/<name> in a directory of
//! the OSG data path (OSG_FILE_PATH, osgDB::getDataFilePathList()) when there is one, so users can
//! override it, else the copy embedded at build time. A bare <name> and the working directory are
//! never searched.
//! Lines `#pragma include "file"` are replaced by that file's text, once per file. `embeddedOnly`
//! ignores the data path; `overrideFile`, when given, receives the path of an override used.
OSGWATER_EXPORT std::string shaderSource(const std::string& name, bool embeddedOnly = false,
                                         std::string* overrideFile = nullptr);

//! A program from a vertex and a fragment shader, sources as by shaderSource(). When override
//! files on the data path make it fail to compile or link, it says so once and falls back to the
//! embedded shaders (a broken override must not leave the water black or missing).
class OSGWATER_EXPORT FallbackProgram : public osg::Program
{
public:
    FallbackProgram() {}
    FallbackProgram(const std::string& name, const std::string& vert, const std::string& frag);
    FallbackProgram(const FallbackProgram& other, const osg::CopyOp& copyop = osg::CopyOp::SHALLOW_COPY);
    META_StateAttribute(osgWater, FallbackProgram, PROGRAM)

    void apply(osg::State& state) const override;
    //! The override file in use ("" when the program uses the embedded shaders only).
    std::string getOverrideFile() const;

protected:
    virtual ~FallbackProgram() {}
    std::string _vert, _frag;
    mutable std::string _overrideFile;        // guarded by _fallbackMutex
    mutable std::atomic<bool> _mayFallBack{false}; // an override is in use
    mutable OpenThreads::Mutex _fallbackMutex;
};

//! A FallbackProgram from a vertex and a fragment shader.
OSGWATER_EXPORT osg::Program* createProgram(const std::string& name, const std::string& vert, const std::string& frag);

}

#endif
