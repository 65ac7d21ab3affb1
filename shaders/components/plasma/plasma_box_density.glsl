// The plasma box's electron density n/n0 at a point of the box, its frames interpolated in time.
// The frames are stacked along z, uPlasmaBoxCells texels each, texel centres at (i + 1/2)/n; across
// the field (x, y) the texture repeats, as the simulation's box does; along z a lookup stays between
// the frame's first and last texel centres, so frames never blend into each other.
uniform sampler3D uPlasmaBoxFrames;
uniform int uPlasmaBoxCells;
uniform vec4 uPlasmaBox; // side km, steps along a ray (0: no box), frame position, frame count

real plasmaBoxFrameDensity(vec3 unit, real frame)
{
    real n = real(uPlasmaBoxCells);
    real z = clamp(unit.z * n, 0.5, n - 0.5) + frame * n;
    return textureLod(uPlasmaBoxFrames, vec3(unit.x, unit.y, z / (n * uPlasmaBox.w)), 0.0).r;
}

// unit: the point in the box's own coordinates, [0, 1] on every axis.
real plasmaBoxDensity(vec3 unit)
{
    real f0 = floor(uPlasmaBox.z);
    real f1 = min(f0 + 1.0, uPlasmaBox.w - 1.0);
    return mix(plasmaBoxFrameDensity(unit, f0), plasmaBoxFrameDensity(unit, f1), uPlasmaBox.z - f0);
}
