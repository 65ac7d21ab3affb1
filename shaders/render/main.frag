// Entry point: one fragment = one pixel's ray, relative to the camera.
// Radiance is written linear (RGB in the scene's radiance unit) into an RGBA32F target.
uniform vec3 uCameraPositionKm; // camera relative to the planet centre, planet frame

out vec4 fragRadiance;

void main()
{
    vec3 direction = fragmentRayDirection();
    fragRadiance = vec4(shadeRay(uCameraPositionKm, direction), 1.0);
}
