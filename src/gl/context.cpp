#include "gl/context.h"

#include "gl/backends.h"
#include "gl/functions.h"

#include <algorithm>
#include <stdexcept>

namespace aurorawall::gl {

Context::~Context() = default;

void Context::bindWindowFramebuffer(int)
{
    throw std::logic_error("bindWindowFramebuffer: a headless context has no windows");
}

void Context::swapBuffers(int)
{
    throw std::logic_error("swapBuffers: a headless context has no windows");
}

static std::string glString(GLenum name)
{
    const GLubyte* s = glGetString(name);
    return s ? reinterpret_cast<const char*>(s) : "";
}

std::string Context::rendererName() const { return glString(GL_RENDERER); }

std::string currentRendererName() { return glString(GL_RENDERER); }

bool hasExtension(const std::string& name)
{
    GLint count = 0;
    glGetIntegerv(GL_NUM_EXTENSIONS, &count);
    for (GLint i = 0; i < count; ++i)
        if (name == reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, GLuint(i))))
            return true;
    return false;
}

int largestRenderTargetPx()
{
    GLint texture = 0, renderbuffer = 0, viewport[2] = {0, 0};
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &texture);
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &renderbuffer);
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
    return std::min({texture, renderbuffer, viewport[0], viewport[1]});
}

bool isSoftwareRenderer(const std::string& rendererName)
{
    return rendererName.rfind("llvmpipe", 0) == 0 || rendererName.rfind("softpipe", 0) == 0;
}

std::string Context::glVersion() const { return glString(GL_VERSION); }

std::string Context::vendorName() const { return glString(GL_VENDOR); }

std::unique_ptr<Context> createContext(Backend backend, const std::vector<WindowSpec>& windowsForGlfw, int nodeRank)
{
    switch (backend) {
    case Backend::Egl: return createEglContext(nodeRank);
    case Backend::Osmesa: return createOsmesaContext();
    case Backend::Glfw: return createGlfwContext(windowsForGlfw);
    }
    throw std::logic_error("createContext: unknown backend");
}

} // namespace aurorawall::gl
