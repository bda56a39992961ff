// One fuzz input through osgDB's .osgt/.osgb reader; shared by the libFuzzer target and the
// regression test that replays every input the fuzzer ever crashed on.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>

namespace osgwater_fuzz {

//! Reads `data` as .osgt (when it starts with "#Ascii") or .osgb. When a WaterNode comes out, checks
//! that every setting is finite and that writing it and reading it back is a fixed point (in both
//! formats). Returns an empty string when all holds, else what failed; never throws.
std::string readOne(const uint8_t* data, size_t size);

//! Whether `data` reads as a WaterNode, WaterSettings or WaterSurface at all (for the seeds).
bool isWater(const uint8_t* data, size_t size);

//! Quiets osg::notify (the reader warns on nearly every mutated input) and loads the osg plugin.
void init();

}
