// Stars: a fixed random field on the celestial sphere, a function of direction only, so every
// tile of the wall sees the same sky. Directions are binned into longitude/latitude cells; a
// cell holds a star with probability uStarDensity, placed in the inner part of the cell and
// drawn as a Gaussian about one pixel wide (uPixelAngle, radians), the same peak at every
// resolution; a coarse view, whose pixels hold several stars, shows their summed light, and every
// view shows the same stars. A pixel adds up the stars of
// every cell near enough for their Gaussian to reach it (3σ), not only of its own cell: the
// radiance is then a smooth function of the direction, and a last-bit difference in the ray (one
// GPU against another) moves a star's light between neighbouring pixels by as little, instead of
// switching the star on or off where its Gaussian crossed a cell's edge. Gaussians are sampled at
// the pixel centres, at least one pixel wide: the sum over a star's neighbourhood keeps its flux
// within 2·exp(−π²) (Poisson summation) whatever its position within a pixel.
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

// Cells: 2·kStarCells in longitude over 2π (π/kStarCells radians each, times cos(latitude) on the
// sky), kStarCells/2 in latitude over π (2π/kStarCells radians each).
const float kStarCells = 1024.0;

// Whether cell `cell` (wrapped in longitude; none beyond the poles) holds a star.
bool holdsStar(vec2 cell)
{
    return cell.y >= 0.0 && cell.y < 0.5 * kStarCells && starHash(vec2(mod(cell.x, 2.0 * kStarCells), cell.y), 0.0) <= uStarDensity;
}

// The light of the star of cell `cell` (one that holdsStar) at the point `grid` of the cell grid,
// at latitude angle `latitude` (radians), Gaussian width sigma (radians).
vec3 starOfCell(vec2 cell, vec2 grid, float latitude, float sigma)
{
    vec2 wrapped = vec2(mod(cell.x, 2.0 * kStarCells), cell.y);
    vec2 centre = cell + 0.25 + 0.5 * vec2(starHash(wrapped, 1.0), starHash(wrapped, 2.0));
    vec2 offsetRad = (grid - centre) * vec2(kPi / kStarCells * cos(latitude), 2.0 * kPi / kStarCells);
    float magnitude = pow(starHash(wrapped, 3.0), 4.0); // few bright stars, many faint ones
    vec3 tint = mix(vec3(1.0, 0.8, 0.6), vec3(0.7, 0.8, 1.0), starHash(wrapped, 4.0));
    return uStarBrightness * magnitude * tint * exp(-dot(offsetRad, offsetRad) / (sigma * sigma));
}

vec3 starRadiance(vec3 d)
{
    vec2 angles = vec2(atan(d.y, d.x) + kPi, asin(clamp(d.z, -1.0, 1.0)) + 0.5 * kPi) / kPi; // [0,2] x [0,1]
    vec2 grid = angles * vec2(kStarCells, 0.5 * kStarCells);
    vec2 cell = floor(grid);
    float latitude = angles.y * kPi - 0.5 * kPi;
    float sigma = max(uPixelAngle, 2e-4);
    // The cells within 3σ, at most 4 each way (beyond, near the poles, where longitude cells narrow,
    // or at pixels wider than a cell, a star's light is cut at 4 cells), row by row.
    int reachLat = min(4, 1 + int(3.0 * sigma / (2.0 * kPi / kStarCells)));
    int reachLon = min(4, 1 + int(3.0 * sigma / (kPi / kStarCells * max(cos(latitude), 1e-3))));
    vec3 radiance = vec3(0.0);
    // Few cells hold a star, and a SIMD group pays for a branch's body whenever any of its lanes takes it
    // (llvmpipe even when none does), so the inner loop only finds the next cell that holds one; its light
    // is added outside that loop, which a lane leaves once a star. The same cells in the same order as
    // one loop over all of them: the same sum.
    int i = -reachLon;
    int j = -reachLat;
    while (j <= reachLat) {
        for (; j <= reachLat; j = i == -reachLon ? j + 1 : j) {
            if (holdsStar(cell + vec2(i, j)))
                break;
            i = i < reachLon ? i + 1 : -reachLon;
        }
        if (j > reachLat)
            break;
        radiance += starOfCell(cell + vec2(i, j), grid, latitude, sigma);
        i = i < reachLon ? i + 1 : -reachLon;
        j = i == -reachLon ? j + 1 : j;
    }
    return radiance;
}

// The stars close a ray that nothing opaque ends, seen through the lower atmosphere.
Ray shadeStars(Ray ray)
{
    if (reachesSpace(ray))
        ray.radiance += starRadiance(ray.direction) * ray.transmittance;
    return ray;
}
