// Preetham's clear sky (sky/ClearSky, mirrored by osgWater::Sky::getRadiance): Perez's distribution
// (1 + A e^(B / cos theta)) (1 + C e^(D gamma) + E cos^2 gamma) for the chromaticities x, y and the
// luminance Y at once, each scaled to its zenith's value, then CIE XYZ to linear sRGB.
uniform vec3 osgWater_SkyA; // Perez's coefficients for (x, y, Y)
uniform vec3 osgWater_SkyB;
uniform vec3 osgWater_SkyC;
uniform vec3 osgWater_SkyD;
uniform vec3 osgWater_SkyE;
uniform vec3 osgWater_SkyZenith; // the zenith's (x, y, Y) over Perez's values there
uniform vec3 osgWater_SkySun;    // toward the sun, unit, z up
uniform float osgWater_SkyScale; // linear light per kcd/m^2

// the sky's linear light along d (toward the sky, z up; at and below the horizon the horizon's)
vec3 owSkyLight(vec3 d)
{
    d = normalize(d);
    float cosGamma = clamp(dot(d, osgWater_SkySun), -1.0, 1.0);
    float gamma = acos(cosGamma);
    // B < 0: the first factor's limit at the horizon is 1
    vec3 horizon = d.z > 0.0 ? 1.0 + osgWater_SkyA * exp(osgWater_SkyB / d.z) : vec3(1.0);
    vec3 xyY = osgWater_SkyZenith * horizon * (1.0 + osgWater_SkyC * exp(osgWater_SkyD * gamma) + osgWater_SkyE * cosGamma * cosGamma);
    vec3 XYZ = xyY.y != 0.0 ? vec3(xyY.x / xyY.y * xyY.z, xyY.z, (1.0 - xyY.x - xyY.y) / xyY.y * xyY.z) : vec3(0.0);
    // optics::linearSrgbFromXyz: the inverse of sRGB's primaries and D65 white (IEC 61966-2-1), by columns
    const mat3 srgbFromXyz = mat3(3.2404542, -0.9692660, 0.0556434, -1.5371385, 1.8760108, -0.2040259, -0.4985314, 0.0415560, 1.0572252);
    return max(srgbFromXyz * XYZ, 0.0) * osgWater_SkyScale;
}
