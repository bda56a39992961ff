#version 130
#pragma import_defines(OSGWATER_GRID)
// Glow pass 1 (thesis §9.3): only the sun's specular highlight of the surface,
// pow(max(0, R.E), e) x sun colour, R the sun's direction mirrored about the wave normal; widened
// by the slopes below the pixel (the wind's roughness, sigma^2). pow(cos a, e) is close to a
// Gaussian of the angle a with variance 1/e per axis; a facet sloped by s turns R by 2 s, a Gaussian
// of variance 2 sigma^2 per axis (sigma^2 is both axes' mean square slope); together the lobe of
// e' = e / (1 + 2 e sigma^2), scaled by e'/e so it holds the same light.
#pragma include "waves.glsl"

uniform vec3 osgWater_EyeLocal;
uniform vec3 osgWater_SunLocal;       // towards the sun
uniform vec3 osgWater_GlowColor;
uniform float osgWater_GlowExponent;

in vec3 vLocal;
in vec3 vMeshNormal;

void main()
{
#ifdef OSGWATER_GRID
#ifdef OSGWATER_WIND
    waterFootprint = waterFootprintOf(dFdx(vLocal.xy), dFdy(vLocal.xy)); // the cascades filtered as the view's are
#endif
    vec4 slopes = waterSlopesAndRoughness(vLocal.xy);
    vec3 N = normalize(vec3(-slopes.yz, 1.0));
    float roughness = slopes.w;
#else
    float l2 = dot(vMeshNormal, vMeshNormal);
    vec3 N = l2 > 1e-20 ? vMeshNormal * inversesqrt(l2) : vec3(0.0, 0.0, 1.0);
    const float roughness = 0.0;
#endif
    vec3 d = osgWater_EyeLocal - vLocal;
    float dl = dot(d, d);
    vec3 E = dl > 1e-20 ? d * inversesqrt(dl) : N;
    vec3 R = reflect(-osgWater_SunLocal, N);
    float RE = max(dot(R, E), 0.0);
    float e = osgWater_GlowExponent / (1.0 + 2.0 * osgWater_GlowExponent * roughness);
    gl_FragColor = vec4((e / osgWater_GlowExponent) * pow(RE, e) * osgWater_GlowColor, 1.0);
}
