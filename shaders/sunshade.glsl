// Whether the sun reaches the water (the sun's shade map: the whole scene seen from the sun), shared
// by the photon pass and the procedural caustics. Needs optics.glsl (owDepthPass) included first.
const float kSunReachesTolerance = 0.005; // metres: well above the shade map's precision over its depth range
uniform sampler2D osgWater_SunShade;   // the whole scene's depth seen from the sun (unclipped)
uniform mat4 osgWater_SunShadeProj;

// Whether the sun's ray reaches the water at P (sun eye space) before the scene: the shade map (the
// whole scene, so the shore in front of the water and the pier above it alike) read between its
// four texels around P. Read at the nearest texel, the shore moves by up to half a texel's rise,
// and a strip along the waterline is lit or dark by chance; between the texels a plane is exact
// (the beach's caustics test: 4.7% from the photon reference read at the nearest texel with a 1 cm
// tolerance, 4.0% read between). Next to a texel the map leaves clear (nothing there) the nearest
// texel answers.
bool owSunReaches(vec3 P)
{
    owDepthPass shade = owDepthPass(osgWater_SunShadeProj, vec4(0.0, 0.0, 0.0, 1.0), false);
    vec2 tc;
    if (!owPassTexCoord(shade.proj, P, tc)) return true;
    float depth = owDepthBetweenTexels(osgWater_SunShade, tc);
    if (depth >= 1.0) return true; // nothing on this ray
    return !(owPassEyeZ(shade, depth) > P.z + kSunReachesTolerance);
}
