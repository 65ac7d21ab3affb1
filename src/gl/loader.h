#pragma once
// Fills the pointers of functions.h from a backend's GetProcAddress. Kept apart from functions.h
// so backends that include a system GL header (<GL/osmesa.h> pulls in <GL/gl.h>) can call it.

namespace aurorawall::gl {

using ProcAddressFunction = void* (*)(const char* name);

// Loads every function of AURORAWALL_GL_FUNCTIONS through getProcAddress; a context must be
// current. Does nothing when the pointers already came from this same getProcAddress, so backends
// call it on every makeCurrent, and switching between backends in one process reloads them.
// Throws std::runtime_error naming the functions the context lacks.
void loadFunctions(ProcAddressFunction getProcAddress);

// Clears the pointers; the next loadFunctions loads again. For when the library behind them is
// unloaded (glfwTerminate closes the libGL that GLFW opened).
void forgetFunctions();

} // namespace aurorawall::gl
