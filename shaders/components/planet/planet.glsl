// Planet: a sphere of radius uPlanetRadiusKm centred at the origin, dark night ground.
uniform float uPlanetRadiusKm;
uniform float uCameraAltitudeKm; // |camera| - planet radius, from double precision
uniform vec3 uPlanetRadiance;

// The altitude of the ray's start: the camera's, from double precision, or that of a start moved
// beyond the scene (render/tile_rays.glsl), so high that float's rounding there is of no note.
float rayStartAltitude(Ray ray)
{
    return uRayStartDistanceKm == 0.0 ? uCameraAltitudeKm : length(ray.origin) - uPlanetRadiusKm;
}

// The ground closes the ray, seen through the lower atmosphere.
Ray shadeGround(Ray ray)
{
    if (ray.groundT >= 0.0)
        ray.radiance += uPlanetRadiance * ray.transmittance;
    return ray;
}
