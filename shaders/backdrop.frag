#version 130
// Under water, a ray that meets nothing ends in water: the water colour, drawn at the far plane
// where the depth buffer is still clear (thesis eq. 10 with d -> infinity).
// Drawn in the view itself: encoded for display.
#pragma include "srgb.glsl"
uniform vec3 osgWater_WaterColor;

void main()
{
    gl_FragColor = vec4(owDisplay(osgWater_WaterColor), 1.0);
}
