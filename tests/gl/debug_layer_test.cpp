// The GL debug modes (gl/debug_layer.h): each one catches the fault it is for on this context, and
// lets correct code through. Each test installs its modes and restores the environment's after.
#include "gl/context.h"
#include "gl/debug_layer.h"
#include "gl/functions.h"
#include "gl/shader_program.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace aurorawall::gl {
namespace {

// Installs modes for one test on the current context.
class DebugModesScope {
public:
    explicit DebugModesScope(const std::string& modes) { installDebugLayer(parseDebugModes(modes)); }
    ~DebugModesScope() { installDebugLayer(debugModes()); }
};

// out[i] = i + 1 for every invocation, and the workgroup that wrote it.
Program fillProgram()
{
    return Program::compute({{}, {{"fill.comp", R"(
layout(local_size_x = 4) in;
layout(std430, binding = 0) buffer Out { uint values[]; };
layout(std430, binding = 1) buffer Groups { uint groups[]; };
void main()
{
    uint i = DISPATCH_INVOCATION.x;
    values[i] = i + 1u;
    groups[i] = gl_WorkGroupID.x;
})"}}});
}

GLuint storageBuffer(std::size_t words)
{
    GLuint buffer = 0;
    glCreateBuffers(1, &buffer);
    glNamedBufferStorage(buffer, GLsizeiptr(words * sizeof(std::uint32_t)), nullptr, GL_DYNAMIC_STORAGE_BIT);
    return buffer;
}

std::vector<std::uint32_t> readBack(GLuint buffer, std::size_t words)
{
    std::vector<std::uint32_t> values(words);
    glGetNamedBufferSubData(buffer, 0, GLsizeiptr(words * sizeof(std::uint32_t)), values.data());
    return values;
}

TEST(DebugModes, ParseTheListAndRejectUnknownWords)
{
    const DebugModes all = parseDebugModes("nan-fill,reverse-workgroups,hazards");
    EXPECT_TRUE(all.nanFill && all.reverseWorkgroups && all.hazards);
    EXPECT_FALSE(parseDebugModes("").any());
    EXPECT_TRUE(parseDebugModes("hazards").hazards);
    EXPECT_FALSE(parseDebugModes("hazards").nanFill);
    EXPECT_THROW(parseDebugModes("nan-fill,nan"), std::invalid_argument);
}

TEST(DebugModes, NanFillPoisonsBuffersCreatedWithoutData)
{
    const auto context = createContext(Backend::Egl);
    const DebugModesScope modes("nan-fill");
    const GLuint poisoned = storageBuffer(4);
    for (std::uint32_t word : readBack(poisoned, 4))
        EXPECT_EQ(word, 0xFFFFFFFFu); // NaN as float, −1 as int
    const std::vector<float> given = {1.0f, 2.0f};
    GLuint kept = 0;
    glCreateBuffers(1, &kept);
    glNamedBufferStorage(kept, GLsizeiptr(given.size() * sizeof(float)), given.data(), 0);
    std::vector<float> read(2);
    glGetNamedBufferSubData(kept, 0, GLsizeiptr(read.size() * sizeof(float)), read.data());
    EXPECT_EQ(read, given);
    const GLuint buffers[2] = {poisoned, kept};
    glDeleteBuffers(2, buffers);
}

TEST(DebugModes, ReversedWorkgroupsRenumberTheDispatch)
{
    const auto context = createContext(Backend::Egl);
    for (const bool reversed : {false, true}) {
        const DebugModesScope modes(reversed ? "reverse-workgroups" : "");
        Program program = fillProgram();
        const GLuint values = storageBuffer(12), groups = storageBuffer(12);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, values);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, groups);
        program.use();
        glDispatchCompute(3, 1, 1);
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        const std::vector<std::uint32_t> v = readBack(values, 12), g = readBack(groups, 12);
        for (std::uint32_t i = 0; i < 12; ++i) {
            EXPECT_EQ(v[i], i + 1) << i; // the same result in either order
            EXPECT_EQ(g[i], reversed ? 2 - i / 4 : i / 4) << i;
        }
        const GLuint buffers[2] = {values, groups};
        glDeleteBuffers(2, buffers);
    }
}

// The hazard check stops exactly the accesses that lack their barrier.
TEST(DebugModes, HazardsNeedTheirBarriers)
{
    const auto context = createContext(Backend::Egl);
    const DebugModesScope modes("hazards");
    Program program = fillProgram();
    const GLuint values = storageBuffer(4), groups = storageBuffer(4);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, values);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, groups);
    program.use();
    const std::vector<std::uint32_t> zeros(4, 0);

    glDispatchCompute(1, 1, 1);
    EXPECT_THROW(glDispatchCompute(1, 1, 1), std::logic_error); // the second would race the first
    EXPECT_THROW(glNamedBufferSubData(values, 0, 16, zeros.data()), std::logic_error);
    EXPECT_THROW(readBack(values, 4), std::logic_error);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    EXPECT_NO_THROW(glDispatchCompute(1, 1, 1));
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    EXPECT_THROW(glNamedBufferSubData(values, 0, 16, zeros.data()), std::logic_error); // not the update bit
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    EXPECT_NO_THROW(glNamedBufferSubData(values, 0, 16, zeros.data()));
    EXPECT_NO_THROW(readBack(groups, 4));
    const GLuint buffers[2] = {values, groups};
    glDeleteBuffers(2, buffers);
}

} // namespace
} // namespace aurorawall::gl
