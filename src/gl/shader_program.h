#pragma once
// GLSL programs assembled from named modules, with compile errors mapped back to module files.
//
// A stage's source is a preamble ("#version 450 core", "#define real float" as common/glsl.h
// expects, then the caller's #defines) followed by the modules in order, one source string each.
// Module k (1-based) starts with "#line k*100000+1 k": the line number alone identifies the module,
// because Mesa 22 reports every source string as 0. The assembler maps driver locations
// ("0:100012(3)" Mesa, "1(12)" NVIDIA, "ERROR: 1:12:" others) back to "file:line".
// A compute shader's preamble also defines DISPATCH_INVOCATION, the invocation's index in the
// dispatch (uvec3): compute shaders use it instead of gl_GlobalInvocationID, so that the debug mode
// reverse-workgroups (debug_layer.h) can renumber the workgroups.
#include <glm/glm.hpp>

#include <GL/glcorearb.h>

#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

namespace aurorawall::gl {

struct ShaderModule {
    std::string file; // shown in errors, e.g. "shaders/aurora.glsl"
    std::string text;
};

struct ShaderSource {
    std::vector<std::string> defines; // "NAME" or "NAME VALUE", emitted as #define lines
    std::vector<ShaderModule> modules;
    std::vector<std::string> extensions = {}; // "GL_ARB_shader_clock", emitted as #extension NAME : require
};

// A failed compile or link; what() starts with the stage and the first mapped location,
// e.g. "fragment shader: shaders/aurora.glsl:12(3): error: `foo' undeclared", then the full log.
class ShaderError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The full-screen triangle's vertex shader (see FullScreenTriangle); no attributes.
ShaderSource fullScreenTriangleVertexShader();

// A module read from a file; throws aurorawall::InputError "path: cannot read shader module ...".
ShaderModule readShaderModule(const std::string& path);

// A linked program, owned; belongs to the context group current at creation.
class Program {
public:
    static Program graphics(const ShaderSource& vertex, const ShaderSource& fragment);
    static Program compute(const ShaderSource& source);

    Program(Program&& other) noexcept;
    Program& operator=(Program&& other) noexcept;
    ~Program();

    GLuint id() const { return id_; }
    void use() const;

    // Set a uniform of this program (no need to use() it). A name the linker removed as unused
    // (location -1) is ignored, as GL does, so #define-disabled code needs no special case.
    void set(const std::string& name, float value);
    void set(const std::string& name, int value);
    void set(const std::string& name, const glm::vec2& value);
    void set(const std::string& name, const glm::ivec2& value);
    void set(const std::string& name, const glm::vec3& value);
    void set(const std::string& name, const glm::vec4& value);
    void set(const std::string& name, const glm::mat3& value);
    // Uniform arrays, e.g. `uniform vec4 points[16];` set from element 0 on.
    void set(const std::string& name, const std::vector<float>& values);
    void set(const std::string& name, const std::vector<glm::vec2>& values);
    void set(const std::string& name, const std::vector<glm::vec4>& values);
    // Binds `texture` (a name from glCreateTextures) to `unit` and points sampler `name` at it.
    void bindTexture(const std::string& name, int unit, GLuint texture);

private:
    explicit Program(GLuint id) : id_(id) {}
    GLint location(const std::string& name);

    GLuint id_ = 0;
    std::unordered_map<std::string, GLint> locations_;
};

} // namespace aurorawall::gl
