#include "Views.h"
#include <cmath>
#include <fstream>
#include <sstream>

namespace bench {

bool parseView(const std::string& line, View& v)
{
    std::istringstream in(line);
    std::vector<double> n;
    std::string word;
    while (in >> word) {
        char* end = nullptr;
        const double x = std::strtod(word.c_str(), &end);
        if (end == word.c_str() || *end != '\0' || !std::isfinite(x)) return false;
        n.push_back(x);
    }
    if (n.size() != 9 && n.size() != 10) return false;
    v.eye.set(n[0], n[1], n[2]);
    v.center.set(n[3], n[4], n[5]);
    v.up.set(n[6], n[7], n[8]);
    v.t = n.size() == 10 ? n[9] : 0.0;
    // a view needs a direction and an up vector not along it
    const osg::Vec3d dir = v.center - v.eye;
    return dir.length() > 1e-9 && (dir ^ v.up).length() > 1e-9 * dir.length() * v.up.length();
}

bool readViews(const std::string& file, std::vector<View>& views, std::string& error)
{
    std::ifstream in(file);
    if (!in) {
        error = "cannot open views file " + file;
        return false;
    }
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        const size_t first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos || line[first] == '#') continue;
        std::string name;
        const size_t hash = line.find('#');
        if (hash != std::string::npos) {
            name = line.substr(hash + 1);
            name.erase(0, name.find_first_not_of(" \t"));
            name.erase(name.find_last_not_of(" \t\r") + 1);
            line.erase(hash);
        }
        View v;
        if (!parseView(line, v)) {
            error = file + ":" + std::to_string(number) +
                    ": expected 'ex ey ez cx cy cz ux uy uz [t]' (finite numbers, eye != centre, up not along the view)";
            return false;
        }
        v.name = name.empty() ? "view " + std::to_string(views.size() + 1) : name;
        views.push_back(v);
    }
    if (views.empty()) {
        error = "no views in " + file;
        return false;
    }
    return true;
}

}
