#include "ObjWriter.h"

ObjWriter::ObjWriter(const std::string& path, const std::string& mtllib)
    : _f(std::fopen(path.c_str(), "w"))
{
    if (_f) std::fprintf(_f, "# osgWater lake, written by osgwatergenlake (deterministic)\nmtllib %s\n", mtllib.c_str());
}

ObjWriter::~ObjWriter()
{
    if (_f) std::fclose(_f);
}

void ObjWriter::group(const std::string& name, const std::string& material)
{
    std::fprintf(_f, "g %s\nusemtl %s\n", name.c_str(), material.c_str());
}

unsigned ObjWriter::vertex(const osg::Vec3& p, const osg::Vec3& n, const osg::Vec2& t)
{
    std::fprintf(_f, "v %.4f %.4f %.4f\nvn %.4f %.4f %.4f\nvt %.4f %.4f\n", p.x(), p.z(), -p.y(), n.x(), n.z(), -n.y(),
                 t.x(), t.y());
    return ++_v;
}

void ObjWriter::triangle(unsigned a, unsigned b, unsigned c)
{
    std::fprintf(_f, "f %u/%u/%u %u/%u/%u %u/%u/%u\n", a, a, a, b, b, b, c, c, c);
    ++_faces;
}

void ObjWriter::quad(unsigned a, unsigned b, unsigned c, unsigned d)
{
    std::fprintf(_f, "f %u/%u/%u %u/%u/%u %u/%u/%u %u/%u/%u\n", a, a, a, b, b, b, c, c, c, d, d, d);
    ++_faces;
}
