// One pixel's ray, shared by the two entry points of the march (main.frag, main.comp): the caller
// sets gPixelCentre (tile_rays.glsl), and gets the radiance, linear RGB in the scene's radiance
// unit with alpha 1, and the ray's work, 1 + its aurora samples, with which the load balancer shares
// the measured time of a draw among the bands it covered (src/gl/float_target.h).
uniform vec3 uCameraPositionKm; // camera relative to the planet centre, planet frame

void shadePixel(out vec4 radiance, out float work)
{
    work = 1.0;
    if (!fragmentInImage()) {
        radiance = vec4(0.0, 0.0, 0.0, 1.0);
        return;
    }
    radiance = vec4(shadeRay(uCameraPositionKm, fragmentRayDirection()), 1.0);
#ifdef HAS_AURORA
    work = 1.0 + float(gAuroraSamples);
#endif
}
