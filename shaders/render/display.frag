// Shows a rendered tile in a window: exposure, tone curve and sRGB encoding, mirroring
// io::toneMapPixel (src/io/tone_map.h) so the window shows what wall.png shows.
uniform sampler2D uTile;
uniform float uExposure;
uniform int uCurve; // 0: ACES filmic + sRGB, 1: magnitude-preserving gamma

out vec4 fragColour;

float srgbEncode(float x)
{
    return x <= 0.0031308 ? 12.92 * x : 1.055 * pow(x, 1.0 / 2.4) - 0.055;
}

void main()
{
    vec3 x = texelFetch(uTile, ivec2(gl_FragCoord.xy), 0).rgb * uExposure;
    x = clamp(x, vec3(0.0), vec3(65504.0)); // NaN and out-of-gamut negatives become 0 on every GPU we know
    vec3 display;
    if (uCurve == 0) {
        vec3 aces = clamp(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
        display = vec3(srgbEncode(aces.r), srgbEncode(aces.g), srgbEncode(aces.b));
    } else {
        float magnitude = length(x);
        display = magnitude > 0.0 ? x * pow(magnitude, 1.0 / 2.2 - 1.0) : vec3(0.0);
    }
    fragColour = vec4(clamp(display, 0.0, 1.0), 1.0);
}
