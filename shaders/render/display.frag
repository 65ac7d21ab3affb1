// Shows a rendered tile in a window: exposure, then the tone curve of render/tone_map.glsl, the
// same text io::toneMapPixel (src/io/tone_map.h) evaluates for wall.png.
uniform sampler2D uTile;
uniform float uExposure;
uniform int uCurve; // TONE_MAP_ACES_FILMIC or TONE_MAP_MAGNITUDE_GAMMA

out vec4 fragColour;

void main()
{
    vec3 x = texelFetch(uTile, ivec2(gl_FragCoord.xy), 0).rgb * uExposure;
    x = clamp(x, vec3(0.0), vec3(65504.0)); // NaN and out-of-gamut negatives become 0 on every GPU we know
    fragColour = vec4(toneCurve(x, uCurve), 1.0);
}
