#include "optics/VirtualVertices.h"
#include <osgWater/WaterSurface>
#include <algorithm>
#include <cmath>

namespace osgWater { namespace virtualvertices {

namespace {

glm::dvec3 unitOr(const glm::dvec3& v, const glm::dvec3& fallback)
{
    const double l = glm::length(v);
    return (l > 1e-300 && std::isfinite(l)) ? v / l : fallback;
}

//! Barycentric coordinates of P in triangle ABC (P in its plane); false for a degenerate triangle.
bool barycentric(const glm::dvec3& P, const glm::dvec3& A, const glm::dvec3& B, const glm::dvec3& C, glm::dvec3& b)
{
    const glm::dvec3 e0 = B - A, e1 = C - A, p = P - A;
    const double d00 = glm::dot(e0, e0), d01 = glm::dot(e0, e1), d11 = glm::dot(e1, e1);
    const double d20 = glm::dot(p, e0), d21 = glm::dot(p, e1);
    const double det = d00 * d11 - d01 * d01;
    if (!(std::fabs(det) > 1e-24 * d00 * d11)) return false;
    const double v = (d11 * d20 - d01 * d21) / det;
    const double w = (d00 * d21 - d01 * d20) / det;
    b = glm::dvec3(1.0 - v - w, v, w);
    return true;
}

struct Facet {
    glm::dvec3 P[3], N[3], d[3];
    bool extrapolated = false;
};

Facet facetOf(const Cells& cells, int f)
{
    const Membrane& m = *cells.membrane;
    Facet out;
    for (int k = 0; k < 3; ++k) {
        const int i = m.facets[f][k];
        out.P[k] = m.positions[i];
        out.N[k] = m.normals[i];
        out.d[k] = cells.rays[i].direction;
        out.extrapolated = out.extrapolated || cells.rays[i].kind != RayKind::Refracted;
    }
    return out;
}

//! The thesis's containment test (§3.1.2): the cell's section by the plane through T whose normal is
//! the mean of the facet's rays; T's barycentric coordinates in that section. A vertex on the
//! facet's near side (a ray meets the plane behind the facet) is not in the cell.
bool inCell(const Facet& f, const glm::dvec3& T, glm::dvec3& b)
{
    const glm::dvec3 sum = f.d[0] + f.d[1] + f.d[2];
    const double l = glm::length(sum);
    if (!(l > 1e-12)) return false;
    const glm::dvec3 n = sum / l;
    glm::dvec3 Q[3];
    for (int k = 0; k < 3; ++k) {
        const double denom = glm::dot(f.d[k], n);
        if (!(denom > 1e-12)) return false;
        const double t = glm::dot(T - f.P[k], n) / denom;
        if (t < 0.0) return false;
        Q[k] = f.P[k] + t * f.d[k];
    }
    if (!barycentric(T, Q[0], Q[1], Q[2], b)) return false;
    const double eps = -1e-12;
    return b.x >= eps && b.y >= eps && b.z >= eps;
}

//! The ray refracted at the facet point of barycentric coordinates b, and that point.
glm::dvec3 refractedAt(const Facet& f, const glm::dvec3& eye, double eta, const glm::dvec3& b, glm::dvec3& S)
{
    S = b.x * f.P[0] + b.y * f.P[1] + b.z * f.P[2];
    const glm::dvec3 N = unitOr(b.x * f.N[0] + b.y * f.N[1] + b.z * f.N[2], f.N[0]);
    return refractionRay(unitOr(S - eye, -N), N, eta).direction;
}

//! How far T lies off the ray refracted at b: the cross product of the ray and the unit direction
//! to T (zero when T is on it).
glm::dvec3 missAt(const Facet& f, const glm::dvec3& eye, double eta, const glm::dvec3& T, const glm::dvec3& b)
{
    glm::dvec3 S;
    const glm::dvec3 r = refractedAt(f, eye, eta, b, S);
    return glm::cross(r, unitOr(T - S, r));
}

//! Gauss-Newton on the barycentric coordinates (v, w), from the thesis's linear placement: the
//! residual has three components and two unknowns and vanishes at the solution, so it converges
//! quadratically; the Jacobian by central differences.
glm::dvec3 solveSightPoint(const Facet& f, const glm::dvec3& eye, double eta, const glm::dvec3& T, glm::dvec3 b)
{
    const double h = 1e-7;
    for (int iteration = 0; iteration < 30; ++iteration) {
        const glm::dvec3 g = missAt(f, eye, eta, T, b);
        if (glm::length(g) < 1e-15) break;
        const glm::dvec3 jv = (missAt(f, eye, eta, T, b + glm::dvec3(-h, h, 0)) -
                               missAt(f, eye, eta, T, b + glm::dvec3(h, -h, 0))) / (2.0 * h);
        const glm::dvec3 jw = (missAt(f, eye, eta, T, b + glm::dvec3(-h, 0, h)) -
                               missAt(f, eye, eta, T, b + glm::dvec3(h, 0, -h))) / (2.0 * h);
        const double a = glm::dot(jv, jv), c = glm::dot(jv, jw), d = glm::dot(jw, jw);
        const double det = a * d - c * c;
        if (!(std::fabs(det) > 1e-30)) break;
        const double rv = -glm::dot(jv, g), rw = -glm::dot(jw, g);
        const double dv = (d * rv - c * rw) / det, dw = (a * rw - c * rv) / det;
        if (!std::isfinite(dv) || !std::isfinite(dw)) break;
        b += glm::dvec3(-dv - dw, dv, dw);
        if (std::fabs(dv) + std::fabs(dw) < 1e-16) break;
    }
    return b;
}

} // namespace

RefractionRay refractionRay(const glm::dvec3& I, const glm::dvec3& N, double eta)
{
    RefractionRay ray;
    double c = glm::dot(I, N);  // < 0 where the sight ray enters from the eye's side
    glm::dvec3 tangential = eta * (I - c * N);
    if (c > 0.0) {
        // eq. 3.1: the dot product taken as zero (the sight ray treated as grazing)
        ray.kind = RayKind::FacingAway;
        c = 0.0;
        tangential = eta * I;
    }
    const double k = 1.0 - eta * eta * (1.0 - c * c);
    glm::dvec3 R;
    if (k >= 0.0) {
        R = tangential - std::sqrt(k) * N;
    } else {
        // eq. 3.2: the root of the negated argument, negated: a ray that leaves on the eye's side
        if (ray.kind == RayKind::Refracted) ray.kind = RayKind::TotallyReflected;
        R = tangential + std::sqrt(-k) * N;
    }
    ray.direction = unitOr(R, -N);
    return ray;
}

Cells buildCells(const Membrane& membrane, const glm::dvec3& eye, double nEye, double nOther)
{
    Cells cells;
    cells.membrane = &membrane;
    cells.eye = eye;
    cells.eta = nEye / nOther;
    cells.rays.reserve(membrane.positions.size());
    for (std::size_t i = 0; i < membrane.positions.size(); ++i) {
        const glm::dvec3& N = membrane.normals[i];
        cells.rays.push_back(refractionRay(unitOr(membrane.positions[i] - eye, -N), N, cells.eta));
    }
    return cells;
}

double membraneCellSize(const WaterSurface& surface)
{
    double cell = surface.getSize() / double(std::max(surface.getResolution(), 2u) - 1);
    const double shortest = surface.getShortestWavelength(); // the sum's or the wind's
    if (shortest > 0.0) cell = std::min(cell, shortest / 8.0);
    return cell;
}

glm::dvec3 foreshortened(const glm::dvec3& eye, const glm::dvec3& S, const glm::dvec3& T, double eta)
{
    return S + unitOr(S - eye, S - T) * (eta * glm::length(T - S));
}

VirtualVertex virtualVertex(const Cells& cells, const glm::dvec3& T, SightPoint method, bool countCells)
{
    VirtualVertex out;
    if (!cells.membrane) return out;
    const int facets = int(cells.membrane->facets.size());
    for (int i = 0; i < facets; ++i) {
        const Facet f = facetOf(cells, i);
        glm::dvec3 b;
        if (!inCell(f, T, b)) continue;
        ++out.containingCells;
        if (!out.found) {
            out.found = true;
            out.facet = i;
            out.extrapolated = f.extrapolated;
            out.barycentric = method == SightPoint::Solved ? solveSightPoint(f, cells.eye, cells.eta, T, b) : b;
            const glm::dvec3& w = out.barycentric;
            out.sightPoint = w.x * f.P[0] + w.y * f.P[1] + w.z * f.P[2];
            out.position = foreshortened(cells.eye, out.sightPoint, T, cells.eta);
        }
        if (!countCells) break;
    }
    return out;
}

} }
