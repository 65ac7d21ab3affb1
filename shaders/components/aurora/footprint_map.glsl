// The footprint map (src/components/aurora/physics/footprint_map.h): an azimuthal equidistant projection of the sphere
// around a centre direction, mapping angle θ from the centre linearly to radius θ/Θ · 1/2 from the middle
// of the [0, 1]² map (Snyder, "Map Projections — A Working Manual", USGS PP 1395, 1987, §25, oblique
// aspect on the sphere). Map x points east at the centre, map y north: north = cross(centre, east).
// One text for GLSL and C++ (src/common/glsl.h): `real` is float on the GPU, float or double on the CPU.
// Needs render/angle.glsl.
//
// Uniform conventions: centre and east are unit vectors (east ⟂ centre), angularRadius Θ in radians
// (0 < Θ ≤ π/2), size = N texels per side, texel (i, j) covers [i, i + 1]/N × [j, j + 1]/N, j = 0 the
// bottom row (the first row uploaded).

// Map coordinate of a unit direction d. With x = d·east, y = d·north we have (x, y) = sin θ (cos α, sin α),
// α the azimuth, so the equidistant position (θ/Θ)(cos α, sin α)/2 + 1/2 is (x, y) · θ/(2Θ sin θ) + 1/2.
vec2 footprintMapCoord(vec3 unitDir, vec3 centre, vec3 east, real angularRadius)
{
    vec3 north = cross(centre, east);
    vec2 xy = vec2(dot(unitDir, east), dot(unitDir, north));
    real sinTheta = length(xy);
    real theta = angleBetween(unitDir, centre);
    real thetaOverSin = sinTheta > real(0.0) ? theta / sinTheta : real(1.0);
    return vec2(real(0.5), real(0.5)) + (real(0.5) * thetaOverSin / angularRadius) * xy;
}

// Inverse of footprintMapCoord: q = 2Θ (coord − 1/2) has length θ and the azimuth's direction, so
// d = cos θ · centre + (sin θ / θ)(q.x east + q.y north).
vec3 footprintMapDirection(vec2 coord, vec3 centre, vec3 east, real angularRadius)
{
    vec3 north = cross(centre, east);
    vec2 q = real(2.0) * angularRadius * (coord - vec2(real(0.5), real(0.5)));
    real theta = length(q);
    real sinOverTheta = theta > real(0.0) ? sin(theta) / theta : real(1.0);
    return cos(theta) * centre + sinOverTheta * (q.x * east + q.y * north);
}

// The texel (i, j) that contains map coordinate coord: floor(coord · N), clamped to [0, N − 1] so the map's
// right and top edges belong to the last texel. The shader reads it with texelFetch(map, ivec2(texel), 0).
vec2 footprintMapTexel(vec2 coord, real size)
{
    return clamp(floor(coord * size), vec2(real(0.0), real(0.0)), vec2(size - real(1.0), size - real(1.0)));
}

// Distance in km from direction d to the cap θ ≤ Θ around the centre, R (θ − Θ); negative inside the cap.
// Every curtain lies inside the cap, so where this is positive it is a lower bound of the distance to every
// curtain (the "far" case: the map is not read there).
real footprintMapOutsideKm(vec3 unitDir, vec3 centre, real angularRadius, real planetRadiusKm)
{
    return planetRadiusKm * (angleBetween(unitDir, centre) - angularRadius);
}

// Lower bound in km of the distance from any point of a texel to the nearest curtain polyline: the texel's
// stored seed distance less the map's margin (FootprintMap::marginKm), at least 0.
real footprintConservativeKm(real storedDistanceKm, real marginKm)
{
    return max(storedDistanceKm - marginKm, real(0.0));
}
