// Where the footprint direction n projects on the great-circle segment from a to b (unit vectors
// from the planet's centre, `length` km of arclength apart on the sphere of radius R). Shared by
// the shader and the CPU reference (src/common/glsl.h).

// The unit normal of the segment's great circle, pointing to the side where the lateral distance is
// positive. cross(a, b - a), not cross(a, b): for points kilometres apart the latter cancels to about 4
// digits in float and tilts the great circle by up to a kilometre at the segment's end.
vec3 segmentNormal(vec3 a, vec3 b)
{
    return normalize(cross(a, b - a));
}

// With the segment's normal already known: (km along from a, length, signed lateral distance km,
// distance beyond the segment's ends km).
vec4 projectOnSegmentWithNormal(vec3 a, vec3 normal, real length, vec3 n, real R)
{
    real along = R * atan(dot(cross(a, n), normal), dot(a, n));
    real lateral = R * asin(clamp(dot(n, normal), real(-1.0), real(1.0)));
    return vec4(along, length, lateral, max(max(-along, along - length), real(0.0)));
}

vec4 projectOnSegment(vec3 a, vec3 b, real length, vec3 n, real R)
{
    return projectOnSegmentWithNormal(a, segmentNormal(a, b), length, n, R);
}

// The signed curvature (1/km, positive where the polyline bends towards `normal`) at its point `corner`,
// the end of a segment of `inner` km on the great circle of unit normal `normal`, from the point `beyond`
// `outer` km past it (on either side): a curve of curvature κ through three points d1 and d2 apart passes
// the third κ d2 (d1 + d2) / 2 off the great circle through the first two, to first order in κ d.
// beyond − corner, not beyond alone: the difference keeps the offset's digits in float. The points are
// floats, ~1e-7 R apart from where they belong, so next to a segment of metres the offset is rounding;
// the turn at the corner, κ (d1 + d2) / 2, is then held to the polyline's largest (`largestTurn`, rad).
real polylineCurvature(vec3 corner, vec3 beyond, vec3 normal, real inner, real outer, real R, real largestTurn)
{
    real bound = real(2.0) * largestTurn / max(inner + outer, real(1e-6));
    real curvature = real(2.0) * R * dot(beyond - corner, normal) / max(outer * (inner + outer), real(1e-6));
    return clamp(curvature, -bound, bound);
}
