// The plasma box: a cube of plasma along the field lines whose electron density glows in the green
// 557.7 nm line (volume emission proportional to n/n0), seen through the lower atmosphere like the
// aurora. The box's place relative to where the rays start (render/tile_rays.glsl) comes from
// double on the CPU, so that a camera close to a small box sees it without float's rounding at
// the planet's size.
uniform vec3 uPlasmaBoxCentreFromRayStart; // km, planet frame
uniform mat3 uPlasmaBoxAxes;             // columns: the box's x (east), y (north), z (up, along the field)
uniform vec3 uPlasmaBoxRgb;              // linear sRGB cd/m^2 per km of path at n = n0

Ray shadePlasmaBox(Ray ray)
{
    int steps = int(uPlasmaBox.y);
    if (steps == 0)
        return ray;
    // The ray's start in the box frame (transpose); exactly -centre at a camera's start.
    vec3 o = ((ray.origin - uRayStartKm) - uPlasmaBoxCentreFromRayStart) * uPlasmaBoxAxes;
    vec3 d = ray.direction * uPlasmaBoxAxes;
    vec2 segment = plasmaBoxSegment(o, d, 0.5 * uPlasmaBox.x);
    segment.x = max(segment.x, 0.0);
    segment.y = min(segment.y, ray.end);
    if (segment.x < segment.y)
        ray.radiance += uPlasmaBoxRgb * transmittanceTo(ray, segment) *
                        plasmaBoxColumn(o, d, segment, steps, uPlasmaBox.x);
    return ray;
}
