// Which layers a ray meets, and in what order (Lawlor & Genetti 2011, section 3.1, figure 8).
// Shared by the shader and the C++ tests (src/common/glsl.h); needs render/ray_sphere.glsl.
//
// The ray x(t) = o + t d, t >= 0, |d| = 1, starts at the camera, `altitude` km above the ground
// (from double precision). The layers are concentric shells that never overlap: the ground
// (radius R), the lower atmosphere up to R + atmosphereTop, and the aurora between
// R + auroraBottom and R + auroraTop (auroraBottom > atmosphereTop). So along any ray the order
// is fixed: aurora -> atmosphere -> aurora -> ground or space, and each aurora part lies wholly
// in front of or wholly behind the atmosphere. A viewer inside a layer starts mid-sequence.
struct RayLayers {
    bool insideGround;  // the camera is below the surface: nothing is seen
    real groundT;       // where the ray meets the ground; negative if it never does
    vec2 atmosphere;    // the part inside the lower atmosphere (empty when x >= y)
    vec2 auroraNear;    // the parts inside the aurora shell, in order along the ray
    vec2 auroraFar;
};

RayLayers rayLayers(vec3 o, vec3 d, real R, real altitude, real atmosphereTop, real auroraBottom, real auroraTop)
{
    RayLayers l;
    l.insideGround = altitude < real(0.0);
    l.groundT = real(-1.0);
    real end = real(1e30);
    vec2 ground = raySphere(o, d, R, altitude);
    if (ground.x <= ground.y && ground.y > real(0.0)) {
        l.groundT = max(ground.x, real(0.0));
        end = l.groundT;
    }
    l.atmosphere = raySphere(o, d, R + atmosphereTop, altitude - atmosphereTop);
    l.atmosphere = vec2(max(l.atmosphere.x, real(0.0)), min(l.atmosphere.y, end));
    ShellSegments shell = rayShell(o, d, R + auroraBottom, altitude - auroraBottom, R + auroraTop, altitude - auroraTop, end);
    l.auroraNear = shell.first;
    l.auroraFar = shell.second;
    return l;
}

// Does the part `segment` of the ray lie behind the lower atmosphere, so that its light is
// attenuated by the atmosphere's transmittance on the way to the camera?
bool behindAtmosphere(vec2 segment, vec2 atmosphere)
{
    return atmosphere.x < atmosphere.y && segment.x >= atmosphere.y;
}
