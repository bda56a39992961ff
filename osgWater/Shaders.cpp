#include <osgWater/Shaders>
#include <osgDB/FileUtils>
#include <osg/Notify>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace osgWater { namespace detail { const std::map<std::string, std::string>& embeddedShaders(); } }

using namespace osgWater;

namespace {

std::string rawSource(const std::string& name)
{
    std::string path = osgDB::findDataFile("osgWater/shaders/" + name);
    if (path.empty()) path = osgDB::findDataFile(name);
    if (!path.empty()) {
        std::ifstream in(path.c_str());
        if (in) {
            OSG_INFO << "osgWater: shader " << name << " from " << path << std::endl;
            std::stringstream ss;
            ss << in.rdbuf();
            return ss.str();
        }
    }
    const auto& table = detail::embeddedShaders();
    auto it = table.find(name);
    if (it != table.end()) return it->second;
    OSG_WARN << "osgWater: shader " << name << " is neither on the data path nor embedded" << std::endl;
    return std::string();
}

std::string expand(const std::string& name, std::set<std::string>& seen)
{
    std::istringstream in(rawSource(name));
    std::ostringstream out;
    std::string line;
    while (std::getline(in, line)) {
        const std::string key = "#pragma include \"";
        const size_t p = line.find(key);
        if (p != std::string::npos) {
            const size_t q = line.find('"', p + key.size());
            const std::string inc = line.substr(p + key.size(), q - p - key.size());
            if (seen.insert(inc).second) out << expand(inc, seen);
            continue;
        }
        out << line << '\n';
    }
    return out.str();
}

}

std::string osgWater::shaderSource(const std::string& name)
{
    std::set<std::string> seen;
    seen.insert(name);
    return expand(name, seen);
}

osg::Program* osgWater::createProgram(const std::string& name, const std::string& vert, const std::string& frag)
{
    osg::Program* p = new osg::Program;
    p->setName(name);
    osg::Shader* vs = new osg::Shader(osg::Shader::VERTEX, shaderSource(vert));
    vs->setName(vert);
    osg::Shader* fs = new osg::Shader(osg::Shader::FRAGMENT, shaderSource(frag));
    fs->setName(frag);
    p->addShader(vs);
    p->addShader(fs);
    return p;
}
