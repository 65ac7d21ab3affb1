// The ray of this fragment (src/wall/tile_rays.*), from the wall's physical geometry or, for a
// dome master, from the angular fisheye of render/fisheye.glsl.
// Flat: the direction through canvas point (px, py) (x right, y down, pixel centres at +0.5) is
// uRayOrigin + px uRayStepRight + py uRayStepDown, already rotated into the planet frame on
// the CPU in double precision. Tiles of one flat wall share these three vectors and differ
// only in the integer uPixelOffset, so both sides of a seam compute identical rays. A side-by-side
// stereo screen starts the columns from uSplitX on at the right eye, uRayOriginRight.
// Dome: the offset of (px, py) from uDomeCentre sets the angle from uDomeAxis (uDomeRadiansPerPixel
// per pixel) and the azimuth between uDomeRight and uDomeDown; every tile shares these uniforms.
uniform vec3 uRayOrigin;
uniform vec3 uRayStepRight;
uniform vec3 uRayStepDown;
uniform vec3 uRayOriginRight;
uniform float uSplitX;     // beyond every canvas column unless the screen is side by side
uniform vec2 uPixelOffset; // integers, exact in float
uniform int uTileHeight;
uniform float uPixelAngle; // angular size of one pixel at the canvas origin (radians)

uniform int uDome;         // 1: dome master, 0: flat
uniform vec2 uDomeCentre;  // canvas coordinate of the image centre
uniform float uDomeRadius; // image circle, pixels
uniform float uDomeRadiansPerPixel;
uniform vec3 uDomeAxis;    // planet frame, orthonormal
uniform vec3 uDomeRight;
uniform vec3 uDomeDown;

// Where the rays start (src/cluster/frame_state.h, rayStart): uRayStartKm from double; a far
// camera's rays each moved uRayStartDistanceKm along themselves. The flat wall's three vectors again,
// split into their part across the view's forward direction uViewForward (xyz) and along it (w), so
// that a narrow view's d - forward is formed without cancellation.
uniform vec3 uRayStartKm;
uniform float uRayStartDistanceKm; // 0: the rays start at the camera, uRayStartKm
uniform vec3 uViewForward;
uniform vec4 uRayOriginSplit;
uniform vec4 uRayStepRightSplit;
uniform vec4 uRayStepDownSplit;
uniform vec4 uRayOriginRightSplit;

// The centre of this invocation's pixel in the tile, bottom-up with centres at +0.5 (gl_FragCoord.xy
// of the fragment march), set by the entry point; canvas rows run top-down.
vec2 gPixelCentre;

vec2 fragmentCanvasPosition()
{
    return uPixelOffset + vec2(gPixelCentre.x, float(uTileHeight) - gPixelCentre.y);
}

// False for the pixels of a dome master outside its image circle, which stay black.
bool fragmentInImage()
{
    return uDome == 0 || insideFisheye(fragmentCanvasPosition() - uDomeCentre, uDomeRadius);
}

vec3 fragmentRayDirection()
{
    vec2 canvas = fragmentCanvasPosition();
    if (uDome != 0)
        return fisheyeDirection(canvas - uDomeCentre, uDomeRadiansPerPixel, uDomeAxis, uDomeRight, uDomeDown);
    vec3 origin = canvas.x >= uSplitX ? uRayOriginRight : uRayOrigin;
    return normalize(origin + canvas.x * uRayStepRight + canvas.y * uRayStepDown);
}

// direction - uViewForward for this fragment's unit ray direction. A flat wall's ray within 45
// degrees of forward is u across it at unit distance along it: d = (forward + u) / s with
// s = sqrt(1 + |u|^2), so d - forward = (u - forward |u|^2 / (1 + s)) / s, to float's relative
// precision however narrow the view. Other rays (a dome's, a wide view's) subtract, to float's
// absolute precision, which their own width far exceeds.
vec3 fragmentRayOffsetFromForward(vec3 direction)
{
    vec2 canvas = fragmentCanvasPosition();
    vec4 v = (canvas.x >= uSplitX ? uRayOriginRightSplit : uRayOriginSplit) + canvas.x * uRayStepRightSplit +
             canvas.y * uRayStepDownSplit;
    if (uDome != 0 || v.w < length(v.xyz))
        return direction - uViewForward;
    vec3 u = v.xyz / v.w;
    float uu = dot(u, u);
    float s = sqrt(1.0 + uu);
    return (u - uViewForward * (uu / (1.0 + s))) / s;
}

// Where the ray of unit direction `direction` starts: planet frame, km.
vec3 fragmentRayStart(vec3 direction)
{
    if (uRayStartDistanceKm == 0.0)
        return uRayStartKm;
    return uRayStartKm + uRayStartDistanceKm * fragmentRayOffsetFromForward(direction);
}
