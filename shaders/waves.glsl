#pragma import_defines(OSGWATER_WIND, OSGWATER_CHOPPY)
// The waves: the surface's height, slopes and normal, and what the drawn mesh may miss of them.
uniform float osgWater_Level;

#ifdef OSGWATER_WIND
// The wind's waves (OSGWATER_WIND): the sum of the FFT cascades' tiles, each a layer of
// osgWater_WaveCascades holding (h, dh/dx, dh/dy) with its mip levels. Texel i of a tile of side L
// sampled n times is the FFT's sample at x = i L / n: its centre, (i + 1/2) / n in texture
// coordinates. Mirrored by WaveCascades::sample (bilinear, level 0) through WaterSurface::height.
uniform sampler2DArray osgWater_WaveCascades;
uniform sampler2DArray osgWater_WaveHeights; // the same layers' heights alone, level 0
uniform vec4 osgWater_Cascades[5];    // per cascade: (1 / tile, height bound, the band's top k, 0)
uniform int osgWater_CascadeCount;
uniform float osgWater_CascadeTexels; // texels along a tile's side
uniform float osgWater_UnresolvedSlopes; // the slopes' variance no cascade holds (to Cox and Munk's)

// metres the shaded point's pixel spans on the water: the mip level the cascades are read at (0
// reads the texels as the CPU does). Set by a fragment shader's main before it asks for the waves.
float waterFootprint = 0.0;

// The footprint of a pixel whose corners lie dx, dy apart on the water (its local x, y: a fragment
// shader's dFdx, dFdy): the side of the square with its area, the one isotropic filter that averages
// as many texels as the pixel covers. At grazing angles the pixel is long along the view and narrow
// across it; its longer side blurred away the waves running along the view that the pixel does
// resolve, and the image and the refraction's lookups drifted off the reference's (the lake at
// 320x180, low grazing: mean CIEDE2000 2.36 -> 2.07; the refraction's pixels beyond their own
// rays' fan by over 2 px 5.0% -> 0.8%)
float waterFootprintOf(vec2 dx, vec2 dy)
{
    return sqrt(abs(dx.x * dy.y - dx.y * dy.x));
}

#ifdef OSGWATER_CHOPPY
// Choppy waves (OSGWATER_CHOPPY): the point q of the undisplaced tiles lands at q + D(q), at the
// height h(q). osgWater_WaveHeights holds (h, Dx, Dy) per layer, osgWater_WaveJacobians the
// displacement's derivatives (dDx/dx, dDy/dy, dDx/dy), mipmapped. Mirrored by WaveCascades::height
// and normal (SpectralWaves).
uniform sampler2DArray osgWater_WaveJacobians;
uniform float osgWater_ChoppyChord; // SpectralWaves::choppyChord
const float kMinStretch = 0.1;      // WaveCascades::MIN_STRETCH

// (h, Dx, Dy) at the undisplaced point q: every cascade at level 0, bilinear
vec3 waterDisplacementAt(vec2 q)
{
    vec3 d = vec3(0.0);
    for (int c = 0; c < 5; ++c) {
        if (c >= osgWater_CascadeCount) break;
        vec4 s = osgWater_Cascades[c];
        d += textureLod(osgWater_WaveHeights, vec3(q * s.x + 0.5 / osgWater_CascadeTexels, float(c)), 0.0).xyz;
    }
    return d;
}

// The undisplaced point whose displacement lands on p, and (h, Dx, Dy) there: fixed-point
// iteration q = p - D(q) from q = p. Each step shrinks the miss by the displacement's derivatives
// (about 0.1, at a squeezed crest 0.5): two leave a lake's few centimetres of displacement well
// under a millimetre off, where the CPU's query iterates until it settles.
const int kChoppyIterations = 2;

vec2 waterUndisplaced(vec2 p, out vec3 d)
{
    vec2 q = p;
    d = waterDisplacementAt(q);
    for (int i = 0; i < kChoppyIterations; ++i) {
        q = p - d.yz;
        d = waterDisplacementAt(q);
    }
    return q;
}

// the displaced surface's slopes from the undisplaced one's, g, and the displacement's derivatives
// J there: J's inverse applied to g (WaveCascades::Texel::displacedSlope)
vec2 waterDisplacedSlope(vec3 J, vec2 g)
{
    float xx = 1.0 + J.x, yy = 1.0 + J.y, xy = J.z;
    return vec2(yy * g.x - xy * g.y, xx * g.y - xy * g.x) / max(xx * yy - xy * xy, kMinStretch);
}
#endif

// (height, dh/dx, dh/dy, roughness) filtered over `footprint` metres. The roughness is the slopes'
// variance the point's normal does not show: per cascade, the mean |grad h|^2 under the filter less
// the square of the mean slopes (what the filtering averaged away; the cascades are independent, so
// their variances add), plus the slopes no cascade holds.
vec4 waterSampleWithRoughness(vec2 p, float footprint)
{
#ifdef OSGWATER_CHOPPY
    // read where the point over p came from (found at level 0: far off the short waves' few
    // millimetres of displacement no longer matter); the roughness is the undisplaced slopes'
    vec3 d;
    p = waterUndisplaced(p, d);
    vec3 J = vec3(0.0);
#endif
    vec4 r = vec4(osgWater_Level, 0.0, 0.0, osgWater_UnresolvedSlopes);
    // (a cascade the footprint averages whole, its lod past the last level, reads its tile's mean:
    // taking that from a uniform instead of the read saved no frame on the lake, 0.995x, 95%
    // 0.982-1.021 over 16 pairs, and is not done)
    for (int c = 0; c < 5; ++c) {
        if (c >= osgWater_CascadeCount) break;
        vec4 s = osgWater_Cascades[c];
        float lod = log2(max(footprint * s.x * osgWater_CascadeTexels, 1e-6));
        vec3 at = vec3(p * s.x + 0.5 / osgWater_CascadeTexels, float(c));
        vec4 t = textureLod(osgWater_WaveCascades, at, lod);
        r += vec4(t.xyz, max(t.w - dot(t.yz, t.yz), 0.0));
#ifdef OSGWATER_CHOPPY
        J += textureLod(osgWater_WaveJacobians, at, lod).xyz;
#endif
    }
#ifdef OSGWATER_CHOPPY
    r.yz = waterDisplacedSlope(J, r.yz);
#endif
    return r;
}

// (height, dh/dx, dh/dy) filtered over `footprint` metres
vec3 waterSampleOver(vec2 p, float footprint)
{
    return waterSampleWithRoughness(p, footprint).xyz;
}

// The height at level 0, bilinear, from the heights' own one-channel texture: what the CPU's
// query reads, at a fraction of the cost of a filtered four-channel read, where the sight ray's
// search reads it several times a fragment
float waterHeight(vec2 p)
{
#ifdef OSGWATER_CHOPPY
    vec3 d;
    waterUndisplaced(p, d);
    return osgWater_Level + d.x;
#else
    float h = osgWater_Level;
    for (int c = 0; c < 5; ++c) {
        if (c >= osgWater_CascadeCount) break;
        vec4 s = osgWater_Cascades[c];
        h += textureLod(osgWater_WaveHeights, vec3(p * s.x + 0.5 / osgWater_CascadeTexels, float(c)), 0.0).x;
    }
    return h;
#endif
}

// The height a mesh whose cells are `cell` metres across draws: the cascades averaged over two
// cells, so the waves shorter than two cells, which the cells could only alias, are gone.
float waterHeightDrawn(vec2 p, float cell)
{
    return waterSampleOver(p, 2.0 * cell).x;
}

vec3 waterHeightAndSlope(vec2 p)
{
    return waterSampleOver(p, waterFootprint);
}

// (height, dh/dx, dh/dy, the slopes' variance below the pixel: its roughness) at the footprint
vec4 waterSlopesAndRoughness(vec2 p)
{
    return waterSampleWithRoughness(p, waterFootprint);
}

// How far a mesh whose cells are `cell` metres across, with triangle sides up to `chord`, can lie
// from the surface: each cascade taken as one wave as high as its height bound and as short as its
// band's shortest, faded (or cut into chords) as the sum of sines' waves are. Choppy, a chord spans
// more of the undisplaced wave where a crest is squeezed (osgWater_ChoppyChord times as much at most).
float waterDrawnErrorBound(float cell, float chord, bool faded)
{
#ifdef OSGWATER_CHOPPY
    float span = chord * osgWater_ChoppyChord;
#else
    float span = chord;
#endif
    float e = 0.0;
    for (int c = 0; c < 5; ++c) {
        if (c >= osgWater_CascadeCount) break;
        vec4 s = osgWater_Cascades[c];
        float cellsPerWave = 6.2831853 / (max(s.z, 1e-9) * cell);
        float keep = faded ? smoothstep(2.0, 4.0, cellsPerWave) : 1.0;
        e += s.y * (1.0 - keep * cos(3.1415927 * min(span * max(s.z, 1e-9) / 6.2831853, 1.0)));
    }
    return e;
}

vec3 waterNormal(vec2 p)
{
    return normalize(vec3(-waterSampleOver(p, waterFootprint).yz, 1.0));
}
#else
// Sum of sines: h = level + sum a_i sin(k_i . xy - phase_i). Mirrored by WaterSurface::height/normal.
// Phases arrive wrapped to [0, 2 pi) from the CPU (double precision), so time never grows here.
uniform vec4 osgWater_Waves[8];      // (k dir.x, k dir.y, amplitude, 0)
uniform float osgWater_WavePhases[8];
uniform int osgWater_WaveCount;

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

// How many cells `cell` metres across span one wavelength of wave w (k dir.x, k dir.y, ...)
float waterCellsPerWave(vec4 w, float cell)
{
    return 6.2831853 / (max(length(w.xy), 1e-9) * cell);
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
        h += smoothstep(2.0, 4.0, waterCellsPerWave(w, cell)) * w.z * sin(dot(w.xy, p) - osgWater_WavePhases[i]);
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

// How far a mesh whose cells are `cell` metres across, with triangle sides up to `chord`, can lie
// from the analytic surface: per wave, what its fade leaves out (`faded`: the vertices at
// waterHeightDrawn, else at waterHeight) and the sag of a chord between vertices,
// a (1 - cos(pi chord / wavelength)), at most 2a for a wave the chords alias.
float waterDrawnErrorBound(float cell, float chord, bool faded)
{
    float e = 0.0;
    for (int i = 0; i < 8; ++i) {
        if (i >= osgWater_WaveCount) break;
        vec4 w = osgWater_Waves[i];
        float cellsPerWave = waterCellsPerWave(w, cell);
        float keep = faded ? smoothstep(2.0, 4.0, cellsPerWave) : 1.0;
        e += abs(w.z) * (1.0 - keep * cos(3.1415927 * min(chord / (cell * cellsPerWave), 1.0)));
    }
    return e;
}

// the sum's waves are all drawn: no roughness
vec4 waterSlopesAndRoughness(vec2 p)
{
    return vec4(waterHeightAndSlope(p), 0.0);
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
#endif

// The same for a mesh whose triangles' sides are no longer than its cells (the uniform grid's:
// its diagonals, a sqrt 2 longer, the thesis's grid has always taken as the side).
float waterDrawnErrorBound(float cell, bool faded)
{
    return waterDrawnErrorBound(cell, cell, faded);
}

// Where the line P + t D meets the waves, by one Newton step on f = z - h from P: the t of the
// step. hs: (h, dh/dx, dh/dy) at P.xy. A line along the surface (f' = 0) does not move.
float waterNewtonStep(vec3 P, vec3 D, vec3 hs)
{
    float df = D.z - dot(hs.yz, D.xy);
    return -(P.z - hs.x) / (abs(df) > 1e-6 ? df : 1e30);
}

// Where the line of sight from C through V first meets the analytic surface, and the unit normal
// there. V: a point of a drawn mesh within `bound` metres of the surface, up or down; eyeSide: 1
// for an eye above the surface, -1 below. The surface can only cross the ray where the ray lies
// within `bound` of V's height: a window around V. Its start lies on the eye's side; the first
// sign change of f = z - h on a few samples across the window brackets the crossing, and regula
// falsi (Illinois) closes in on it. No sign change (the window's start already past a crest the
// ray grazed before V, or a crest between two samples): V itself. The slope the normal needs then
// gives one Newton step for free, kept inside the bracket. One path for every fragment, at most
// eight height evaluations and one of the slope: llvmpipe pays for every side of a branch (early
// exits measured no faster), so there is no cheaper path to branch to. Nor does the error budget
// skip it where the mesh is seen within a quarter pixel of the waves: what a pixel shows is read
// along the normal there, and over the wind's ripples a quarter pixel of place moved the mirror
// rays' hits by 2.4 texels (p99; marched 0.26), for no frame time saved here (the frame 1.004x
// over 16 pairs, with a grazing view's heights a pixel down from 3.9 to 3.0). What a fragment shades: the
// drawn mesh only decides which pixels hold water. `roughness`: the slopes' variance below the
// pixel there (waterSlopesAndRoughness; 0 for the sum's waves, all drawn), from the same reads.
#ifdef OSGWATER_WIND
// (each of the wind's samples reads every cascade's texture: two samples find the crossing as
// often to within a centimetre, 0.07% of pixels against 0.04% with four, for 10% less frame)
const int kSightSamples = 2;
#else
const int kSightSamples = 4;
#endif
const int kSightRefinements = 3;

// How many heights the march evaluated on this fragment (the work debug output counts them)
int waterHeightReads = 0;

float waterAbove(vec3 C, vec3 D, float t, float eyeSide)
{
    ++waterHeightReads;
    vec3 P = C + t * D;
    return eyeSide * (P.z - waterHeight(P.xy));
}

vec3 waterOnSightRay(vec3 C, vec3 V, float bound, float eyeSide, out vec3 N, out float roughness)
{
    vec3 D = V - C;
    float s = max(length(D), 1e-9);
    D /= s;
    float w = bound / max(abs(D.z), 1e-3);
    float tLo = max(s - w, 0.0), fLo = waterAbove(C, D, tLo, eyeSide);
    float tHi = -1.0, fHi = 0.0;
    for (int k = 1; k <= kSightSamples; ++k) {
        if (!(fLo > 0.0) || tHi >= 0.0) break; // the window starts past the surface, or bracketed
        float t = s + w * (2.0 * float(k) / float(kSightSamples) - 1.0);
        float f = waterAbove(C, D, t, eyeSide);
        if (f <= 0.0) { tHi = t; fHi = f; }
        else { tLo = t; fLo = f; }
    }
    int side = 0;
    for (int k = 0; k < kSightRefinements; ++k) {
        if (tHi < 0.0) break;
        float t = tLo + (tHi - tLo) * fLo / (fLo - fHi);
        float f = waterAbove(C, D, t, eyeSide);
        if (f > 0.0) { tLo = t; fLo = f; if (side < 0) fHi *= 0.5; side = -1; }
        else { tHi = t; fHi = f; if (side > 0) fLo *= 0.5; side = 1; }
    }
    vec3 P = tHi < 0.0 ? V : C + (tLo + (tHi - tLo) * fLo / (fLo - fHi)) * D;
    vec4 hsr = waterSlopesAndRoughness(P.xy); // the same reads as the slopes alone
    vec3 hs = hsr.xyz;
    roughness = hsr.w;
    N = normalize(vec3(-hs.yz, 1.0));
    // the slope the normal needs gives a last Newton step for free, kept inside the bracket
    float t = dot(P - C, D) + waterNewtonStep(P, D, hs);
    if (tHi >= 0.0) t = clamp(t, min(tLo, tHi), max(tLo, tHi));
    return C + t * D;
}

// Where a steep line through V (unit direction D) meets the waves, and the unit normal there; V
// lies within `bound` metres of the surface, up or down. Newton steps from V, each kept in the
// window where the line lies within `bound` of V's height. Where the line is steeper than the
// waves can slope, f' = D.z - grad h . D.xy keeps its sign, f has one root in the window and
// Newton closes in on it fast (the lake: slopes up to 0.49 against a sun whose rays lean by 0.57,
// f' > 0.6). For the sun's photons: as exact as waterOnSightRay's bracket on the lake's
// caustics, in three evaluations of the waves against nine.
const int kSteepSteps = 2;

vec3 waterOnSteepLine(vec3 V, vec3 D, float bound, out vec3 N)
{
    float w = bound / max(abs(D.z), 1e-3), t = 0.0;
    for (int k = 0; k < kSteepSteps; ++k) {
        vec3 P = V + t * D;
        t = clamp(t + waterNewtonStep(P, D, waterHeightAndSlope(P.xy)), -w, w);
    }
    vec3 P = V + t * D;
    N = normalize(vec3(-waterHeightAndSlope(P.xy).yz, 1.0));
    return P;
}

