#pragma once
// Elapsed GPU time of the commands submitted between start() and stop().
//
// On a GPU with timestamp queries (GL_QUERY_COUNTER_BITS of GL_TIMESTAMP > 0, e.g. NVIDIA) it
// records GL_TIMESTAMP with glQueryCounter around the block, so nothing is flushed early.
// On Mesa's software renderers (llvmpipe, softpipe), or without timestamp queries, it calls glFinish
// at both ends and measures CPU wall time: llvmpipe (Mesa 22.3) answers GL_TIMESTAMP and
// GL_TIME_ELAPSED queries but they cover only part of a draw (12 ms of a 90 ms draw), and the first
// GL_TIME_ELAPSED result is garbage.
// Timer queries are not shared between contexts: create it with the context it measures.
#include <GL/glcorearb.h>

#include <chrono>

namespace aurorawall::gl {

class GpuTimer {
public:
    GpuTimer();
    GpuTimer(const GpuTimer&) = delete;
    GpuTimer& operator=(const GpuTimer&) = delete;
    ~GpuTimer();

    bool usesQueries() const { return queries_[0] != 0; }

    void start();
    // Marks the block's end. With queries the GPU writes the time once it has done the block, and
    // nothing waits: CPU work after stop() is not counted. Without, it waits (glFinish).
    void stop();
    // Seconds from start() to stop(); with queries, waits until the GPU has reached stop().
    double seconds();
    double stopSeconds()
    {
        stop();
        return seconds();
    }

private:
    GLuint queries_[2] = {0, 0};
    std::chrono::steady_clock::time_point cpuStart_;
    std::chrono::steady_clock::time_point cpuStop_;
};

} // namespace aurorawall::gl
