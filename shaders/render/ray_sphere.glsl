// Ray-sphere intersection, shared by the shader and the C++ tests (see src/common/glsl.h).
//
// Ray x(t) = o + t d with |d| = 1, sphere |x| = r centred at the origin; `heightAbove` is
// |o| - r computed by the caller in double precision (the camera's altitude above this
// sphere), because |o| - r in float32 loses everything below half a metre at 6371 km.
// Stable form (Haines et al., "Precision improvements for ray/sphere intersection",
// Ray Tracing Gems, 2019, ch. 7):
//   b = dot(o, d); the discriminant is r^2 - |o - b d|^2, written as a product of a
//   difference and a sum so it does not cancel for rays far from the centre;
//   q = -b - sign(b) sqrt(disc) is one root without cancellation, c/q the other, with
//   c = |o|^2 - r^2 = heightAbove (|o| + r).
// Returns (t_near, t_far); a miss returns (1, -1), an empty interval (t_near > t_far).
vec2 raySphere(vec3 o, vec3 d, real r, real heightAbove)
{
    real b = dot(o, d);
    real closest = length(o - b * d);
    real disc = (r - closest) * (r + closest);
    if (disc < real(0.0))
        return vec2(real(1.0), real(-1.0));
    real c = heightAbove * (length(o) + r);
    real q = -b - (b >= real(0.0) ? real(1.0) : real(-1.0)) * sqrt(disc);
    if (q == real(0.0)) // ray from the centre's tangent point: both roots are at 0
        return vec2(real(0.0), real(0.0));
    real t1 = q;
    real t2 = c / q;
    return vec2(min(t1, t2), max(t1, t2));
}

// The part of the ray with t in [0, tMax] inside the spherical shell rInner < |x| < rOuter,
// as up to two intervals in order along the ray (the ray may cross the inner sphere's shadow).
// With a single part it is `first`; unused intervals are empty (x > y). Heights are |o| - rInner and |o| - rOuter from the caller, in double.
struct ShellSegments {
    vec2 first;
    vec2 second;
};

ShellSegments rayShell(vec3 o, vec3 d, real rInner, real heightAboveInner, real rOuter, real heightAboveOuter,
                       real tMax)
{
    ShellSegments s;
    s.first = vec2(real(1.0), real(-1.0));
    s.second = vec2(real(1.0), real(-1.0));
    vec2 outer = raySphere(o, d, rOuter, heightAboveOuter);
    outer.x = max(outer.x, real(0.0));
    outer.y = min(outer.y, tMax);
    if (outer.x >= outer.y)
        return s;
    vec2 inner = raySphere(o, d, rInner, heightAboveInner);
    if (inner.x >= inner.y || inner.y <= outer.x || inner.x >= outer.y) {
        s.first = outer;
        return s;
    }
    s.first = vec2(outer.x, max(outer.x, inner.x));
    s.second = vec2(min(outer.y, inner.y), outer.y);
    if (s.first.x >= s.first.y) { // the ray starts inside the inner sphere: one part, put it first
        s.first = s.second;
        s.second = vec2(real(1.0), real(-1.0));
    }
    return s;
}
