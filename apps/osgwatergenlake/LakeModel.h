// The procedural lake of the demos: terrain height, and a deterministic random source, shared by
// the OBJ generator and the tests that check the screenshot against the scene's geometry.
#pragma once
#include <cstdint>

namespace lake {

const float kSize = 140.0f;        // terrain side, metres, centred on the origin
const float kDeepest = 9.0f;       // depth of the centre below the water (z = 0)
const float kRimHeight = 3.0f;     // shore rim above the water

//! Terrain height at (x, y): deep flat centre, sloping shore, rolling rim. Water level is z = 0.
float height(float x, float y);

//! Small deterministic generator (no std:: distributions: their output differs between libraries).
struct Random {
    uint64_t s;
    explicit Random(uint64_t seed) : s(seed * 6364136223846793005ull + 1442695040888963407ull) {}
    uint32_t next()
    {
        s = s * 6364136223846793005ull + 1442695040888963407ull;
        return uint32_t(s >> 33);
    }
    float uniform(float a, float b) { return a + (b - a) * (next() / 4294967296.0f); }
};

// Where things are (also used by tests)
struct Tree { float x, y, height; };
const Tree kTrees[] = { { 44, 18, 11 }, { 38, 36, 9 }, { 20, 49, 12 }, { -8, 52, 10 }, { -30, 44, 11 },
                        { -48, 22, 9 }, { 50, -10, 10 } };
const float kPostX = -22.0f, kPostY = 24.0f;    // post crossing the water near the north-west shore
const float kPierX0 = 44.0f, kPierX1 = 22.0f, kPierY = 14.0f;  // pier from the east shore towards the centre
const float kCrateX = 0.0f, kCrateY = -28.0f;   // submerged crate, on the bed ~3.5 m down

}
