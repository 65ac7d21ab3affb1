// Entry point of the march as a compute shader: one invocation = one pixel's ray, in workgroups of
// 8x4 neighbouring pixels (a 32-lane warp's worth), written with imageStore to the float target's
// textures (radiance and work, src/gl/float_target.h; rows bottom-up, as the fragment march's).
// GPUs built for compute (NVIDIA H100, H200) run compute shaders on every multiprocessor and
// fragment shaders on a few.
layout(local_size_x = 8, local_size_y = 4) in;
layout(rgba32f, binding = 0) writeonly uniform image2D uRadianceImage;
layout(r32f, binding = 1) writeonly uniform image2D uWorkImage;
uniform ivec2 uTileSize; // pixels
#ifdef AURORAWALL_WORK_STATS
layout(rgba32f, binding = 2) writeonly uniform image2D uWorkCountsImage; // work_counts.glsl's counts
#endif

void main()
{
    ivec2 pixel = ivec2(DISPATCH_INVOCATION.xy);
    if (pixel.x >= uTileSize.x || pixel.y >= uTileSize.y)
        return;
    gPixelCentre = vec2(pixel) + 0.5;
    vec4 radiance;
    float work;
    shadePixel(radiance, work);
    imageStore(uRadianceImage, pixel, radiance);
    imageStore(uWorkImage, pixel, vec4(work));
#ifdef AURORAWALL_WORK_STATS
    imageStore(uWorkCountsImage, pixel, vec4(gWork));
#endif
}
