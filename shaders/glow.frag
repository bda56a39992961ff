#version 130
#pragma import_defines(OSGWATER_GRID)
// Glow pass 1 (thesis §9.3): only the sun's specular highlight of the surface,
// pow(max(0, R.E), e) x sun colour, R the sun's direction mirrored about the wave normal.
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
    waterFootprint = max(length(dFdx(vLocal.xy)), length(dFdy(vLocal.xy))); // the cascades filtered as the view's are
#endif
    vec3 N = waterNormal(vLocal.xy);
#else
    float l2 = dot(vMeshNormal, vMeshNormal);
    vec3 N = l2 > 1e-20 ? vMeshNormal * inversesqrt(l2) : vec3(0.0, 0.0, 1.0);
#endif
    vec3 d = osgWater_EyeLocal - vLocal;
    float dl = dot(d, d);
    vec3 E = dl > 1e-20 ? d * inversesqrt(dl) : N;
    vec3 R = reflect(-osgWater_SunLocal, N);
    float RE = max(dot(R, E), 0.0);
    gl_FragColor = vec4(pow(RE, osgWater_GlowExponent) * osgWater_GlowColor, 1.0);
}
