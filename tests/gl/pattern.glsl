// Test pattern: a smooth function of the pixel centre that exercises transcendentals. Shared
// GLSL/C++ module (common/glsl.h); every channel stays in [1, 4] so relative errors are meaningful,
// and sin and cos take arguments in [−π, π], where Vulkan bounds their error.
vec4 testPattern(vec2 fragCoord, vec2 size)
{
    vec2 p = fragCoord / size;
    vec3 n = normalize(vec3(p.x - real(0.5), p.y - real(0.5), real(1)));
    real a = real(2) + sin(real(6) * p.x - real(3)) * exp(real(-1.5) * p.y);
    real b = pow(real(1) + p.x * p.y, real(2.5));
    real c = real(3) + n.x + n.y * cos(real(3) * p.y);
    real d = log(real(2) + p.x) + sqrt(real(1) + p.y) * n.z;
    return vec4(a, b, c, d);
}
