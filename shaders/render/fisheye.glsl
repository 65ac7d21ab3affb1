// Angular fisheye (azimuthal equidistant projection), the format of planetarium dome masters
// (P. Bourke, "Dome master format", paulbourke.net/dome): the angle from the dome's axis grows
// linearly with the distance from the image centre, theta = |offset| * radiansPerPx, and the
// azimuth is the direction of the offset in the image. Shared by the shader and the CPU (C++).

// Unit direction of the pixel at offsetPx from the image centre (x right, y down, pixels), for a
// dome whose axis, image-right and image-down directions are the orthonormal axis, right, down.
// Exactly theta from the axis for theta in [0, pi].
vec3 fisheyeDirection(vec2 offsetPx, real radiansPerPx, vec3 axis, vec3 right, vec3 down)
{
    real r = length(offsetPx);
    if (r == real(0))
        return axis;
    real theta = r * radiansPerPx;
    vec2 azimuth = offsetPx / r;
    return cos(theta) * axis + sin(theta) * (azimuth.x * right + azimuth.y * down);
}

// Whether the pixel at offsetPx from the image centre lies inside the dome's circle of radiusPx.
bool insideFisheye(vec2 offsetPx, real radiusPx)
{
    return dot(offsetPx, offsetPx) <= radiusPx * radiusPx;
}
