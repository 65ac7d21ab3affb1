// Planet: a sphere of radius uPlanetRadiusKm centred at the origin, dark night ground.
uniform float uPlanetRadiusKm;
uniform float uCameraAltitudeKm; // |camera| - planet radius, from double precision
uniform vec3 uPlanetRadiance;
