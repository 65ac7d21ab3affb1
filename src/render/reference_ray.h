#pragma once
// A double-precision CPU reference of the renderer's model for single rays: the radiance the
// generated shadeRay (render/march_shader.h) computes, without the shader's approximations.
// Each listed component contributes its own part (scene::Component::makeReference): the same
// geometry steps (the shared modules render/ray_sphere.glsl and layers.glsl compiled in double),
// then the shading steps in the same compositing order, each evaluated exactly (exact airmass,
// fine integration of emission, no lookup tables). Components the reference cannot model refuse
// (scene::NotInReference), and the scene must not list them.
#include "scene/scene.h"

#include <glm/glm.hpp>

#include <memory>
#include <vector>

namespace aurorawall::render {

struct ReferenceSettings {
    double stepKm = 0.05; // fine fixed step for emission integrals
    bool shaderSteps = false; // scene::ReferenceContext::shaderSteps
};

class ReferenceModel {
public:
    // The scene at animation time timeS. roleData: what the caller gives the roles' parts of the
    // reference (ReferenceContext::roleData; e.g. the curtain detail's frames, which the scene's
    // provider of the role gives: src/components/roles). Throws scene::NotInReference (a
    // std::invalid_argument) naming a listed component the reference does not model, and
    // std::invalid_argument for a role's provider without its data.
    ReferenceModel(const scene::Scene& scene, double timeS, scene::RoleData roleData, ReferenceSettings settings = {});

    // Radiance (linear sRGB, cd/m^2) arriving at `originKm` (planet frame) from direction `direction`
    // (any length), i.e. shadeRay(o, d).
    glm::dvec3 radiance(glm::dvec3 originKm, glm::dvec3 direction) const;

private:
    struct Part {
        std::unique_ptr<scene::ReferenceShader> shader;
        const scene::Component* component = nullptr;
    };
    std::vector<Part> parts_; // registry order (geometry steps)
    std::vector<const scene::ReferenceShader*> shading_; // compositing order (scene/compositing_order.h)
};

} // namespace aurorawall::render
