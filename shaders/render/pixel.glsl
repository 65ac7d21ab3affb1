// One pixel's ray, shared by the two entry points of the march (main.frag, main.comp): the caller
// sets gPixelCentre (tile_rays.glsl), and gets the radiance, linear RGB in the scene's radiance
// unit with alpha 1, and the ray's work (src/render/work_counts.h, PixelWork): by default 1 + the
// steps its marching components took (gRayWork), with which the load balancer shares the measured time of a draw among the bands
// it covered (src/gl/float_target.h); with AURORAWALL_WORK_CLOCK the GPU clock cycles it took; with
// AURORAWALL_WORK_FETCHES 1 + its texture fetches.
void shadePixel(out vec4 radiance, out float work)
{
#ifdef AURORAWALL_WORK_CLOCK
    uvec2 start = clock2x32ARB();
#endif
    work = 1.0;
    radiance = vec4(0.0, 0.0, 0.0, 1.0);
    if (fragmentInImage()) {
        vec3 direction = fragmentRayDirection();
        radiance = vec4(shadeRay(fragmentRayStart(direction), direction), 1.0);
        work = 1.0 + float(gRayWork);
    }
#if defined(AURORAWALL_WORK_CLOCK)
    work = float(clock2x32ARB().x - start.x); // the low word's difference: a ray takes < 2^32 cycles
#elif defined(AURORAWALL_WORK_FETCHES)
    work = 1.0 + float(gWork.w);
#endif
}
