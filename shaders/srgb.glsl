// The kit's colour convention: light is summed in linear units. Colours that come from files (the
// scene's materials and textures) and the view's clear colour are sRGB-encoded display values,
// decoded here once; what the kit draws in the view itself is encoded once, at the end, after the
// exposure. The pass targets between hold linear light. The sRGB curve (IEC 61966-2-1) with its
// power pieces fitted: a quintic for decoding and a series in sqrt(x), x^1/4, x^1/8 for encoding,
// each within 0.05/255 of the curve once in display values; pow costs a software rasteriser several
// times more, on every fragment of every scene pass. Mirrored in osgWater/optics/Srgb.cpp
// (decodeSrgbFitted, encodeSrgbFitted), which a test holds to the exact curve.
// OSGWATER_TONE (WaterSettings::ToneCurve, one of contract.glsl's OSGWATER_TONE_*): the curve the
// exposed light goes through before the encoding; a program outside the kit's states has none and clips.
#pragma import_defines(OSGWATER_TONE)
#pragma include "contract.glsl"
#ifndef OSGWATER_TONE
#define OSGWATER_TONE OSGWATER_TONE_CLIP
#endif
uniform float osgWater_Exposure; // linear light is multiplied by it before the encoding

vec3 owDecodeSrgb(vec3 c)
{
    c = clamp(c, 0.0, 1.0);
    // ((c + 0.055) / 1.055)^2.4 above the knee
    vec3 p = 0.00095477318 + c * (0.031784446 + c * (0.52634035 + c * (0.64794601 + c * (-0.28556063 + c * 0.078688271))));
    return mix(c / 12.92, p, step(vec3(0.04045), c));
}

vec3 owEncodeSrgb(vec3 c)
{
    c = clamp(c, 0.0, 1.0); // no root of a negative; above 1 the display clips anyway
    // 1.055 c^(1/2.4) - 0.055 above the knee
    vec3 s1 = sqrt(c), s2 = sqrt(s1), s3 = sqrt(s2);
    vec3 p = 0.65468427 * s1 + 0.68885027 * s2 - 0.31928944 * s3 - 0.020599216 * c - 0.0037160980;
    return mix(c * 12.92, p, step(vec3(0.0031308), c));
}

// Exposed light as a display's 0..1 (WaterSettings::ToneCurve; mirrored by optics::toneCurve)
vec3 owToneCurve(vec3 x)
{
#if OSGWATER_TONE == OSGWATER_TONE_ACES
    x = max(x, 0.0);
    return x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14); // the encoding clamps above 1
#else
    return x;
#endif
}

//! Linear light as the view shows it: exposed, through the tone curve, then encoded.
vec3 owDisplay(vec3 linear) { return owEncodeSrgb(owToneCurve(osgWater_Exposure * linear)); }

