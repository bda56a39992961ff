// Command line of osgwaterbench.
#pragma once
#include <cstddef>
#include <string>

namespace bench {

struct BenchOptions {
    std::string scene, viewsFile, out = "bench-out", techniques, docs, commandLine;
    std::string resumeKey;         //!< --resume KEY: finished work kept and taken again (see ResumeCache)
    std::string fresnelFigure;     //!< --fresnel-figure DIR: the Fresnel fit's figure and table alone
    std::string waterType;         //!< --water-type NAME: a WaterTypes preset on the scene's settings ("": as they are)
    std::string heldOutFile;       //!< --held-out FILE: views the default technique alone measures, apart from the rest
    int width = 1280, height = 720;
    int frames = 30;               //!< timed frames per technique and view (>= 30 unless --quick)
    size_t photons = 4000000;      //!< caustics reference photons (>= 1e6 for published tables)
    int referenceSamples = 2;      //!< the reference image's rays a pixel, each way (n x n)
    int referenceRefine = 4;       //!< ... and m x m more where its two halves disagree (0: none)
    int ablationRounds = 3;        //!< alternating rounds of the ablation (0: none)
    bool quick = false, help = false;
    bool ablationOnly = false;     //!< the ablation alone: no techniques, no reference
    //! Parses argv; false with a message on a bad or missing value.
    bool read(int argc, char** argv, std::string& error);
};

}
