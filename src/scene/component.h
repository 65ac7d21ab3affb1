#pragma once
// The one interface a scene component implements (a planet, its atmosphere, an emitting layer, ...).
// A component owns, in its own folder (src/components/NAME, shaders/components/NAME):
//   - its settings, read from its table of the scene file ([NAME]) with units and bounds;
//   - its GLSL modules and the shell its shading step belongs to along a ray (scene/shell.h);
//   - its GPU part: precomputed tables, per-frame data, uniforms and textures (ComponentRenderer);
//   - its part of the double-precision CPU reference of a ray (ReferenceShader), or a refusal.
// The registry (src/components/registry.h) lists every component; the scene loader, the shader
// assembly, the renderer and the reference all iterate over the components a scene lists, so a
// scene that does not list a component compiles and precomputes none of it.
// Components find each other by role, never by name: a component names the roles it provides
// (e.g. "curtain detail"); one that uses a role asks the scene or FindRenderer for its provider and
// talks to it through the role's interface (src/components/roles), which the core does not know.
#include "cluster/frame_state.h"
#include "common/glsl.h"
#include "config/toml_reader.h"
#include "gl/shader_program.h"
#include "scene/shell.h"

#include <any>
#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace aurorawall::scene::f64 {
AURORAWALL_GLSL_PRECISION(double)
#include "render/ray.glsl"
} // namespace aurorawall::scene::f64

namespace aurorawall::scene {

struct Scene;

// A component's parameters. Each component derives its own struct from SettingsOf<itself>.
struct ComponentSettings {
    virtual ~ComponentSettings() = default;
    virtual std::unique_ptr<ComponentSettings> clone() const = 0;
};

template <class Derived>
struct SettingsOf : ComponentSettings {
    std::unique_ptr<ComponentSettings> clone() const override
    {
        return std::make_unique<Derived>(static_cast<const Derived&>(*this));
    }
};

// The GPU part of a component for one rank, made once the GL context is current.
class ComponentRenderer {
public:
    virtual ~ComponentRenderer() = default;
    // What was precomputed at start-up and what it cost ("deposition table 1081x128: 35 ms"); empty: nothing.
    virtual std::string precomputationLog() const { return {}; }
    // Once per frame, before its tiles: per-frame data and the uniforms of this component.
    virtual void setFrame(gl::Program& program, const cluster::FrameState& frame) = 0;
    // Before each tile: texture bindings (they belong to the current context).
    virtual void bind(gl::Program&) const {}
    // Once a frame, after its first draw is submitted and before the CPU waits for it: work for the
    // next frame that the draw hides (e.g. an upload into textures this frame's draw does not read).
    virtual void whileDrawing() {}
    // What the last setFrame computed (e.g. a footprint map); empty: nothing.
    virtual std::string frameLog() const { return {}; }
};

// Finds the renderer of the listed component that provides a role (null when none does).
using FindRenderer = std::function<ComponentRenderer*(const std::string& role)>;

// Data the caller of the CPU reference gives for a role, by role (e.g. the curtain detail's frames);
// the role's header says what its entry holds.
using RoleData = std::map<std::string, std::any>;

// What a component's part of the CPU reference may use besides the scene.
struct ReferenceContext {
    double timeS = 0.0;   // animation time
    double stepKm = 0.05; // fine fixed step for emission integrals
    // Each component that can evaluates as its shader does, in double (the shader's steps, tables and
    // closed forms: the aurora's march, the atmosphere's airmass) instead of finely or exactly.
    bool shaderSteps = false;
    RoleData roleData;
};

// A component's part of shadeRay in double precision: the same model as its shader, evaluated
// without the shader's approximations (exact integrals, no lookup tables).
class ReferenceShader {
public:
    virtual ~ReferenceShader() = default;
    // The geometry step (see Component::shaderGeometryCall); most components have none.
    virtual f64::Ray bound(f64::Ray ray) const { return ray; }
    virtual f64::Ray shade(f64::Ray ray) const = 0;
};

// Thrown by Component::makeReference for a component the reference does not model.
class NotInReference : public std::invalid_argument {
public:
    using std::invalid_argument::invalid_argument;
};

class Component {
public:
    virtual ~Component() = default;

    // The name in a scene's component list, its table name and its shader define HAS_<NAME>.
    virtual std::string name() const = 0;
    // What must be listed with this one: components by name, or roles that a listed component
    // provides (how a component needs another without naming it).
    virtual std::vector<std::string> needs() const { return {}; }
    // The roles it provides to other components; a scene lists at most one provider of a role.
    virtual std::vector<std::string> provides() const { return {}; }

    virtual std::unique_ptr<ComponentSettings> defaultSettings() const = 0;
    // Reads the component's table into `settings` (which holds the defaults, or a base scene's
    // values); `scene` holds the settings of the components read before this one (registry order),
    // and the planet sets the scene's radius here. Errors name file, line and key (TableReader::fail).
    virtual void read(const config::TableReader& table, Scene& scene, ComponentSettings& settings) const = 0;

    // Shader modules (paths under shaders/), in order; shared helpers first.
    virtual std::vector<std::string> shaderModules() const = 0;
    // Preprocessor symbols its modules test, from its settings in `scene`: a quality knob that changes
    // the shader's code rather than a uniform's value, so a march without it does not carry that code.
    virtual std::vector<std::string> shaderDefines(const Scene&) const { return {}; }
    // GLSL expressions of type Ray applied to `ray` in shadeRay: the geometry step (before any
    // shading: what ends or blocks the ray) and the shading step. Empty: none.
    virtual std::string shaderGeometryCall() const { return {}; }
    virtual std::string shaderShadeCall() const { return {}; }
    // The shell its shading step belongs to (scene/shell.h). The steps run shell by shell, front
    // to back; within a shell, a component's step after those of the components it needs, else in
    // registry order (scene/compositing_order.h). Every component declares one, also one without
    // a shading step of its own (the shell of what it gives its detail to).
    virtual Shell shell() const = 0;
    // How high above the ground (km) it draws anything at a finite distance, from its settings in
    // `scene`; 0 for what draws nothing of its own, lies on the ground or at infinity (the stars).
    // Rays from a far camera start just beyond the highest of these (cluster::rayStart).
    virtual double reachKm(const Scene&) const = 0;

    // The GPU part (needs a current GL context): precomputes its tables.
    virtual std::unique_ptr<ComponentRenderer> makeRenderer(const Scene& scene, const FindRenderer& find) const = 0;
    // Why the CPU reference does not model it (an image lookup, a hash of directions, a model with a
    // reference of its own); empty when it does (most do). withoutUnmodelled (scene/scene.h) leaves
    // one it does not model out of the scenes that the reference and the accuracy sweeps render.
    virtual std::string notInReferenceBecause() const { return {}; }
    bool inReference() const { return notInReferenceBecause().empty(); }
    // Its part of the CPU reference; null when it adds nothing by itself (e.g. data another
    // component uses). One the reference does not model keeps this default, which throws
    // NotInReference with the reason above.
    virtual std::unique_ptr<ReferenceShader> makeReference(const Scene&, const ReferenceContext&) const
    {
        throw NotInReference(notInReferenceBecause());
    }
};

// A component whose settings are S (S::kComponent is its name): the name and the defaults.
template <class S>
class ComponentWith : public Component {
public:
    std::string name() const override { return S::kComponent; }
    std::unique_ptr<ComponentSettings> defaultSettings() const override { return std::make_unique<S>(); }
};

using Registry = std::vector<const Component*>;

} // namespace aurorawall::scene
