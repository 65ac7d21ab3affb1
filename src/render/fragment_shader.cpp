#include "render/fragment_shader.h"


namespace aurorawall::render {

namespace {

std::vector<std::string> modulesOf(scene::Component c)
{
    switch (c) {
    case scene::Component::Planet: return {"scene/planet.glsl"};
    case scene::Component::PlanetTexture: return {"scene/night_lights.glsl"};
    case scene::Component::Atmosphere:
        return {"atmosphere/airmass_common.glsl", "atmosphere/airmass_chapman.glsl", "scene/atmosphere.glsl"};
    case scene::Component::Aurora:
        return {"aurora/deposition_coords.glsl", "aurora/deposition.glsl", "aurora/footprint_map.glsl",
                "aurora/curtain_profile.glsl", "scene/aurora_curtains.glsl"};
    case scene::Component::Sky: return {"atmosphere/sky.glsl", "scene/sky.glsl"};
    case scene::Component::FluidDetail: return {};
    case scene::Component::Stars: return {"scene/stars.glsl"};
    }
    return {};
}

std::string defineOf(scene::Component c)
{
    std::string name = scene::componentName(c);
    for (char& ch : name)
        ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
    return "HAS_" + name;
}

// Components in dependency order: the planet's uniforms are used by the layers above it.
const scene::Component kOrder[] = {scene::Component::Planet, scene::Component::PlanetTexture,
                                   scene::Component::Atmosphere, scene::Component::Sky, scene::Component::FluidDetail,
                                   scene::Component::Aurora, scene::Component::Stars};

} // namespace

std::vector<std::string> fragmentModuleNames(const scene::Scene& scene)
{
    std::vector<std::string> names = {"render/ray_sphere.glsl", "render/layers.glsl", "render/tile_rays.glsl"};
    for (scene::Component c : kOrder)
        if (scene.has(c))
            for (const std::string& m : modulesOf(c))
                names.push_back(m);
    names.push_back("render/composite.glsl");
    names.push_back("render/main.frag");
    return names;
}

gl::ShaderSource fragmentShaderSource(const scene::Scene& scene, const std::string& shaderDir)
{
    gl::ShaderSource source;
    for (scene::Component c : kOrder)
        if (scene.has(c))
            source.defines.push_back(defineOf(c));
    for (const std::string& name : fragmentModuleNames(scene))
        source.modules.push_back(gl::readShaderModule(shaderDir + "/" + name));
    return source;
}

} // namespace aurorawall::render
