// The march's work per pixel, counted only when the program is built with AURORAWALL_WORK_STATS
// (accuracy --work-stats; src/render/work_counts.h) or AURORAWALL_WORK_FETCHES (the pixel's work is
// its texture fetches, pixel.glsl), so that counting costs the march nothing otherwise: x the march's steps (footprint map reads), y the curtains evaluated near a step,
// z the sub-steps integrated, w the texture fetches of the march (footprint map, polylines,
// flux tables, emission table).
#if defined(AURORAWALL_WORK_STATS) || defined(AURORAWALL_WORK_FETCHES)
ivec4 gWork = ivec4(0);
#define COUNT_WORK(field, n) (gWork.field += (n))
#else
#define COUNT_WORK(field, n)
#endif

// The ray's work by which the load balancer shares out a draw's measured time (pixel.glsl: 1 + this):
// each component that marches adds its steps.
int gRayWork = 0;
#define COUNT_RAY_WORK(n) (gRayWork += (n))
