// Sum of sines: h = level + sum a_i sin(k_i . xy - phase_i). Mirrored by WaterSurface::height/normal.
// Phases arrive wrapped to [0, 2 pi) from the CPU (double precision), so time never grows here.
uniform vec4 osgWater_Waves[8];      // (k dir.x, k dir.y, amplitude, 0)
uniform float osgWater_WavePhases[8];
uniform int osgWater_WaveCount;
uniform float osgWater_Level;

float waterHeight(vec2 p)
{
    float h = osgWater_Level;
    for (int i = 0; i < 8; ++i) {
        if (i >= osgWater_WaveCount) break;
        vec4 w = osgWater_Waves[i];
        h += w.z * sin(dot(w.xy, p) - osgWater_WavePhases[i]);
    }
    return h;
}

vec3 waterNormal(vec2 p)
{
    vec2 g = vec2(0.0);
    for (int i = 0; i < 8; ++i) {
        if (i >= osgWater_WaveCount) break;
        vec4 w = osgWater_Waves[i];
        g += w.z * cos(dot(w.xy, p) - osgWater_WavePhases[i]) * w.xy;
    }
    return normalize(vec3(-g, 1.0));
}
