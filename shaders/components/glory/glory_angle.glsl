// The glory table's angles (src/components/glory/optics/glory_table.h, AngleGrid) in three even
// segments from the antisolar point: counts.x samples over [0, spans.x] (the glory's rings, the first
// at 0), counts.y over the next spans.y (the cloudbow and the side scattering), counts.z over the last
// spans.z up to pi (the forward diffraction peak around the light). The continuous sample index of
// the angle gamma from the antisolar point; shared by the shader's lookup and the C++ table
// (src/common/glsl.h).
real gloryAngleIndex(real gamma, vec3 spans, vec3 counts)
{
    real g = clamp(gamma, real(0.0), spans.x + spans.y + spans.z);
    if (g <= spans.x)
        return g / spans.x * (counts.x - real(1.0));
    if (g <= spans.x + spans.y)
        return (counts.x - real(1.0)) + (g - spans.x) / spans.y * counts.y;
    return (counts.x - real(1.0)) + counts.y + (g - spans.x - spans.y) / spans.z * counts.z;
}
