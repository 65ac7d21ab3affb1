#include "gl/debug_layer.h"

#include "common/input_error.h"
#include "gl/functions.h"

#include <cstdlib>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace aurorawall::gl {
namespace {

// The driver's functions that the wrappers forward to.
struct Driver {
    PFNGLNAMEDBUFFERSTORAGEPROC namedBufferStorage;
    PFNGLNAMEDBUFFERDATAPROC namedBufferData;
    PFNGLNAMEDBUFFERSUBDATAPROC namedBufferSubData;
    PFNGLGETNAMEDBUFFERSUBDATAPROC getNamedBufferSubData;
    PFNGLCLEARNAMEDBUFFERDATAPROC clearNamedBufferData;
    PFNGLDELETEBUFFERSPROC deleteBuffers;
    PFNGLBINDBUFFERBASEPROC bindBufferBase;
    PFNGLUSEPROGRAMPROC useProgram;
    PFNGLDELETEPROGRAMPROC deleteProgram;
    PFNGLDISPATCHCOMPUTEPROC dispatchCompute;
    PFNGLMEMORYBARRIERPROC memoryBarrier;
    PFNGLTEXTURESTORAGE1DPROC textureStorage1D;
    PFNGLTEXTURESTORAGE2DPROC textureStorage2D;
    PFNGLTEXTURESTORAGE3DPROC textureStorage3D;
    PFNGLTEXIMAGE1DPROC texImage1D;
    PFNGLTEXIMAGE2DPROC texImage2D;
    PFNGLTEXIMAGE3DPROC texImage3D;
};
Driver driver;

// What the hazard check knows: each buffer a dispatch used since the last barrier of each kind.
struct BufferUse {
    bool sinceStorageBarrier = false; // needs GL_SHADER_STORAGE_BARRIER_BIT before the next dispatch
    bool sinceUpdateBarrier = false;  // needs GL_BUFFER_UPDATE_BARRIER_BIT before an update or read-back
};
struct HazardState {
    GLuint program = 0;
    std::map<GLuint, GLuint> storageBindings;           // binding point → buffer
    std::map<GLuint, BufferUse> buffers;
};
HazardState hazards;
DebugModes active;

// The binding points of the shader storage blocks the program uses (the linker drops the others).
// Asked at every dispatch: program names are reused, and each context has its own.
std::vector<GLuint> activeStorageBindings(GLuint program)
{
    GLint blocks = 0;
    glGetProgramInterfaceiv(program, GL_SHADER_STORAGE_BLOCK, GL_ACTIVE_RESOURCES, &blocks);
    std::vector<GLuint> bindings;
    for (GLint b = 0; b < blocks; ++b) {
        const GLenum property = GL_BUFFER_BINDING;
        GLint binding = 0;
        glGetProgramResourceiv(program, GL_SHADER_STORAGE_BLOCK, GLuint(b), 1, &property, 1, nullptr, &binding);
        bindings.push_back(GLuint(binding));
    }
    return bindings;
}

[[noreturn]] void hazard(const std::string& call, GLuint buffer, const char* barrier)
{
    std::ostringstream message;
    message << "GL hazard: " << call << " on buffer " << buffer << " that a compute dispatch used, with no "
            << "glMemoryBarrier(" << barrier << ") between them (AURORAWALL_GL_DEBUG=hazards)";
    throw std::logic_error(message.str());
}

void checkUpdate(const char* call, GLuint buffer)
{
    if (!active.hazards)
        return;
    auto it = hazards.buffers.find(buffer);
    if (it != hazards.buffers.end() && it->second.sinceUpdateBarrier)
        hazard(call, buffer, "GL_BUFFER_UPDATE_BARRIER_BIT");
}

void APIENTRY checkedNamedBufferSubData(GLuint buffer, GLintptr offset, GLsizeiptr size, const void* data)
{
    checkUpdate("glNamedBufferSubData", buffer);
    driver.namedBufferSubData(buffer, offset, size, data);
}

void APIENTRY checkedGetNamedBufferSubData(GLuint buffer, GLintptr offset, GLsizeiptr size, void* data)
{
    checkUpdate("glGetNamedBufferSubData", buffer);
    driver.getNamedBufferSubData(buffer, offset, size, data);
}

void APIENTRY checkedClearNamedBufferData(GLuint buffer, GLenum internalformat, GLenum format, GLenum type,
                                          const void* data)
{
    checkUpdate("glClearNamedBufferData", buffer);
    driver.clearNamedBufferData(buffer, internalformat, format, type, data);
}

void APIENTRY checkedDeleteBuffers(GLsizei n, const GLuint* buffers)
{
    for (GLsizei i = 0; i < n; ++i) {
        hazards.buffers.erase(buffers[i]);
        for (auto& [binding, buffer] : hazards.storageBindings)
            if (buffer == buffers[i])
                buffer = 0;
    }
    driver.deleteBuffers(n, buffers);
}

void APIENTRY checkedBindBufferBase(GLenum target, GLuint index, GLuint buffer)
{
    if (target == GL_SHADER_STORAGE_BUFFER)
        hazards.storageBindings[index] = buffer;
    driver.bindBufferBase(target, index, buffer);
}

void APIENTRY checkedUseProgram(GLuint program)
{
    hazards.program = program;
    driver.useProgram(program);
}

void APIENTRY checkedDeleteProgram(GLuint program)
{
    if (hazards.program == program)
        hazards.program = 0;
    driver.deleteProgram(program);
}

void APIENTRY checkedDispatchCompute(GLuint x, GLuint y, GLuint z)
{
    std::set<GLuint> used;
    for (GLuint binding : activeStorageBindings(hazards.program)) {
        auto it = hazards.storageBindings.find(binding);
        if (it != hazards.storageBindings.end() && it->second != 0)
            used.insert(it->second);
    }
    for (GLuint buffer : used)
        if (hazards.buffers[buffer].sinceStorageBarrier)
            hazard("glDispatchCompute", buffer, "GL_SHADER_STORAGE_BARRIER_BIT");
    driver.dispatchCompute(x, y, z);
    for (GLuint buffer : used)
        hazards.buffers[buffer] = {true, true};
}

void APIENTRY checkedMemoryBarrier(GLbitfield barriers)
{
    for (auto& [buffer, use] : hazards.buffers) {
        if (barriers & GL_SHADER_STORAGE_BARRIER_BIT)
            use.sinceStorageBarrier = false;
        if (barriers & GL_BUFFER_UPDATE_BARRIER_BIT)
            use.sinceUpdateBarrier = false;
    }
    driver.memoryBarrier(barriers);
}

// The data a new buffer store starts with: the caller's, or with nan-fill and none given, all bits
// set (NaN as float, −1 as int), held in `poison`.
const void* initialData(GLsizeiptr size, const void* data, std::vector<unsigned char>& poison)
{
    if (data || !active.nanFill)
        return data;
    poison.assign(std::size_t(size), 0xFF);
    return poison.data();
}

// A new store forgets the old one's uses (buffer names are reused, and each context has its own).
void APIENTRY poisonedNamedBufferStorage(GLuint buffer, GLsizeiptr size, const void* data, GLbitfield flags)
{
    hazards.buffers.erase(buffer);
    std::vector<unsigned char> poison;
    driver.namedBufferStorage(buffer, size, initialData(size, data, poison), flags);
}

void APIENTRY poisonedNamedBufferData(GLuint buffer, GLsizeiptr size, const void* data, GLenum usage)
{
    checkUpdate("glNamedBufferData", buffer);
    hazards.buffers.erase(buffer);
    std::vector<unsigned char> poison;
    driver.namedBufferData(buffer, size, initialData(size, data, poison), usage);
}

bool isFloatFormat(GLenum format)
{
    switch (format) {
    case GL_R16F: case GL_RG16F: case GL_RGB16F: case GL_RGBA16F:
    case GL_R32F: case GL_RG32F: case GL_RGB32F: case GL_RGBA32F: case GL_R11F_G11F_B10F:
        return true;
    default:
        return false;
    }
}

// One level of a float texture set to NaN.
void poisonLevel(GLuint texture, GLint level)
{
    const float nan[4] = {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::quiet_NaN(),
                          std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::quiet_NaN()};
    glClearTexImage(texture, level, GL_RGBA, GL_FLOAT, nan);
}

// Every level of a float texture set to NaN.
void poisonTexture(GLuint texture, GLsizei levels, GLenum internalformat)
{
    if (!isFloatFormat(internalformat))
        return;
    for (GLsizei level = 0; level < levels; ++level)
        poisonLevel(texture, level);
}

void APIENTRY poisonedTextureStorage1D(GLuint texture, GLsizei levels, GLenum format, GLsizei width)
{
    driver.textureStorage1D(texture, levels, format, width);
    poisonTexture(texture, levels, format);
}

void APIENTRY poisonedTextureStorage2D(GLuint texture, GLsizei levels, GLenum format, GLsizei width, GLsizei height)
{
    driver.textureStorage2D(texture, levels, format, width, height);
    poisonTexture(texture, levels, format);
}

void APIENTRY poisonedTextureStorage3D(GLuint texture, GLsizei levels, GLenum format, GLsizei width, GLsizei height,
                                       GLsizei depth)
{
    driver.textureStorage3D(texture, levels, format, width, height, depth);
    poisonTexture(texture, levels, format);
}

// The texture bound to target on the active unit (glTexImage's texture).
GLuint boundTexture(GLenum target)
{
    const GLenum binding = target == GL_TEXTURE_1D   ? GL_TEXTURE_BINDING_1D
                           : target == GL_TEXTURE_3D ? GL_TEXTURE_BINDING_3D
                                                     : GL_TEXTURE_BINDING_2D;
    GLint texture = 0;
    glGetIntegerv(binding, &texture);
    return GLuint(texture);
}

void poisonBoundLevel(GLenum target, GLint level, GLint format, const void* data)
{
    if (data || !isFloatFormat(GLenum(format)) || (target != GL_TEXTURE_1D && target != GL_TEXTURE_2D && target != GL_TEXTURE_3D))
        return;
    poisonLevel(boundTexture(target), level);
}

void APIENTRY poisonedTexImage1D(GLenum target, GLint level, GLint format, GLsizei width, GLint border,
                                 GLenum dataFormat, GLenum type, const void* data)
{
    driver.texImage1D(target, level, format, width, border, dataFormat, type, data);
    poisonBoundLevel(target, level, format, data);
}

void APIENTRY poisonedTexImage2D(GLenum target, GLint level, GLint format, GLsizei width, GLsizei height,
                                 GLint border, GLenum dataFormat, GLenum type, const void* data)
{
    driver.texImage2D(target, level, format, width, height, border, dataFormat, type, data);
    poisonBoundLevel(target, level, format, data);
}

void APIENTRY poisonedTexImage3D(GLenum target, GLint level, GLint format, GLsizei width, GLsizei height,
                                 GLsizei depth, GLint border, GLenum dataFormat, GLenum type, const void* data)
{
    driver.texImage3D(target, level, format, width, height, depth, border, dataFormat, type, data);
    poisonBoundLevel(target, level, format, data);
}

} // namespace

DebugModes parseDebugModes(const std::string& list)
{
    DebugModes modes;
    std::istringstream words(list);
    std::string word;
    while (std::getline(words, word, ',')) {
        if (word == "nan-fill")
            modes.nanFill = true;
        else if (word == "reverse-workgroups")
            modes.reverseWorkgroups = true;
        else if (word == "hazards")
            modes.hazards = true;
        else if (!word.empty())
            throw std::invalid_argument("AURORAWALL_GL_DEBUG: unknown mode '" + common::echoedInput(word) +
                                        "' (allowed: nan-fill, reverse-workgroups, hazards)");
    }
    return modes;
}

const DebugModes& debugModes()
{
    static const DebugModes modes = [] {
        const char* list = std::getenv("AURORAWALL_GL_DEBUG");
        return parseDebugModes(list ? list : "");
    }();
    return modes;
}

namespace {

// Points `function` at `wrapper` when `on`, else at the driver's function, which `original` keeps
// (taken from `function` unless it is the wrapper already: installing twice keeps the driver's).
template <typename Function>
void route(Function& function, Function& original, Function wrapper, bool on)
{
    if (function != wrapper)
        original = function;
    function = on ? wrapper : original;
}

} // namespace

const DebugModes& installedDebugModes() { return active; }

void installDebugLayer(const DebugModes& modes)
{
    hazards = {};
    active = modes;
    const bool buffers = modes.nanFill || modes.hazards;
    route(glNamedBufferStorage, driver.namedBufferStorage, poisonedNamedBufferStorage, buffers);
    route(glNamedBufferData, driver.namedBufferData, poisonedNamedBufferData, buffers);
    route(glTextureStorage1D, driver.textureStorage1D, poisonedTextureStorage1D, modes.nanFill);
    route(glTextureStorage2D, driver.textureStorage2D, poisonedTextureStorage2D, modes.nanFill);
    route(glTextureStorage3D, driver.textureStorage3D, poisonedTextureStorage3D, modes.nanFill);
    route(glTexImage1D, driver.texImage1D, poisonedTexImage1D, modes.nanFill);
    route(glTexImage2D, driver.texImage2D, poisonedTexImage2D, modes.nanFill);
    route(glTexImage3D, driver.texImage3D, poisonedTexImage3D, modes.nanFill);
    route(glNamedBufferSubData, driver.namedBufferSubData, checkedNamedBufferSubData, modes.hazards);
    route(glGetNamedBufferSubData, driver.getNamedBufferSubData, checkedGetNamedBufferSubData, modes.hazards);
    route(glClearNamedBufferData, driver.clearNamedBufferData, checkedClearNamedBufferData, modes.hazards);
    route(glDeleteBuffers, driver.deleteBuffers, checkedDeleteBuffers, modes.hazards);
    route(glBindBufferBase, driver.bindBufferBase, checkedBindBufferBase, modes.hazards);
    route(glUseProgram, driver.useProgram, checkedUseProgram, modes.hazards);
    route(glDeleteProgram, driver.deleteProgram, checkedDeleteProgram, modes.hazards);
    route(glDispatchCompute, driver.dispatchCompute, checkedDispatchCompute, modes.hazards);
    route(glMemoryBarrier, driver.memoryBarrier, checkedMemoryBarrier, modes.hazards);
}

} // namespace aurorawall::gl
