// The plasma box along a ray: where the ray crosses it, and its density's integral there. Shared by
// the shader and C++ (src/common/glsl.h); the caller defines real plasmaBoxDensity(vec3 unit) first,
// unit the point in the box's coordinates scaled to [0, 1]. Box frame: centred at 0, km.

// The part [t0, t1] of o + t d (|d| = 1) inside the cube of half side h, by slabs (Kay & Kajiya 1986):
// each axis keeps the t where |o_i + t d_i| <= h. An axis along which the ray does not move keeps all
// t or none, so no division by zero. Empty when t0 >= t1.
vec2 plasmaBoxSegment(vec3 o, vec3 d, real h)
{
    real t0 = real(-1e30);
    real t1 = real(1e30);
    for (int i = 0; i < 3; ++i) {
        if (abs(d[i]) < real(1e-12)) {
            if (abs(o[i]) > h)
                return vec2(real(1), real(0));
        } else {
            real a = (-h - o[i]) / d[i];
            real b = (h - o[i]) / d[i];
            t0 = max(t0, min(a, b));
            t1 = min(t1, max(a, b));
        }
    }
    return vec2(t0, t1);
}

// The integral of the density (times km) over [segment.x, segment.y] by the midpoint rule of
// `steps` equal steps: exact for a uniform density, second order otherwise.
real plasmaBoxColumn(vec3 o, vec3 d, vec2 segment, int steps, real side)
{
    real dt = (segment.y - segment.x) / real(steps);
    real sum = real(0);
    for (int i = 0; i < steps; ++i) {
        vec3 p = o + (segment.x + (real(i) + real(0.5)) * dt) * d;
        sum += plasmaBoxDensity(p / side + vec3(real(0.5)));
    }
    return sum * dt;
}
