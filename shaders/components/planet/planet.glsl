// Planet: a sphere of radius uPlanetRadiusKm centred at the origin, dark night ground.
uniform float uPlanetRadiusKm;
uniform float uCameraAltitudeKm; // |camera| - planet radius, from double precision
uniform vec3 uPlanetRadiance;

// The ground closes the ray, seen through the lower atmosphere.
Ray shadeGround(Ray ray)
{
    if (ray.groundT >= 0.0)
        ray.radiance += uPlanetRadiance * ray.transmittance;
    return ray;
}
