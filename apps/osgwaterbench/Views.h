// The benchmark's views file: one view per non-empty line not starting with '#':
//   ex ey ez cx cy cz ux uy uz [t]   [# name]
// (eye, centre, up, optional simulation time in seconds; a trailing comment names the view).
#pragma once
#include <osg/Vec3d>
#include <string>
#include <vector>

namespace bench {

struct View {
    std::string name;
    osg::Vec3d eye, center, up;
    double t = 0.0;
};

//! Reads a views file; false with a message naming the file and line on any error.
bool readViews(const std::string& file, std::vector<View>& views, std::string& error);
//! Parses one line (no comment handling); false if it is not 9 or 10 finite numbers.
bool parseView(const std::string& line, View& view);

}
