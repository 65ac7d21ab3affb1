// Shows a rendered tile in a window: exposure, then the tone curve of render/tone_map.glsl, the
// same text io::toneMapPixel (src/io/tone_map.h) evaluates for wall.png; over it, when shown, the
// heads-up display (render/hud_font.h) in the top-left corner: its text white on the image darkened.
uniform sampler2D uTile;
uniform float uExposure;
uniform int uCurve; // TONE_MAP_ACES_FILMIC or TONE_MAP_MAGNITUDE_GAMMA
uniform sampler2D uHud; // the HUD's mask, rows top-down: 1 text, 0 the box behind it
uniform int uHudScale;  // window pixels per mask pixel; 0: no HUD

out vec4 fragColour;

const int kHudOffsetPx = 8; // from the window's top and left edges
const float kHudBoxDimming = 0.3;

vec3 withHud(vec3 colour)
{
    if (uHudScale == 0)
        return colour;
    // The window pixel counted from the top-left corner (the window is the tile's size).
    const ivec2 fromTopLeft = ivec2(int(gl_FragCoord.x), textureSize(uTile, 0).y - 1 - int(gl_FragCoord.y));
    const ivec2 p = fromTopLeft - kHudOffsetPx;
    if (any(lessThan(p, ivec2(0))))
        return colour;
    const ivec2 mask = p / uHudScale;
    if (any(greaterThanEqual(mask, textureSize(uHud, 0))))
        return colour;
    return mix(kHudBoxDimming * colour, vec3(1.0), texelFetch(uHud, mask, 0).r);
}

void main()
{
    vec3 x = texelFetch(uTile, ivec2(gl_FragCoord.xy), 0).rgb * uExposure;
    x = clamp(x, vec3(0.0), vec3(65504.0)); // NaN and out-of-gamut negatives become 0 on every GPU we know
    fragColour = vec4(withHud(toneCurve(x, uCurve)), 1.0);
}
