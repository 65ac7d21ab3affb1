// The ray of this fragment, from the wall's physical geometry (src/wall/tile_rays.*).
// The direction through canvas point (px, py) (x right, y down, pixel centres at +0.5) is
// uRayOrigin + px uRayStepRight + py uRayStepDown, already rotated into the planet frame on
// the CPU in double precision. Tiles of one flat wall share these three vectors and differ
// only in the integer uPixelOffset, so both sides of a seam compute identical rays.
uniform vec3 uRayOrigin;
uniform vec3 uRayStepRight;
uniform vec3 uRayStepDown;
uniform vec2 uPixelOffset; // integers, exact in float
uniform int uTileHeight;
uniform float uPixelAngle; // angular size of one pixel at the canvas origin (radians)

vec3 fragmentRayDirection()
{
    // gl_FragCoord is bottom-up with centres at +0.5; canvas rows run top-down.
    vec2 canvas = uPixelOffset + vec2(gl_FragCoord.x, float(uTileHeight) - gl_FragCoord.y);
    return normalize(uRayOrigin + canvas.x * uRayStepRight + canvas.y * uRayStepDown);
}
