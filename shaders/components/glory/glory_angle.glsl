// The glory table's angles (src/components/glory/optics/glory_table.h, AngleGrid): gloryCount
// samples evenly over [0, span] from the antisolar point, then wideCount samples evenly over the
// remaining wideSpan = pi - span. The continuous sample index of the angle gamma from the antisolar
// point; shared by the shader's lookup and the C++ table (src/common/glsl.h).
real gloryAngleIndex(real gamma, real span, real wideSpan, real gloryCount, real wideCount)
{
    real g = clamp(gamma, real(0.0), span + wideSpan);
    if (g <= span)
        return g / span * (gloryCount - real(1.0));
    return (gloryCount - real(1.0)) + (g - span) / wideSpan * wideCount;
}
