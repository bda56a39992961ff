// libFuzzer target: .osgt/.osgb bytes through osgDB into WaterNode, WaterSettings, WaterSurface.
// Built with -DOSGWATER_FUZZ=ON and clang; run by scripts/fuzz.sh.
#include "FuzzRead.h"
#include <cstdio>
#include <cstdlib>
#include <new>

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
    osgwater_fuzz::init();
    return 0;
}

void osgwaterFuzzCountAllocations(bool on); // AllocationCap.cpp

namespace {
struct CountAllocations {
    CountAllocations() { osgwaterFuzzCountAllocations(true); }
    ~CountAllocations() { osgwaterFuzzCountAllocations(false); }
};
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    std::string failure;
    CountAllocations scope;
    try {
        failure = osgwater_fuzz::readOne(data, size);
    } catch (const std::bad_alloc&) {
        return 0; // asked for more than AllocationCap.cpp allows: rejected, like any other bad file
    }
    if (!failure.empty()) {
        std::fprintf(stderr, "osgwater fuzz: %s\n", failure.c_str());
        std::abort(); // libFuzzer keeps the input as a crash
    }
    return 0;
}
