#pragma once
// Roles that carry no interface of their own: a component that needs one (Component::needs) needs
// some listed component to provide it (Component::provides), whichever that is. A role's name is
// also the shader define HAS_<ROLE> (spaces as underscores) of a scene that lists its provider.
namespace aurorawall::components::roles {

// The ground: the solid sphere every layer is measured from, whose radius is the scene's
// planetRadiusKm (set by its provider when it reads its table).
inline constexpr const char* kGround = "ground";

} // namespace aurorawall::components::roles
