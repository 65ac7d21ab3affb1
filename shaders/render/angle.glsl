// Angle between unit vectors a and b, accurate at all angles (Kahan 2006, "How futile are mindless
// assessments of roundoff in floating-point computation?", §12): θ = 2 atan(|a − b| / |a + b|)
// (acos(a·b) loses half its digits near 0 and π). Shared by the shaders and the C++ code that needs
// the same angle (src/common/glsl.h); for antipodal vectors |a + b| = 0 and θ = π.
real angleBetween(vec3 a, vec3 b)
{
    return real(2.0) * atan(length(a - b) / length(a + b));
}
