// Command line of osgwaterbench.
#pragma once
#include <cstddef>
#include <string>

namespace bench {

struct BenchOptions {
    std::string scene, viewsFile, out = "bench-out", techniques, docs, commandLine;
    int width = 1280, height = 720;
    int frames = 30;               //!< timed frames per technique and view (>= 30 unless --quick)
    size_t photons = 4000000;      //!< caustics reference photons (>= 1e6 for published tables)
    bool quick = false, help = false;
    //! Parses argv; false with a message on a bad or missing value.
    bool read(int argc, char** argv, std::string& error);
};

}
