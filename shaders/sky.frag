#version 130
#pragma import_defines(OSGWATER_DISPLAY)
// osgWater::Sky: the clear sky along each pixel's ray, at the far plane (screen.vert). In the view
// (OSGWATER_DISPLAY) exposed and encoded as the scene is; in the passes linear, for the water to sum.
#pragma include "srgb.glsl"
#pragma include "sky.glsl"

in vec4 vNear;
in vec4 vFar;

void main()
{
    vec3 c = owSkyLight(vFar.xyz / vFar.w - vNear.xyz / vNear.w);
#ifdef OSGWATER_DISPLAY
    gl_FragColor = vec4(owDisplay(c), 1.0);
#else
    gl_FragColor = vec4(c, 1.0);
#endif
}
