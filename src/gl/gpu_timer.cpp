#include "gl/gpu_timer.h"

#include "gl/functions.h"

#include <cstring>

namespace aurorawall::gl {

static bool isMesaSoftwareRenderer()
{
    const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    return renderer && (std::strncmp(renderer, "llvmpipe", 8) == 0 || std::strncmp(renderer, "softpipe", 8) == 0);
}

GpuTimer::GpuTimer()
{
    GLint bits = 0;
    glGetQueryiv(GL_TIMESTAMP, GL_QUERY_COUNTER_BITS, &bits);
    if (bits > 0 && !isMesaSoftwareRenderer())
        glGenQueries(2, queries_);
}

GpuTimer::~GpuTimer()
{
    if (usesQueries())
        glDeleteQueries(2, queries_);
}

void GpuTimer::start()
{
    if (usesQueries()) {
        glQueryCounter(queries_[0], GL_TIMESTAMP);
    } else {
        glFinish();
        cpuStart_ = std::chrono::steady_clock::now();
    }
}

void GpuTimer::stop()
{
    if (usesQueries()) {
        glQueryCounter(queries_[1], GL_TIMESTAMP);
    } else {
        glFinish();
        cpuStop_ = std::chrono::steady_clock::now();
    }
}

double GpuTimer::seconds()
{
    if (!usesQueries())
        return std::chrono::duration<double>(cpuStop_ - cpuStart_).count();
    GLuint64 begin = 0, end = 0;
    glGetQueryObjectui64v(queries_[0], GL_QUERY_RESULT, &begin); // GL_QUERY_RESULT waits
    glGetQueryObjectui64v(queries_[1], GL_QUERY_RESULT, &end);
    return end > begin ? double(end - begin) * 1e-9 : 0.0;
}

} // namespace aurorawall::gl
