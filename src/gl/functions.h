#pragma once
// The OpenGL 4.5 core functions aurorawall calls, as pointers loaded at run time.
//
// Naming: each pointer has the GL name (glCreateShader, glDrawArrays, ...) and lives in namespace
// aurorawall::gl, so code in that namespace (or writing gl::glClear) calls it exactly like the C
// function. Only the PFN... types and GL_... constants come from <GL/glcorearb.h>, which declares no
// prototypes unless GL_GLEXT_PROTOTYPES is set; the headless path therefore never links libGL.
// Do not include <GL/gl.h> or <GL/glext.h> in the same source file (glcorearb.h forbids it, and
// unqualified calls would become ambiguous).
//
// A backend loads the pointers when it makes its context current (see loader.h).
#include <GL/glcorearb.h>

// X(PFN type, name) for every function we use; add a line here to use another one.
#define AURORAWALL_GL_FUNCTIONS(X)                                                  \
    /* state, errors, strings */                                                    \
    X(PFNGLGETERRORPROC, glGetError)                                                \
    X(PFNGLGETSTRINGPROC, glGetString)                                              \
    X(PFNGLGETSTRINGIPROC, glGetStringi)                                            \
    X(PFNGLGETINTEGERVPROC, glGetIntegerv)                                          \
    X(PFNGLGETINTEGER64VPROC, glGetInteger64v)                                      \
    X(PFNGLGETINTEGERI_VPROC, glGetIntegeri_v)                                      \
    X(PFNGLENABLEPROC, glEnable)                                                    \
    X(PFNGLDISABLEPROC, glDisable)                                                  \
    X(PFNGLVIEWPORTPROC, glViewport)                                                \
    X(PFNGLSCISSORPROC, glScissor)                                                  \
    X(PFNGLCLEARPROC, glClear)                                                      \
    X(PFNGLCLEARCOLORPROC, glClearColor)                                            \
    X(PFNGLFINISHPROC, glFinish)                                                    \
    X(PFNGLFLUSHPROC, glFlush)                                                      \
    X(PFNGLPIXELSTOREIPROC, glPixelStorei)                                          \
    X(PFNGLREADPIXELSPROC, glReadPixels)                                            \
    X(PFNGLDRAWARRAYSPROC, glDrawArrays)                                            \
    /* shaders and programs */                                                      \
    X(PFNGLCREATESHADERPROC, glCreateShader)                                        \
    X(PFNGLSHADERSOURCEPROC, glShaderSource)                                        \
    X(PFNGLCOMPILESHADERPROC, glCompileShader)                                      \
    X(PFNGLGETSHADERIVPROC, glGetShaderiv)                                          \
    X(PFNGLGETSHADERINFOLOGPROC, glGetShaderInfoLog)                                \
    X(PFNGLDELETESHADERPROC, glDeleteShader)                                        \
    X(PFNGLCREATEPROGRAMPROC, glCreateProgram)                                      \
    X(PFNGLATTACHSHADERPROC, glAttachShader)                                        \
    X(PFNGLDETACHSHADERPROC, glDetachShader)                                        \
    X(PFNGLLINKPROGRAMPROC, glLinkProgram)                                          \
    X(PFNGLGETPROGRAMIVPROC, glGetProgramiv)                                        \
    X(PFNGLGETPROGRAMINFOLOGPROC, glGetProgramInfoLog)                              \
    X(PFNGLUSEPROGRAMPROC, glUseProgram)                                            \
    X(PFNGLDELETEPROGRAMPROC, glDeleteProgram)                                      \
    X(PFNGLGETPROGRAMINTERFACEIVPROC, glGetProgramInterfaceiv)                      \
    X(PFNGLGETPROGRAMRESOURCEIVPROC, glGetProgramResourceiv)                        \
    /* uniforms */                                                                  \
    X(PFNGLGETUNIFORMLOCATIONPROC, glGetUniformLocation)                            \
    X(PFNGLUNIFORM1FPROC, glUniform1f)                                              \
    X(PFNGLUNIFORM1IPROC, glUniform1i)                                              \
    X(PFNGLUNIFORM1FVPROC, glUniform1fv)                                            \
    X(PFNGLUNIFORM2FVPROC, glUniform2fv)                                            \
    X(PFNGLUNIFORM3FVPROC, glUniform3fv)                                            \
    X(PFNGLUNIFORM4FVPROC, glUniform4fv)                                            \
    X(PFNGLUNIFORM1IVPROC, glUniform1iv)                                            \
    X(PFNGLUNIFORMMATRIX3FVPROC, glUniformMatrix3fv)                                \
    X(PFNGLUNIFORMMATRIX4FVPROC, glUniformMatrix4fv)                                \
    X(PFNGLPROGRAMUNIFORM1FPROC, glProgramUniform1f)                                \
    X(PFNGLPROGRAMUNIFORM1IPROC, glProgramUniform1i)                                \
    X(PFNGLPROGRAMUNIFORM1FVPROC, glProgramUniform1fv)                              \
    X(PFNGLPROGRAMUNIFORM2FVPROC, glProgramUniform2fv)                              \
    X(PFNGLPROGRAMUNIFORM3FVPROC, glProgramUniform3fv)                              \
    X(PFNGLPROGRAMUNIFORM4FVPROC, glProgramUniform4fv)                              \
    X(PFNGLPROGRAMUNIFORM1IVPROC, glProgramUniform1iv)                              \
    X(PFNGLPROGRAMUNIFORM2IVPROC, glProgramUniform2iv)                              \
    X(PFNGLPROGRAMUNIFORMMATRIX3FVPROC, glProgramUniformMatrix3fv)                  \
    X(PFNGLPROGRAMUNIFORMMATRIX4FVPROC, glProgramUniformMatrix4fv)                  \
    /* vertex arrays */                                                             \
    X(PFNGLCREATEVERTEXARRAYSPROC, glCreateVertexArrays)                            \
    X(PFNGLBINDVERTEXARRAYPROC, glBindVertexArray)                                  \
    X(PFNGLDELETEVERTEXARRAYSPROC, glDeleteVertexArrays)                            \
    /* framebuffers */                                                              \
    X(PFNGLCREATEFRAMEBUFFERSPROC, glCreateFramebuffers)                            \
    X(PFNGLBINDFRAMEBUFFERPROC, glBindFramebuffer)                                  \
    X(PFNGLNAMEDFRAMEBUFFERTEXTUREPROC, glNamedFramebufferTexture)                  \
    X(PFNGLNAMEDFRAMEBUFFERDRAWBUFFERSPROC, glNamedFramebufferDrawBuffers)          \
    X(PFNGLNAMEDFRAMEBUFFERREADBUFFERPROC, glNamedFramebufferReadBuffer)            \
    X(PFNGLCHECKNAMEDFRAMEBUFFERSTATUSPROC, glCheckNamedFramebufferStatus)          \
    X(PFNGLDELETEFRAMEBUFFERSPROC, glDeleteFramebuffers)                            \
    X(PFNGLBLITFRAMEBUFFERPROC, glBlitFramebuffer)                                  \
    X(PFNGLBLITNAMEDFRAMEBUFFERPROC, glBlitNamedFramebuffer)                        \
    X(PFNGLREADBUFFERPROC, glReadBuffer)                                            \
    X(PFNGLDRAWBUFFERPROC, glDrawBuffer)                                            \
    /* textures */                                                                  \
    X(PFNGLGENTEXTURESPROC, glGenTextures)                                          \
    X(PFNGLCREATETEXTURESPROC, glCreateTextures)                                    \
    X(PFNGLBINDTEXTUREPROC, glBindTexture)                                          \
    X(PFNGLACTIVETEXTUREPROC, glActiveTexture)                                      \
    X(PFNGLBINDTEXTUREUNITPROC, glBindTextureUnit)                                  \
    X(PFNGLDELETETEXTURESPROC, glDeleteTextures)                                    \
    X(PFNGLTEXPARAMETERIPROC, glTexParameteri)                                      \
    X(PFNGLTEXTUREPARAMETERIPROC, glTextureParameteri)                              \
    X(PFNGLTEXIMAGE1DPROC, glTexImage1D)                                            \
    X(PFNGLTEXIMAGE2DPROC, glTexImage2D)                                            \
    X(PFNGLTEXIMAGE3DPROC, glTexImage3D)                                            \
    X(PFNGLTEXSUBIMAGE1DPROC, glTexSubImage1D)                                      \
    X(PFNGLTEXSUBIMAGE2DPROC, glTexSubImage2D)                                      \
    X(PFNGLTEXSUBIMAGE3DPROC, glTexSubImage3D)                                      \
    X(PFNGLTEXTURESTORAGE1DPROC, glTextureStorage1D)                                \
    X(PFNGLTEXTURESTORAGE2DPROC, glTextureStorage2D)                                \
    X(PFNGLTEXTURESTORAGE3DPROC, glTextureStorage3D)                                \
    X(PFNGLTEXTURESUBIMAGE1DPROC, glTextureSubImage1D)                              \
    X(PFNGLTEXTURESUBIMAGE2DPROC, glTextureSubImage2D)                              \
    X(PFNGLTEXTURESUBIMAGE3DPROC, glTextureSubImage3D)                              \
    X(PFNGLGETTEXTUREIMAGEPROC, glGetTextureImage)                                  \
    X(PFNGLCLEARTEXIMAGEPROC, glClearTexImage)                                      \
    /* buffer objects */                                                            \
    X(PFNGLCREATEBUFFERSPROC, glCreateBuffers)                                      \
    X(PFNGLBINDBUFFERPROC, glBindBuffer)                                            \
    X(PFNGLBINDBUFFERBASEPROC, glBindBufferBase)                                    \
    X(PFNGLNAMEDBUFFERDATAPROC, glNamedBufferData)                                  \
    X(PFNGLNAMEDBUFFERSUBDATAPROC, glNamedBufferSubData)                            \
    X(PFNGLNAMEDBUFFERSTORAGEPROC, glNamedBufferStorage)                            \
    X(PFNGLGETNAMEDBUFFERSUBDATAPROC, glGetNamedBufferSubData)                      \
    X(PFNGLCLEARNAMEDBUFFERDATAPROC, glClearNamedBufferData)                        \
    X(PFNGLDELETEBUFFERSPROC, glDeleteBuffers)                                      \
    /* compute */                                                                   \
    X(PFNGLDISPATCHCOMPUTEPROC, glDispatchCompute)                                  \
    X(PFNGLMEMORYBARRIERPROC, glMemoryBarrier)                                      \
    X(PFNGLBINDIMAGETEXTUREPROC, glBindImageTexture)                                \
    /* timer queries */                                                             \
    X(PFNGLGENQUERIESPROC, glGenQueries)                                            \
    X(PFNGLDELETEQUERIESPROC, glDeleteQueries)                                      \
    X(PFNGLQUERYCOUNTERPROC, glQueryCounter)                                        \
    X(PFNGLBEGINQUERYPROC, glBeginQuery)                                            \
    X(PFNGLENDQUERYPROC, glEndQuery)                                                \
    X(PFNGLGETQUERYIVPROC, glGetQueryiv)                                            \
    X(PFNGLGETQUERYOBJECTUI64VPROC, glGetQueryObjectui64v)

namespace aurorawall::gl {

#define AURORAWALL_GL_DECLARE(type, name) extern type name;
AURORAWALL_GL_FUNCTIONS(AURORAWALL_GL_DECLARE)
#undef AURORAWALL_GL_DECLARE

} // namespace aurorawall::gl
