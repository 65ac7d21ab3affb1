// CIE 1931 XYZ to linear sRGB, and the gamut mapping every spectral colour of the renderer goes
// through. Shared by the shaders and the C++ code (src/common/glsl.h).

// Linear sRGB from CIE XYZ with the IEC 61966-2-1 matrix (D65 white: XYZ (0.9505, 1, 1.089) -> (1, 1, 1)).
vec3 xyzToLinearSrgb(vec3 xyz)
{
    return vec3(real(3.2406) * xyz.x - real(1.5372) * xyz.y - real(0.4986) * xyz.z,
                real(-0.9689) * xyz.x + real(1.8758) * xyz.y + real(0.0415) * xyz.z,
                real(0.0557) * xyz.x - real(0.2040) * xyz.y + real(1.0570) * xyz.z);
}

// Luminance of a linear sRGB colour, Y = 0.2126 R + 0.7152 G + 0.0722 B (IEC 61966-2-1).
real linearSrgbLuminance(vec3 rgb)
{
    return real(0.2126) * rgb.r + real(0.7152) * rgb.g + real(0.0722) * rgb.b;
}

// Gamut mapping: c' = Y (1,1,1) + s (c - Y (1,1,1)) with Y = luminance(c) >= 0 and the largest s in
// [0, 1] making every component >= 0, i.e. s = min over negative components c_k of Y / (Y - c_k).
// It moves the colour toward the D65 white along a straight line in XYZ, so Y and the hue are kept
// exactly; only the saturation drops. Components above 1 are kept (the renderer works in HDR).
vec3 desaturateIntoGamut(vec3 rgb)
{
    real luminance = max(linearSrgbLuminance(rgb), real(0.0));
    vec3 grey = vec3(luminance);
    real saturation = real(1.0);
    for (int k = 0; k < 3; ++k) {
        if (rgb[k] < real(0.0))
            saturation = min(saturation, luminance / (luminance - rgb[k]));
    }
    return grey + saturation * (rgb - grey);
}
