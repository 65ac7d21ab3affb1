#pragma once
// The current GL context's limits that the plasma's compute passes must fit, checked before any
// buffer is made: each pass is one dispatch along x of work groups of 64 invocations, each array
// one shader storage block.
#include <cstddef>
#include <string>

namespace aurorawall::components::plasma::gpu {

struct GpuLimits {
    long long maxStorageBlockBytes = 0; // GL_MAX_SHADER_STORAGE_BLOCK_SIZE
    long long maxWorkGroupsX = 0;       // GL_MAX_COMPUTE_WORK_GROUP_COUNT along x
};

// The limits of the current context.
GpuLimits currentGpuLimits();

// std::length_error naming the limit and the numbers ("5000000 particles need 78125 work groups of
// 64, more than GL_MAX_COMPUTE_WORK_GROUP_COUNT x = 65535") unless `count` items (`what`: "particles",
// "grid nodes") fit one dispatch of groups of workGroupSize, and bytesPerItem each one storage block.
void requireFitsGpu(const GpuLimits& limits, std::size_t count, const std::string& what, int workGroupSize,
                    std::size_t bytesPerItem);

} // namespace aurorawall::components::plasma::gpu
