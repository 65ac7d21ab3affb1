#pragma once
// The aurora's part of the CPU reference with the march's own discretization: the shader's text
// (shaders/components/aurora: aurora_curtains.glsl, curtain_profile.glsl, curtain_emission.glsl) compiled
// as C++ in double (common/glsl.h) and given the data the GPU is given: the same polylines, the CPU's
// footprint map, the per-curtain emission rows (AuroraTables), the flux tables of the detail frames
// (roles::FluxColumnTexture) and the uniforms as the GPU receives them, rounded to float. Between the
// GPU's image and this lie only float round-off and the texture unit's filter weights; between this and
// AuroraReference (the fine point-sampled march), only the march's discretization.
#include "components/aurora/aurora.h"
#include "components/roles/curtain_detail.h"
#include "scene/component.h"

#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace aurorawall::components::aurora {

// Changes the emission rows before the march reads them: RGBA, `nodes` per curtain, nodeSpacingKm apart
// (a bound's march of their slopes, tests/render/reference_ray_test.cpp).
using EditEmissionRows = std::function<void(std::vector<float>& rows, int nodes, double nodeSpacingKm)>;

// frames: the curtain detail frames when the scene lists a provider of the role, else null; shape:
// their shape; stripWidthKm: their strip's width (as AuroraReference).
std::unique_ptr<scene::ReferenceShader> makeAuroraMarch(const Settings& aurora, double planetRadiusKm, double timeS,
                                                        const roles::FluxFrames* frames,
                                                        const std::optional<roles::DetailShape>& shape,
                                                        double stripWidthKm, const EditEmissionRows& editRows = {});

} // namespace aurorawall::components::aurora
