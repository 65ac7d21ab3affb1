#pragma once
// Debug modes that make GPU bugs show on any driver, Mesa llvmpipe included, chosen with the
// environment variable AURORAWALL_GL_DEBUG, a comma-separated list of:
//   nan-fill            every buffer and float texture created without data starts as NaN (all bits
//                       set: NaN as float, −1 as int), so a read of memory no pass wrote poisons
//                       the result instead of reading the zeros a fresh allocation often holds;
//   reverse-workgroups  compute shaders number their workgroups from the last (DISPATCH_INVOCATION,
//                       see shader_program.h), so a dispatch whose result depends on the order its
//                       workgroups run in gives another result;
//   hazards             every storage-buffer access is checked against the GL memory model: a
//                       dispatch that uses a buffer an earlier dispatch used needs
//                       glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT) between them, and a buffer
//                       update or read-back (glNamedBufferSubData, glGetNamedBufferSubData, ...) of a
//                       buffer a dispatch used needs GL_BUFFER_UPDATE_BARRIER_BIT before it (OpenGL
//                       4.5 core, §7.12.2). A missing barrier throws std::logic_error naming the
//                       call and the buffer. Drivers that run commands asynchronously (NVIDIA) need
//                       these barriers; llvmpipe runs each command to its end and hides them.
// Unknown words are an error (std::invalid_argument naming the word and the variable).
#include <string>

namespace aurorawall::gl {

struct DebugModes {
    bool nanFill = false;
    bool reverseWorkgroups = false;
    bool hazards = false;
    bool any() const { return nanFill || reverseWorkgroups || hazards; }
};

// The modes of a comma-separated list ("" for none).
DebugModes parseDebugModes(const std::string& list);
// The modes of AURORAWALL_GL_DEBUG, read once.
const DebugModes& debugModes();

// The modes installed last (programs compiled from now on follow reverse-workgroups).
const DebugModes& installedDebugModes();

// Points the function pointers of functions.h that the modes watch at checking wrappers, and those
// the modes leave out back at the driver's (loadFunctions calls it after loading with debugModes();
// a test may call it with other modes on a current context). Forgets what the hazard check knew.
void installDebugLayer(const DebugModes& modes);

} // namespace aurorawall::gl
