#version 130
// The near-plane cap. Where the near plane lies on the other side of the surface than the eye,
// the eye's ray met the surface before the near plane, which clipped that bit of surface away:
// without this the frame would show the scene behind it untinted, or the clear colour. Here the
// crossing S on the pixel's ray (eye to near plane) is found by bisection on the animated height,
// and the surface is shaded at S exactly as water.frag would.
#pragma include "waves.glsl"
#pragma include "watershade.glsl"

uniform float osgWater_WaveBound; // the sum of the wave amplitudes: |height - level| never exceeds it

in vec4 vNear;
in vec4 vFar;

float owSurfaceOffset(vec3 p)
{
#ifdef OSGWATER_GRID
    return p.z - waterHeight(p.xy);
#else
    return p.z - osgWater_Level;
#endif
}

void main()
{
    if (!(abs(vNear.w) > 1e-20)) discard;
    vec3 P = vNear.xyz / vNear.w;
#ifdef OSGWATER_EYE_BELOW
    const bool below = true;
#else
    const bool below = false;
#endif
    // cheap test first: a near point beyond the crests (troughs) on the eye's side needs no cap,
    // which is every pixel unless the eye is within a near-plane distance of the water
    float dz = P.z - osgWater_Level;
    if (below ? dz < -osgWater_WaveBound : dz > osgWater_WaveBound) discard;
    vec3 C = osgWater_EyeLocal;
    // The first point on the eye's side of the surface (the CPU's verdict, OSGWATER_EYE_BELOW) and
    // the next one on the other: at distances from the eye halving from the near plane's, read
    // from the eye outwards. An eye a hair from the water sees the surface cross its rays within
    // millimetres of it, and some rays come back to the eye's side before the near plane; the
    // near point alone would call them uncrossed.
    vec3 a = C, b = P;
    bool crossed = false;
#ifdef OSGWATER_GRID
    for (int i = 15; i > 0 && !crossed; --i) {
        vec3 m = C + (P - C) * exp2(-float(i));
        if ((owSurfaceOffset(m) < 0.0) == below) a = m;
        else { b = m; crossed = true; }
    }
#endif
    if (!crossed) {
        float fP = owSurfaceOffset(P);
        if (below ? fP < 0.0 : fP >= 0.0) discard; // same side as the eye: the surface itself is drawn
    }
    // bisection: a stays on the eye's side, b on the other
    for (int i = 0; i < 16; ++i) {
        vec3 m = 0.5 * (a + b);
        bool mBelow = owSurfaceOffset(m) < 0.0;
        if (mBelow == below) a = m; else b = m;
    }
    vec3 S = 0.5 * (a + b);
    vec3 D = owSafeNormalize(P - C, owSafeNormalize(vFar.xyz / vFar.w - P, vec3(0.0, 0.0, -1.0)));
#ifdef OSGWATER_GRID
    vec4 hsr = waterSlopesAndRoughness(S.xy);
    vec3 N = normalize(vec3(-hsr.yz, 1.0));
    float roughness = hsr.w;
#else
    vec3 N = vec3(0.0, 0.0, 1.0);
    const float roughness = 0.0;
#endif
    vec4 debugHit;
    vec3 color = owShadeWater(S, N, -D, roughness, debugHit);
    gl_FragColor = owWaterFragment(S, S, N, roughness, color, debugHit);
}
