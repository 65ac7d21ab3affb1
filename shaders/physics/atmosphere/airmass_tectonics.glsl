// Tectonics.js quadratic-height airmass (requires airmass_common.glsl).
// Source: C. Davis, "Atmospheric scattering with multiple lights" (Tectonics.js blog),
// raymarching.glsl.c. Around x_b, a fraction b = 0.45 of the way from the surface crossing x0 to the
// top of the atmosphere (6H), the height is replaced by a quadratic stretched by a = 0.45:
//   h(x) ≈ ½·a·h''(x_b)·(x − x_b)² + h'(x_b)·(x − x_b) + h(x_b),
// and the column is integrated by substitution, −H/h'(x_b)·exp(−h/H), on each side of the closest
// approach. Kept exactly as published, including its 1e20 for rays obstructed by the planet and its
// |result| (made signed here like every method).
real airmassTectonics2d(real x_start, real x_stop, real z2, real r, real H)
{
    real a = real(0.45);
    real b = real(0.45);
    real x0 = sqrt(max(r * r - z2, real(0)));
    if (x_start < x0 && -x0 < x_stop && z2 < r * r) return real(1e20);
    real r1 = r + real(6) * H;
    real x1 = sqrt(max(r1 * r1 - z2, real(0)));
    real xb = x0 + (x1 - x0) * b;
    real rb2 = xb * xb + z2;
    real rb = sqrt(rb2);
    real d2hdx2 = z2 / sqrt(rb2 * rb2 * rb2);
    real dhdx = xb / rb;
    real hb = rb - r;
    real dx0 = x0 - xb;
    real dx_stop = abs(x_stop) - xb;
    real dx_start = abs(x_start) - xb;
    real h0 = (real(0.5) * a * d2hdx2 * dx0 + dhdx) * dx0 + hb;
    real h_stop = (real(0.5) * a * d2hdx2 * dx_stop + dhdx) * dx_stop + hb;
    real h_start = (real(0.5) * a * d2hdx2 * dx_start + dhdx) * dx_start + hb;
    real rho0 = exp(-h0 / H);
    real sigma = sign(x_stop) * max(H / dhdx * (rho0 - exp(-h_stop / H)), real(0))
               - sign(x_start) * max(H / dhdx * (rho0 - exp(-h_start / H)), real(0));
    return min(abs(sigma), real(1e20));
}

// The published 3D wrapper (z2 = |P|² − (P·V)², naive as published), for the segment [t0, t1].
real airmassTectonics(vec3 origin, vec3 direction, real t0, real t1, real H, real R)
{
    real directionLength = length(direction);
    if (!(directionLength > real(0))) return real(0);
    vec3 V = direction / directionLength;
    real xz = dot(-origin, V);
    real z2 = dot(origin, origin) - xz * xz;
    real segmentSign = t1 < t0 ? real(-1) : real(1);
    return segmentSign * airmassTectonics2d(min(t0, t1) - xz, max(t0, t1) - xz, z2, R, H);
}
