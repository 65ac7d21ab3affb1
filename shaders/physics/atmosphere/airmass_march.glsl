// 16-step numerical march (requires airmass_common.glsl): the midpoint rule
//   I ≈ Σ_{i=0}^{15} Δx·ρ(x0 + (i + ½)·Δx),   Δx = (x1 − x0)/16,
// the classic per-pixel loop of real-time atmosphere shaders, kept as the cost and accuracy yardstick.
real airmassMarch16(vec3 origin, vec3 direction, real t0, real t1, real H, real R)
{
    vec3 frame = airmassRayFrame(origin, direction, t0, t1);
    real dx = (frame.z - frame.y) / real(16);
    real sum = real(0);
    for (int i = 0; i < 16; ++i) {
        sum += airmassDensity(frame.x, frame.y + (real(i) + real(0.5)) * dx, H, R);
    }
    return sum * dx;
}
