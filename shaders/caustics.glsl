// Caustics applied like a shadow map (thesis §9.2): the fragment's position in the sun camera's
// texture space indexes the caustics texture (power per unit area seen from the sun, in units of
// the sun's irradiance) and the sun's depth map (shadows). Included only by passes that have
// caustics (OSGWATER_CAUSTICS) or reflective caustics (OSGWATER_REFLECTED_CAUSTICS: the same for
// the sun reflected off the water, with the fragment mirrored in the water plane).
// OSGWATER_CAUSTICS_PROCEDURAL: no caustics texture, the procedural construction at the fragment's
// own place (procedural.glsl, included first; OSGWATER_PROCEDURAL_SHADE: with the shade map).
in float vAboveWater;

#ifdef OSGWATER_CAUSTICS
uniform float osgWater_CausticsIntensity;
uniform sampler2D osgWater_CausticsTex;
uniform sampler2D osgWater_SunDepth;
uniform vec2 osgWater_SunDepthBias;      // depth bias: constant + per unit of slope tangent
uniform vec3 osgWater_CausticsChannels;  // per-channel sun extinction beyond the photons', per metre of depth

in vec3 vSun;
#ifdef OSGWATER_CAUSTICS_TILED
in vec2 vTile;
#endif
#ifdef OSGWATER_CAUSTICS_PROCEDURAL
in vec3 vLocal;
uniform mat4 osgWater_SunView; // water-local -> the sun camera's eye space (the shade map's)

// The procedural caustics at this fragment, as the caustics texture would hold them
float owCausticsHere()
{
    vec3 exitPoint;
    float light = owProceduralLight(vLocal, exitPoint);
#ifdef OSGWATER_PROCEDURAL_SHADE
    if (light > 0.0 && !owSunReaches((osgWater_SunView * vec4(exitPoint, 1.0)).xyz)) light = 0.0;
#endif
    return light;
}
#else
float owCausticsHere()
{
#ifdef OSGWATER_CAUSTICS_TILED
    return texture(osgWater_CausticsTex, vTile).r; // the tile repeats under all the water
#else
    return texture(osgWater_CausticsTex, vSun.xy).r;
#endif
}
#endif

// Share of the direct sun reaching a fragment per channel (1 above the water or without caustics).
// Irradiance on a surface of normal n is C (n.L): C counts power per area seen from the sun. The
// photons faded with the green channel; red and blue differ by their extra extinction over the
// sun's path down to this depth.
vec3 owUnderwaterSun(float ndl)
{
    if (vAboveWater >= 0.0) return vec3(1.0);
    bool inMap = all(greaterThanEqual(vSun.xy, vec2(0.0))) && all(lessThanEqual(vSun.xy, vec2(1.0)));
#ifndef OSGWATER_CAUSTICS_TILED
    if (!inMap) return vec3(1.0); // a tile repeats; shadows where the depth map reaches
#endif
    float tanSlope = sqrt(max(1.0 - ndl * ndl, 0.0)) / max(ndl, 0.1);
    float bias = osgWater_SunDepthBias.x + osgWater_SunDepthBias.y * tanSlope;
    if (inMap && vSun.z > texture(osgWater_SunDepth, vSun.xy).r + bias) return vec3(0.0);
#ifdef OSGWATER_CAUSTICS_CHANNELS
    return osgWater_CausticsIntensity * owCausticsHere() * exp(osgWater_CausticsChannels * vAboveWater);
#else
    return vec3(osgWater_CausticsIntensity * owCausticsHere());
#endif
}
#endif

#ifdef OSGWATER_REFLECTED_CAUSTICS
uniform float osgWater_ReflectedIntensity;
uniform sampler2D osgWater_ReflectedCausticsTex;
uniform sampler2D osgWater_ReflectedSunDepth;    // the scene above the water, mirrored
uniform vec2 osgWater_ReflectedDepthBias;
in vec3 vSunR;
in vec2 vNdlR; // n.l of the front and back faces for the sun's mirror image

// The sun reflected off the water on a fragment above it, in units of the sun's irradiance per
// n.l towards the sun's mirror image: 0 under the water, off the map, or where the mirrored depth
// map shows the reflected light stopped before it reaches the fragment.
float owReflectedSun(float ndl)
{
    if (vAboveWater < 0.0) return 0.0;
    if (any(lessThan(vSunR.xy, vec2(0.0))) || any(greaterThan(vSunR.xy, vec2(1.0)))) return 0.0;
    float tanSlope = sqrt(max(1.0 - ndl * ndl, 0.0)) / max(ndl, 0.1);
    float bias = osgWater_ReflectedDepthBias.x + osgWater_ReflectedDepthBias.y * tanSlope;
    if (vSunR.z > texture(osgWater_ReflectedSunDepth, vSunR.xy).r + bias) return 0.0;
    return osgWater_ReflectedIntensity * texture(osgWater_ReflectedCausticsTex, vSunR.xy).r;
}
#endif
