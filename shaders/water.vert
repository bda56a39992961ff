#version 130
#pragma import_defines(OSGWATER_GRID, OSGWATER_RINGS)
// The water surface, in the WaterNode's local frame (z up). OSGWATER_GRID: the built-in mesh,
// displaced by the waves; OSGWATER_RINGS: that mesh is WaterSurface::MESH_EYE_RINGS, placed here
// around the point under this view's eye (mirrored by WaterSurface::ringRadius / ringCellSize).
#pragma include "waves.glsl"

out vec3 vLocal;
out vec3 vMeshNormal;
out float vDrawnError; // how far the drawn mesh can lie from the analytic surface here, metres

#if defined(OSGWATER_GRID) && !defined(OSGWATER_RINGS)
uniform float osgWater_GridCell; // the uniform grid's spacing, metres
#endif

#ifdef OSGWATER_RINGS
uniform vec3 osgWater_EyeLocal;
uniform vec4 osgWater_SurfaceSquare; // (x0, y0, x1, y1): the built-in mesh's square
const float kRingCount = 256.0;      // WaterSurface::RING_COUNT
const float kRingSegments = 128.0;   // WaterSurface::RING_SEGMENTS
const float kRingInnerHeight = 0.01; // WaterSurface::RING_INNER_HEIGHT

// gl_Vertex: ring i of the rings evenly spaced out to the square's corners (WaterSurface::buildRings);
// `cell`: the size of its cells, `diagonal`: their triangles' longest side
vec4 ringVertex(out float cell, out float diagonal)
{
    vec2 centre = 0.5 * (osgWater_SurfaceSquare.xy + osgWater_SurfaceSquare.zw);
    vec2 fromCentre = gl_Vertex.xy - centre;
    float nominal = length(fromCentre);
    float i = floor(nominal / (0.70710678 * (osgWater_SurfaceSquare.z - osgWater_SurfaceSquare.x)) * kRingCount + 0.5);
    vec2 dir = nominal > 0.0 ? fromCentre / nominal : vec2(1.0, 0.0);

    vec2 c = osgWater_EyeLocal.xy;
    float h = max(abs(osgWater_EyeLocal.z - osgWater_Level), kRingInnerHeight);
    vec2 far = max(abs(c - osgWater_SurfaceSquare.xy), abs(c - osgWater_SurfaceSquare.zw));
    // (never thinner radially than a cell is wide: see WaterSurface::MESH_EYE_RINGS)
    float growth = max(asinh(length(far) / h) / kRingCount, 6.2831853 / kRingSegments);
    float r = h * sinh(growth * i);
    // the cell: its radial span, the larger; its triangles' longest side is its diagonal
    cell = growth * sqrt(r * r + h * h);
    float around = 6.2831853 * r / kRingSegments;
    diagonal = sqrt(cell * cell + around * around);
    // pulled onto the square: a triangle of clamped vertices lies inside it, and the rings, which
    // reach past it, still cover all of it (no discard off the square, which would keep a GPU from
    // testing depth before shading)
    vec2 p = clamp(c + r * dir, osgWater_SurfaceSquare.xy, osgWater_SurfaceSquare.zw);
    return vec4(p, waterHeightDrawn(p, cell), 1.0);
}
#endif

void main()
{
    vec4 v = gl_Vertex;
    vDrawnError = 0.0;
#if defined(OSGWATER_RINGS)
    float cell, diagonal;
    v = ringVertex(cell, diagonal);
    vDrawnError = waterDrawnErrorBound(cell, diagonal, true);
#elif defined(OSGWATER_GRID)
    v.z = waterHeight(v.xy);
    vDrawnError = waterDrawnErrorBound(osgWater_GridCell, false);
#endif
    vLocal = v.xyz;
    vMeshNormal = gl_Normal;
    gl_Position = gl_ModelViewProjectionMatrix * v;
}
