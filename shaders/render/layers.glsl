// Where a ray meets the layers (Lawlor & Genetti 2011, section 3.1, figure 8): the steps the
// components compose. Shared by the shader and the C++ reference (src/common/glsl.h); needs
// render/ray_sphere.glsl and render/ray.glsl.

// A ray that has met nothing yet.
Ray beginRay(vec3 o, vec3 d, real altitude)
{
    Ray ray;
    ray.origin = o;
    ray.direction = d;
    ray.altitude = altitude;
    ray.blocked = false;
    ray.groundT = real(-1.0);
    ray.end = real(1e30);
    ray.lowerAtmosphere = vec2(real(1.0), real(-1.0));
    ray.transmittance = vec3(real(1.0));
    ray.radiance = vec3(real(0.0));
    return ray;
}

// The ground (a sphere of radius R) ends the ray; a ray that starts `altitude` km above it (a
// camera's from double precision), and below it sees nothing.
Ray boundByGround(Ray ray, real R, real altitude)
{
    ray.altitude = altitude;
    ray.blocked = altitude < real(0.0);
    vec2 ground = raySphere(ray.origin, ray.direction, R, ray.altitude);
    if (ground.x <= ground.y && ground.y > real(0.0)) {
        ray.groundT = max(ground.x, real(0.0));
        ray.end = ray.groundT;
    }
    return ray;
}

// Does the ray leave the planet's layers with nothing opaque ending it (space behind them is seen)?
bool reachesSpace(Ray ray)
{
    return ray.end >= real(1e30);
}

// The part of the ray inside the shell from the ground up to `top` km, before the ray ends.
vec2 lowerShellSegment(Ray ray, real R, real top)
{
    vec2 s = raySphere(ray.origin, ray.direction, R + top, ray.altitude - top);
    return vec2(max(s.x, real(0.0)), min(s.y, ray.end));
}

// Does the part `segment` of the ray lie behind the lower atmosphere, so that its light is
// attenuated by its transmittance on the way to the camera?
bool behindAtmosphere(vec2 segment, vec2 lowerAtmosphere)
{
    return lowerAtmosphere.x < lowerAtmosphere.y && segment.x >= lowerAtmosphere.y;
}

// The transmittance between the camera and an emitting part of the ray.
vec3 transmittanceTo(Ray ray, vec2 segment)
{
    return behindAtmosphere(segment, ray.lowerAtmosphere) ? ray.transmittance : vec3(real(1.0));
}
