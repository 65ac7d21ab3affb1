#include "render/reference_ray.h"

#include "scene/compositing_order.h"
#include "scene/ray_steps.h"

#include <utility>

namespace aurorawall::render {

ReferenceModel::ReferenceModel(const scene::Scene& scene, double timeS, scene::RoleData roleData,
                               ReferenceSettings settings)
{
    scene::ReferenceContext context;
    context.timeS = timeS;
    context.stepKm = settings.stepKm;
    context.shaderSteps = settings.shaderSteps;
    context.roleData = std::move(roleData);
    for (const scene::Component* c : scene.components()) {
        std::unique_ptr<scene::ReferenceShader> shader = c->makeReference(scene, context);
        if (shader)
            parts_.push_back({std::move(shader), c});
    }
    for (const scene::Component* c : scene::inCompositingOrder(scene.components()))
        for (const Part& p : parts_)
            if (p.component == c)
                shading_.push_back(p.shader.get());
}

glm::dvec3 ReferenceModel::radiance(glm::dvec3 o, glm::dvec3 direction) const
{
    scene::f64::Ray ray = scene::f64::beginRay(o, glm::normalize(direction), 0.0);
    for (const Part& p : parts_)
        ray = p.shader->bound(ray);
    if (ray.blocked)
        return glm::dvec3(0.0);
    for (const scene::ReferenceShader* s : shading_)
        ray = s->shade(ray);
    return ray.radiance;
}

} // namespace aurorawall::render
