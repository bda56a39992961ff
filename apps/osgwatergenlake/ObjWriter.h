// Minimal Wavefront OBJ writer for the lake generator. Scene coordinates are z-up (OSG); OBJ files
// are y-up by convention and osgDB's OBJ reader turns them back, so (x, y, z) is written (x, z, -y).
#pragma once
#include <osg/Vec2>
#include <osg/Vec3>
#include <cstdio>
#include <string>

class ObjWriter
{
public:
    explicit ObjWriter(const std::string& path, const std::string& mtllib);
    ~ObjWriter();
    bool ok() const { return _f != nullptr; }

    void group(const std::string& name, const std::string& material);
    //! Adds a vertex (position, normal, texcoord) and returns its 1-based index.
    unsigned vertex(const osg::Vec3& p, const osg::Vec3& n, const osg::Vec2& t);
    void triangle(unsigned a, unsigned b, unsigned c);
    void quad(unsigned a, unsigned b, unsigned c, unsigned d);

    unsigned vertices() const { return _v; }
    unsigned faces() const { return _faces; }

private:
    std::FILE* _f;
    unsigned _v = 0, _faces = 0;
};
