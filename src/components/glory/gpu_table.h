#pragma once
// The glory's phase table P(γ, λ) (optics/glory_table.h) computed on the GPU in float by the compute
// shader shaders/components/glory/mie_table.comp: the same radius nodes, weights and normalisation as
// phaseTable(), the Mie coefficients and the sums of S11 over the nodes in float (GLSL has double only
// as an extension), water taken as non-absorbing (k = 0) as there. Its error against phaseTable() and
// its cost are in docs/GLORY.md.
#include "components/glory/optics/glory_table.h"

#include <string>

namespace aurorawall::glory {

// Needs a current OpenGL 4.5 context; reads components/glory/mie_table.comp under shaderDir (throws
// InputError naming it if missing). Throws std::runtime_error when one wavelength's Mie coefficients
// (nodes × terms × 16 bytes) exceed GL_MAX_SHADER_STORAGE_BLOCK_SIZE. mieSeries counts the Mie series
// summed, as phaseTable() does; spec.threads is not used.
PhaseTable phaseTableOnGpu(const mie::DropSizeDistribution& drops, const GloryTableSpec& spec,
                           const std::string& shaderDir);

} // namespace aurorawall::glory
