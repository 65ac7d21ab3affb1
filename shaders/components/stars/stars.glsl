// Stars: a fixed random field on the celestial sphere, a function of direction only, so every
// tile of the wall sees the same sky. Directions are binned into longitude/latitude cells; a
// cell holds a star with probability uStarDensity, placed in the inner part of the cell and
// drawn as a Gaussian about one pixel wide (uPixelAngle, radians).
uniform float uStarDensity;
uniform float uStarBrightness; // cd/m^2 at the centre of the brightest star

float starHash(vec2 cell, float salt)
{
    // Integer hash (Jarzynski & Olano 2020, PCG-style) of the cell coordinates.
    uvec2 v = uvec2(ivec2(cell) + 65536) * uvec2(1664525u, 1013904223u) + uvec2(uint(salt * 1000.0));
    v.x += v.y * 1664525u;
    v.y += v.x * 1664525u;
    v ^= v >> 16u;
    v.x += v.y * 1664525u;
    v.y += v.x * 1664525u;
    v ^= v >> 16u;
    return float(v.x & 0xffffffu) / 16777216.0;
}

vec3 starRadiance(vec3 d)
{
    const float cells = 1024.0;
    const float pi = 3.14159265358979;
    vec2 angles = vec2(atan(d.y, d.x) + pi, asin(clamp(d.z, -1.0, 1.0)) + 0.5 * pi) / pi; // [0,2] x [0,1]
    vec2 grid = angles * vec2(cells, 0.5 * cells);
    vec2 cell = floor(grid);
    if (starHash(cell, 0.0) > uStarDensity)
        return vec3(0.0);
    vec2 centre = cell + 0.25 + 0.5 * vec2(starHash(cell, 1.0), starHash(cell, 2.0));
    vec2 offsetRad = (grid - centre) * vec2(pi / cells * cos(angles.y * pi - 0.5 * pi), pi / (0.5 * cells));
    float sigma = max(uPixelAngle, 2e-4);
    float magnitude = pow(starHash(cell, 3.0), 4.0); // few bright stars, many faint ones
    vec3 tint = mix(vec3(1.0, 0.8, 0.6), vec3(0.7, 0.8, 1.0), starHash(cell, 4.0));
    return uStarBrightness * magnitude * tint * exp(-dot(offsetRad, offsetRad) / (sigma * sigma));
}

// The stars close a ray that nothing opaque ends, seen through the lower atmosphere.
Ray shadeStars(Ray ray)
{
    if (reachesSpace(ray))
        ray.radiance += starRadiance(ray.direction) * ray.transmittance;
    return ray;
}
