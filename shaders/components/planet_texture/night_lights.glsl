// planet_texture: city lights of the night side, an equirectangular texture (longitude -180 deg
// at the left edge, latitude -90 deg at the bottom row), linear, scaled to cd/m^2.
uniform sampler2D uNightLights;
uniform float uNightLightsRadiance;

// n: unit vector from the planet centre in the planet frame (x toward longitude 180 deg,
// y toward 90 deg W, z north), so longitude = atan(-y, -x).
vec3 nightLights(vec3 n)
{
    vec2 uv = vec2(atan(-n.y, -n.x) / (2.0 * kPi) + 0.5, asin(clamp(n.z, -1.0, 1.0)) / kPi + 0.5);
    return uNightLightsRadiance * textureLod(uNightLights, uv, 0.0).rgb;
}

// The lights add to the ground, seen through the lower atmosphere.
Ray shadeNightLights(Ray ray)
{
    if (ray.groundT >= 0.0)
        ray.radiance += nightLights(normalize(ray.origin + ray.end * ray.direction)) * ray.transmittance;
    return ray;
}
