#version 130
// Fixed-function look of the OBJ loader's geometry: material * texture, one sun + ambient.
// Under water, where caustics are on, the direct sun is the caustic irradiance of the photon pass
// (thesis ch. 8), and zero where the sun's depth map shows something between the fragment and the
// surface (underwater shadows).
#pragma include "caustics.glsl"
uniform sampler2D osgWater_BaseTexture; // unit 0; a white texel when the geometry has none
uniform vec3 osgWater_SunEye;           // towards the sun, in this pass's eye space
uniform vec3 osgWater_SunColor;
uniform vec3 osgWater_Ambient;

in vec3 vNormalEye;
in vec2 vTexCoord;

void main()
{
    vec4 tex = texture(osgWater_BaseTexture, vTexCoord);
    float l2 = dot(vNormalEye, vNormalEye);
    vec3 n = l2 > 1e-20 ? vNormalEye * inversesqrt(l2) : osgWater_SunEye;
    if (!gl_FrontFacing) n = -n;
    float ndl = max(dot(n, osgWater_SunEye), 0.0);
    float sun = owUnderwaterSun(ndl);
    vec3 c = gl_FrontMaterial.emission.rgb
           + gl_FrontMaterial.ambient.rgb * osgWater_Ambient
           + gl_FrontMaterial.diffuse.rgb * osgWater_SunColor * (ndl * sun);
    gl_FragColor = vec4(c * tex.rgb, gl_FrontMaterial.diffuse.a * tex.a);
}
