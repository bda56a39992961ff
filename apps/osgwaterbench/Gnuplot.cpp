#include "Gnuplot.h"
#include <cstdio>
#include <cstdlib>
#include <fstream>

namespace bench {

namespace {

void replaceAll(std::string& s, const std::string& what, const std::string& with)
{
    for (size_t at = s.find(what); at != std::string::npos; at = s.find(what, at + with.size())) s.replace(at, what.size(), with);
}

}

bool runGnuplot(const std::string& dir, const std::string& stem, const std::string& data, std::string commands)
{
    const std::string dataFile = dir + "/" + stem + ".dat", script = dir + "/" + stem + ".gp";
    replaceAll(commands, "DATA", "'" + dataFile + "'");
    replaceAll(commands, "OUTPUT", "'" + dir + "/" + stem + ".png'");
    std::ofstream(dataFile) << data;
    std::ofstream(script) << commands;
    const std::string cmd = "gnuplot '" + script + "' 2>&1";
    const int rc = std::system(cmd.c_str());
    std::remove(dataFile.c_str());
    std::remove(script.c_str());
    return rc == 0;
}

}
