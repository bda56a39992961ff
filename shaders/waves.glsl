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

// The height a mesh whose cells are `cell` metres across draws: each wave smoothly faded out between
// 4 and 2 cells per wavelength (WaterSurface::ringWaveFade): at 2 (Nyquist) the cells could only
// alias it.
float waterHeightDrawn(vec2 p, float cell)
{
    float h = osgWater_Level;
    for (int i = 0; i < 8; ++i) {
        if (i >= osgWater_WaveCount) break;
        vec4 w = osgWater_Waves[i];
        float cellsPerWave = 6.2831853 / (max(length(w.xy), 1e-9) * cell);
        h += smoothstep(2.0, 4.0, cellsPerWave) * w.z * sin(dot(w.xy, p) - osgWater_WavePhases[i]);
    }
    return h;
}

// (height, dh/dx, dh/dy) in one pass over the waves
vec3 waterHeightAndSlope(vec2 p)
{
    vec3 r = vec3(osgWater_Level, 0.0, 0.0);
    for (int i = 0; i < 8; ++i) {
        if (i >= osgWater_WaveCount) break;
        vec4 w = osgWater_Waves[i];
        float x = dot(w.xy, p) - osgWater_WavePhases[i];
        r += w.z * vec3(sin(x), cos(x) * w.xy);
    }
    return r;
}

// Where the line of sight from C through V (a point of a drawn mesh, near the surface) meets the
// analytic surface, and the unit normal there: one Newton step along the ray from V, kept when it
// gets closer (a ray grazing a crest can send it far off). On the eye's rings V is within
// millimetres of the surface near the eye (a centimetre or so where they fade a wave), and the step
// takes it to a small fraction of that. What a fragment shades: the drawn mesh only decides which
// pixels hold water.
vec3 waterOnSightRay(vec3 C, vec3 V, out vec3 N)
{
    vec3 hs = waterHeightAndSlope(V.xy);
    N = normalize(vec3(-hs.yz, 1.0));
    vec3 D = V - C;
    float s = length(D);
    if (!(s > 1e-9)) return V;
    D /= s;
    float f = V.z - hs.x, df = D.z - dot(hs.yz, D.xy);
    if (!(abs(df) > 1e-6)) return V;
    vec3 P = V - (f / df) * D;
    vec3 hp = waterHeightAndSlope(P.xy);
    if (!(abs(P.z - hp.x) < abs(f))) return V;
    N = normalize(vec3(-hp.yz, 1.0));
    return P;
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
