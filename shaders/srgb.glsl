// The kit's colour convention: light is summed in linear units. Colours that come from files (the
// scene's materials and textures) and the view's clear colour are sRGB-encoded display values,
// decoded here once; what the kit draws in the view itself is encoded once, at the end, after the
// exposure. The pass targets between hold linear light. The sRGB curve exactly (IEC 61966-2-1);
// mirrored in osgWater/optics/Srgb.cpp.
uniform float osgWater_Exposure; // linear light is multiplied by it before the encoding

vec3 owDecodeSrgb(vec3 c)
{
    c = clamp(c, 0.0, 1.0);
    return mix(c / 12.92, pow((c + 0.055) / 1.055, vec3(2.4)), step(vec3(0.04045), c));
}

vec3 owEncodeSrgb(vec3 c)
{
    c = clamp(c, 0.0, 1.0); // pow of a negative is undefined; above 1 the display clips anyway
    return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}

//! Linear light as the view shows it: exposed, then encoded.
vec3 owDisplay(vec3 linear) { return owEncodeSrgb(osgWater_Exposure * linear); }

