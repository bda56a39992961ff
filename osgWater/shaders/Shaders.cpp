#include "shaders/Shaders.h"
#include "shaders/ShaderContract.h"
#include <osgDB/FileUtils>
#include <osgDB/FileNameUtils>
#include <osg/Notify>
#include <fstream>
#include <map>
#include <mutex>
#include <set>
#include <sstream>

namespace osgWater { namespace detail { const std::map<std::string, std::string>& embeddedShaders(); } }

using namespace osgWater;

namespace {

const std::string& embedded(const std::string& name)
{
    static const std::string none;
    const auto& table = detail::embeddedShaders();
    auto it = table.find(name);
    if (it != table.end()) return it->second;
    OSG_WARN << "osgWater: shader " << name << " is neither on the data path nor embedded" << std::endl;
    return none;
}

// osgWater/shaders/<name> in a directory of the OSG data path, or "". Never a bare name and never
// the working directory: osgDB::findDataFile also tries the name as given, relative to the working
// directory, where any project may keep a scene.frag of its own.
std::string overridePath(const std::string& name)
{
    for (const std::string& dir : osgDB::getDataFilePathList()) {
        if (dir.empty()) continue; // an empty entry means the working directory
        const std::string path = osgDB::concatPaths(dir, "osgWater/shaders/" + name);
        if (osgDB::fileType(path) == osgDB::REGULAR_FILE) return path;
    }
    return std::string();
}

// the override file on the data path (its path in `from`), else the embedded copy
std::string rawSource(const std::string& name, bool embeddedOnly, std::string* from)
{
    if (name == shaderContractFile()) return shaderContractSource(); // generated: never overridden
    if (!embeddedOnly) {
        const std::string path = overridePath(name);
        if (!path.empty()) {
            std::ifstream in(path.c_str());
            std::stringstream ss;
            if (in) ss << in.rdbuf();
            if (in && !ss.str().empty()) {
                OSG_INFO << "osgWater: shader " << name << " from " << path << std::endl;
                if (from) *from = path;
                return ss.str();
            }
            OSG_WARN << "osgWater: shader override " << path << " could not be read (or is empty), using the embedded "
                     << name << std::endl;
        }
    }
    return embedded(name);
}

std::string expand(const std::string& name, std::set<std::string>& seen, bool embeddedOnly, std::string* from)
{
    std::istringstream in(rawSource(name, embeddedOnly, from));
    std::ostringstream out;
    std::string line;
    while (std::getline(in, line)) {
        const std::string key = "#pragma include \"";
        const size_t p = line.find(key);
        if (p != std::string::npos) {
            const size_t q = line.find('"', p + key.size());
            const std::string inc = line.substr(p + key.size(), q - p - key.size());
            if (seen.insert(inc).second) out << expand(inc, seen, embeddedOnly, from);
            continue;
        }
        out << line << '\n';
    }
    return out.str();
}

// Every WaterNode makes a dozen programs: the embedded sources are expanded once per process, and the
// data path is only searched for overrides of the files that expansion used
struct Expanded {
    std::string source;
    std::set<std::string> files;
};

const Expanded& embeddedExpansion(const std::string& name)
{
    static std::mutex mutex;
    static std::map<std::string, Expanded> cache;
    std::lock_guard<std::mutex> lock(mutex);
    auto it = cache.find(name);
    if (it != cache.end()) return it->second;
    Expanded e;
    e.files.insert(name);
    e.source = expand(name, e.files, true, nullptr);
    return cache.emplace(name, std::move(e)).first->second;
}

bool hasOverride(const std::string& name)
{
    return !overridePath(name).empty();
}

}

std::string osgWater::shaderSource(const std::string& name, bool embeddedOnly, std::string* overrideFile)
{
    const Expanded& e = embeddedExpansion(name);
    if (embeddedOnly) return e.source;
    bool overridden = false;
    for (const std::string& file : e.files) overridden = overridden || hasOverride(file);
    if (!overridden) return e.source;
    std::set<std::string> seen;
    seen.insert(name);
    return expand(name, seen, false, overrideFile);
}

FallbackProgram::FallbackProgram(const std::string& name, const std::string& vert, const std::string& frag)
    : _vert(vert), _frag(frag)
{
    setName(name);
    osg::Shader* vs = new osg::Shader(osg::Shader::VERTEX, shaderSource(vert, false, &_overrideFile));
    vs->setName(vert);
    osg::Shader* fs = new osg::Shader(osg::Shader::FRAGMENT, shaderSource(frag, false, &_overrideFile));
    fs->setName(frag);
    addShader(vs);
    addShader(fs);
    _mayFallBack = !_overrideFile.empty();
}

FallbackProgram::FallbackProgram(const FallbackProgram& o, const osg::CopyOp& copyop)
    : osg::Program(o, copyop), _vert(o._vert), _frag(o._frag), _overrideFile(o.getOverrideFile())
{
    _mayFallBack = !_overrideFile.empty();
}

std::string FallbackProgram::getOverrideFile() const
{
    OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_fallbackMutex);
    return _overrideFile;
}

void FallbackProgram::apply(osg::State& state) const
{
    osg::Program::apply(state);
    if (!_mayFallBack) return; // the embedded shaders are tested: nothing to fall back to
    const PerContextProgram* pcp = getPCP(state);
    if (!pcp || pcp->isLinked()) return;
    {
        // draw threads of several contexts may get here at once
        OpenThreads::ScopedLock<OpenThreads::Mutex> lock(_fallbackMutex);
        if (_overrideFile.empty()) return; // another context fell back meanwhile
        OSG_WARN << "osgWater: program " << getName() << " does not compile or link with the override "
                 << _overrideFile << ", falling back to the embedded " << _vert << " and " << _frag << std::endl;
        FallbackProgram* self = const_cast<FallbackProgram*>(this); // the draw thread owns this change
        self->getShader(0)->setShaderSource(shaderSource(_vert, true));
        self->getShader(1)->setShaderSource(shaderSource(_frag, true));
        self->dirtyProgram();
        self->_overrideFile.clear();
        self->_mayFallBack = false;
    }
    osg::Program::apply(state);
}

osg::Program* osgWater::createProgram(const std::string& name, const std::string& vert, const std::string& frag)
{
    return new FallbackProgram(name, vert, frag);
}
