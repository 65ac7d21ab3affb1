// Entry point: one fragment = one pixel's ray, relative to the camera.
// Radiance is written linear (RGB in the scene's radiance unit) into an RGBA32F target; alpha holds
// the ray's work (1 + its aurora samples), with which the load balancer splits the measured time of a
// draw among the bands it covered (src/app/balanced_frame.h). Images keep alpha 1 (io/half_pixels.h).
uniform vec3 uCameraPositionKm; // camera relative to the planet centre, planet frame

out vec4 fragRadiance;

void main()
{
    vec3 direction = fragmentRayDirection();
    vec3 radiance = shadeRay(uCameraPositionKm, direction);
#ifdef HAS_AURORA
    fragRadiance = vec4(radiance, 1.0 + float(gAuroraSamples));
#else
    fragRadiance = vec4(radiance, 1.0);
#endif
}
