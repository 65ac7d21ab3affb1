#include "components/plasma/gpu/gpu_limits.h"

#include "gl/functions.h"

#include <stdexcept>

namespace aurorawall::components::plasma::gpu {

GpuLimits currentGpuLimits()
{
    GpuLimits limits;
    GLint64 blockBytes = 0;
    gl::glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &blockBytes);
    GLint groupsX = 0;
    gl::glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, 0, &groupsX);
    limits.maxStorageBlockBytes = blockBytes;
    limits.maxWorkGroupsX = groupsX;
    return limits;
}

void requireFitsGpu(const GpuLimits& limits, std::size_t count, const std::string& what, int workGroupSize,
                    std::size_t bytesPerItem)
{
    const long long groups = ((long long)count + workGroupSize - 1) / workGroupSize;
    if (groups > limits.maxWorkGroupsX)
        throw std::length_error(std::to_string(count) + " " + what + " need " + std::to_string(groups) +
                                " work groups of " + std::to_string(workGroupSize) +
                                ", more than GL_MAX_COMPUTE_WORK_GROUP_COUNT x = " +
                                std::to_string(limits.maxWorkGroupsX) + " (at most " +
                                std::to_string(limits.maxWorkGroupsX * workGroupSize) + " " + what + ")");
    const long long bytes = (long long)count * (long long)bytesPerItem;
    if (bytes > limits.maxStorageBlockBytes)
        throw std::length_error(std::to_string(count) + " " + what + " need a storage buffer of " +
                                std::to_string(bytes) + " bytes, more than GL_MAX_SHADER_STORAGE_BLOCK_SIZE = " +
                                std::to_string(limits.maxStorageBlockBytes) + " (at most " +
                                std::to_string(limits.maxStorageBlockBytes / (long long)bytesPerItem) + " " + what +
                                ")");
}

} // namespace aurorawall::components::plasma::gpu
