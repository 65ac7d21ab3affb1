// Entry point: one fragment = one pixel's ray, relative to the camera.
// Radiance is written linear (RGB in the scene's radiance unit, alpha 1) to attachment 0 of the float
// target; the ray's work (1 + its aurora samples) to attachment 1, with which the load balancer
// shares the measured time of a draw among the bands it covered (src/gl/float_target.h).
uniform vec3 uCameraPositionKm; // camera relative to the planet centre, planet frame

layout(location = 0) out vec4 fragRadiance;
layout(location = 1) out float fragWork;

void main()
{
    if (!fragmentInImage()) {
        fragRadiance = vec4(0.0, 0.0, 0.0, 1.0);
        fragWork = 1.0;
        return;
    }
    vec3 direction = fragmentRayDirection();
    vec3 radiance = shadeRay(uCameraPositionKm, direction);
    fragRadiance = vec4(radiance, 1.0);
#ifdef HAS_AURORA
    fragWork = 1.0 + float(gAuroraSamples);
#else
    fragWork = 1.0;
#endif
}
