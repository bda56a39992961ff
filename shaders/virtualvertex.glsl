// Refraction by virtual vertices (the geometric-refraction thesis, ch. 3), per vertex of the scene
// the refraction pass draws from above the water: each true vertex T under the water moves to
// where it appears, so the pass draws the underwater scene as the eye sees it through the waves
// and the water shader reads it at the surface point's own place. Mirrored by
// osgWater/optics/VirtualVertices.h (double precision; SightPoint::Solved).
// The membrane: the waves faceted on a square grid of osgWater_MembraneCell metres, the analytic
// normal at each grid vertex. Each facet's cell is bounded by the refraction rays through its
// vertices (eq. 2.2; eq. 3.1 and 3.2 where Snell gives none, so no facet loses its cell). A vertex
// looks for its cell among the 3 x 3 grid squares around the point where the waves' exact
// refracted ray through it leaves the water (found first, by Newton's method); the first cell that
// holds it, the middle square first, gives its virtual vertex (the thesis's first-virtual-vertex
// rule in zones of convergence: the cell around the exact refracted ray comes first). The sight point is placed on that facet by the thesis's linear
// interpolation, then solved on the facet (the refraction through the interpolated normal passes
// through T: exact on flat water), and the virtual vertex lies on the eye's ray through it,
// eta times as far beyond it as T is (eq. 2.4). A vertex no cell holds (rare: an extrapolated ray,
// a grazing eye) moves by the exact sight point.
#pragma include "waves.glsl"

uniform vec2 osgWater_IOR;              // (air, water)
uniform float osgWater_MembraneCell;    // the membrane's facets, metres across
uniform mat4 osgWater_LocalToEye;       // the water's local frame -> this pass's eye space

vec3 vvUnitOr(vec3 v, vec3 fallback)
{
    float l2 = dot(v, v);
    return l2 > 1e-20 ? v * inversesqrt(l2) : fallback;
}

// The thesis's refraction ray for the unit sight direction I at a point of unit normal N (eye
// side), eta = n_eye / n_other: Snell (eq. 2.2), a sight ray that leaves the membrane's eye side
// taken as grazing (eq. 3.1), total internal reflection's root negated (eq. 3.2). Always finite.
vec3 vvRefractionRay(vec3 I, vec3 N, float eta)
{
    float c = dot(I, N);
    vec3 tangential = c > 0.0 ? eta * I : eta * (I - c * N);
    c = min(c, 0.0);
    float k = 1.0 - eta * eta * (1.0 - c * c);
    return vvUnitOr(tangential - sign(k) * sqrt(abs(k)) * N, -N);
}

// The membrane vertex of grid index ij, and its unit normal
vec3 vvMembraneVertex(vec2 ij, out vec3 N)
{
    vec2 p = ij * osgWater_MembraneCell;
    vec3 hs = waterHeightAndSlope(p);
    N = normalize(vec3(-hs.yz, 1.0));
    return vec3(p, hs.x);
}

// Flat water at the level: the horizontal distance r from the eye's foot where the refracted ray
// to a point `depth` below the level and `L` away (horizontally) leaves the water, eye `H` above
// the level, and the derivative of that ray's reach with r (for Newton on the waves). The reach
// r + depth tan(theta_t) grows with r: Newton from the straight line's crossing, kept in [r0, L].
float vvFlatCrossing(float H, float depth, float L, float eta, out float reachSlope)
{
    float r0 = L * H / max(H + depth, 1e-6), r = r0;
    reachSlope = 1.0;
    for (int k = 0; k < 6; ++k) {
        float q = inversesqrt(r * r + H * H);
        float st = eta * r * q;
        float ct2 = max(1.0 - st * st, 1e-6);
        reachSlope = 1.0 + depth * eta * H * H * q * q * q / (ct2 * sqrt(ct2));
        float reach = r + depth * st * inversesqrt(ct2);
        r = clamp(r - (reach - L) / reachSlope, r0, L);
    }
    return r;
}

// Where the waves' refracted ray from the eye C to T leaves the water (xy), by Newton's method
// from the flat water's answer (its Jacobian kept: the waves tilt the ray by little).
vec2 vvExactSightPoint(vec3 C, vec3 T, float eta)
{
    vec2 toT = T.xy - C.xy;
    float L = length(toT);
    vec2 u = L > 1e-6 ? toT / L : vec2(1.0, 0.0), v = vec2(-u.y, u.x);
    float reachSlope;
    float r = vvFlatCrossing(max(C.z - osgWater_Level, 1e-3), max(osgWater_Level - T.z, 0.0), L, eta, reachSlope);
    float tangentialSlope = r > 1e-6 ? L / r : 1.0;
    vec2 s = C.xy + r * u;
    for (int k = 0; k < 3; ++k) {
        vec3 hs = waterHeightAndSlope(s);
        vec3 S = vec3(s, hs.x);
        vec3 R = vvRefractionRay(vvUnitOr(S - C, vec3(0.0, 0.0, -1.0)), normalize(vec3(-hs.yz, 1.0)), eta);
        vec2 miss = T.xy - (S.xy + R.xy * (T.z - S.z) / min(R.z, -1e-4));
        s += u * (dot(miss, u) / reachSlope) + v * (dot(miss, v) / tangentialSlope);
    }
    return s;
}

// The thesis's containment test (§3.1.2): T's barycentric coordinates in the cell's section by the
// plane through T normal to the mean of the facet's rays; false where T is not in the cell (or
// lies on the facet's near side).
bool vvInCell(vec3 P0, vec3 P1, vec3 P2, vec3 d0, vec3 d1, vec3 d2, vec3 T, out vec3 b)
{
    b = vec3(0.0);
    vec3 n = vvUnitOr(d0 + d1 + d2, vec3(0.0));
    vec3 den = vec3(dot(d0, n), dot(d1, n), dot(d2, n));
    if (!all(greaterThan(den, vec3(1e-6)))) return false;
    vec3 t = vec3(dot(T - P0, n), dot(T - P1, n), dot(T - P2, n)) / den;
    if (any(lessThan(t, vec3(0.0)))) return false;
    vec3 Q0 = P0 + t.x * d0, e0 = P1 + t.y * d1 - Q0, e1 = P2 + t.z * d2 - Q0, p = T - Q0;
    float d00 = dot(e0, e0), d01 = dot(e0, e1), d11 = dot(e1, e1), d20 = dot(p, e0), d21 = dot(p, e1);
    float det = d00 * d11 - d01 * d01;
    if (!(abs(det) > 1e-12 * d00 * d11)) return false;
    float bv = (d11 * d20 - d01 * d21) / det, bw = (d00 * d21 - d01 * d20) / det;
    b = vec3(1.0 - bv - bw, bv, bw);
    return all(greaterThanEqual(b, vec3(-1e-5)));
}

// How far T lies off the ray refracted on the facet at barycentric b (the cross product of the
// ray and the unit direction to T), and that facet point S.
vec3 vvMissOnFacet(vec3 P0, vec3 P1, vec3 P2, vec3 N0, vec3 N1, vec3 N2, vec3 C, vec3 T, float eta, vec3 b, out vec3 S)
{
    S = b.x * P0 + b.y * P1 + b.z * P2;
    vec3 N = vvUnitOr(b.x * N0 + b.y * N1 + b.z * N2, N0);
    vec3 r = vvRefractionRay(vvUnitOr(S - C, -N), N, eta);
    return cross(r, vvUnitOr(T - S, r));
}

// The sight point on a facet: from the linear placement b, two Gauss-Newton steps on (v, w)
// (forward differences) until the refraction there passes through T.
vec3 vvSolvedSightPoint(vec3 P0, vec3 P1, vec3 P2, vec3 N0, vec3 N1, vec3 N2, vec3 C, vec3 T, float eta, vec3 b)
{
    const float h = 1e-3;
    vec3 S;
    for (int k = 0; k < 2; ++k) {
        vec3 g = vvMissOnFacet(P0, P1, P2, N0, N1, N2, C, T, eta, b, S);
        vec3 jv = (vvMissOnFacet(P0, P1, P2, N0, N1, N2, C, T, eta, b + vec3(-h, h, 0.0), S) - g) / h;
        vec3 jw = (vvMissOnFacet(P0, P1, P2, N0, N1, N2, C, T, eta, b + vec3(-h, 0.0, h), S) - g) / h;
        float a = dot(jv, jv), c = dot(jv, jw), d = dot(jw, jw);
        float det = a * d - c * c;
        if (!(abs(det) > 1e-20)) break;
        float rv = -dot(jv, g), rw = -dot(jw, g);
        float dv = (d * rv - c * rw) / det, dw = (a * rw - c * rv) / det;
        b += vec3(-dv - dw, dv, dw);
    }
    return b.x * P0 + b.y * P1 + b.z * P2;
}

// The virtual vertex of T (local frame), seen from the eye C above the water.
vec3 vvVirtualVertex(vec3 C, vec3 T)
{
    // above the level: the band the pass keeps to clear the crests, drawn where it is (no early
    // return: a vertex that returned still runs a loop until every vertex beside it is done)
    if (T.z >= osgWater_Level) return T;
    float eta = osgWater_IOR.x / osgWater_IOR.y;
    vec2 s = vvExactSightPoint(C, T, eta);
    // the square under s first, then its eight neighbours; two facets each. A square's membrane
    // vertices are made when it is tried: nearly every vertex stops at the first square
    const vec2 order[9] = vec2[9](vec2(0.0, 0.0), vec2(-1.0, 0.0), vec2(1.0, 0.0), vec2(0.0, -1.0), vec2(0.0, 1.0),
                                  vec2(-1.0, -1.0), vec2(1.0, -1.0), vec2(-1.0, 1.0), vec2(1.0, 1.0));
    vec2 under = floor(s / osgWater_MembraneCell);
    // the facet found, its corners' indices in the square and T's barycentric coordinates there
    bool found = false;
    vec3 P[4], N[4], b;
    int k1 = 1, k2 = 2;
    for (int q = 0; q < 9 && T.z < osgWater_Level; ++q) {
        vec3 d[4]; // the square's corners (0,0), (1,0), (1,1), (0,1)
        for (int k = 0; k < 4; ++k) {
            P[k] = vvMembraneVertex(under + order[q] + vec2(k == 1 || k == 2 ? 1.0 : 0.0, k >= 2 ? 1.0 : 0.0), N[k]);
            d[k] = vvRefractionRay(vvUnitOr(P[k] - C, -N[k]), N[k], eta);
        }
        found = vvInCell(P[0], P[1], P[2], d[0], d[1], d[2], T, b);
        if (!found) {
            k1 = 2;
            k2 = 3;
            found = vvInCell(P[0], P[2], P[3], d[0], d[2], d[3], T, b);
        }
        if (found) break; // a loop stops once every vertex it runs for has broken out
        k1 = 1;
        k2 = 2;
    }
    // no cell holds T: the exact sight point
    vec3 S = found ? vvSolvedSightPoint(P[0], P[k1], P[k2], N[0], N[k1], N[k2], C, T, eta, b)
                   : vec3(s, waterHeight(s));
    return S + vvUnitOr(S - C, S - T) * (eta * length(T - S));
}
