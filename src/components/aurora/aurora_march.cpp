#include "components/aurora/aurora_march.h"

#include "components/aurora/aurora_tables.h"
#include "components/aurora/curtain_build.h"
#include "components/aurora/curtain_field.h"
#include "components/aurora/curtain_model.h"
#include "components/roles/flux_columns.h"
#include "scene/ray_steps.h"

#include <algorithm>

namespace aurorawall::components::aurora::f64 {
using namespace aurorawall::scene::f64; // the ray, its steps and the shared modules' types
namespace {
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#include "render/angle.glsl"
#include "components/aurora/deposition_coords.glsl"
#include "components/aurora/footprint_map.glsl"
#include "components/aurora/gaussian_column.glsl"
#include "components/aurora/flux_column.glsl"
#include "components/aurora/segment_projection.glsl"
#include "components/aurora/curtain_end.glsl"
#pragma GCC diagnostic pop

// The shader's aurora modules as classes: the uniforms and samplers become members (set by the caller),
// the functions member functions that read them; the work counters compile away. One class for the
// smooth profile, one for the curtain detail (the shader's HAS_CURTAIN_DETAIL).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-parameter" // the smooth profile's curtainIntegral ignores some
#define uniform
#define EXACT_SUB_STEPS uAuroraExactSubSteps
#define COUNT_WORK(field, n)
#define COUNT_RAY_WORK(n)
struct SmoothProgram {
    real uPlanetRadiusKm = 0.0;
#include "components/aurora/curtain_emission.glsl"
#include "components/aurora/curtain_profile.glsl"
#include "components/aurora/aurora_curtains.glsl"
};
static_assert(MAX_CURTAINS == kMaxCurtains, "the shader's uniform arrays hold kMaxCurtains curtains");
#undef MAX_CURTAINS
#define HAS_CURTAIN_DETAIL
struct DetailProgram {
    real uPlanetRadiusKm = 0.0;
    bool uAuroraExactSubSteps = false; // the shader's EXACT_SUB_STEPS, per scene (only the detail reads it)
#include "components/aurora/curtain_emission.glsl"
#include "components/aurora/curtain_profile.glsl"
#include "components/aurora/aurora_curtains.glsl"
};
#undef HAS_CURTAIN_DETAIL
#undef MAX_CURTAINS
#undef COUNT_RAY_WORK
#undef COUNT_WORK
#undef EXACT_SUB_STEPS
#undef uniform
#pragma GCC diagnostic pop

} // namespace
} // namespace aurorawall::components::aurora::f64

namespace aurorawall::components::aurora {

namespace {

// A texture's level 0 as uploaded (RGBA32F).
common::GlslSampler<double> sampler(int width, int height, int layers, std::vector<float> texels)
{
    return common::GlslSampler<double>{width, height, layers, std::move(texels)};
}

// What the aurora component's renderer binds (Renderer::setFrame, CurtainField, AuroraTables): the
// settings and the curtains at timeS, with the footprint map built on the CPU.
template <class Program>
void setCurtains(Program& p, const Settings& a, double planetRadiusKm, const CurtainModel& model, double timeS,
                 const EditEmissionRows& editRows)
{
    const std::vector<CurtainState> states = model.statesAt(timeS);
    CurtainBuild build = buildCurtains(model, states, MapBuilder::Cpu);
    p.uPlanetRadiusKm = static_cast<float>(planetRadiusKm);
    p.uAuroraBottomKm = static_cast<float>(a.bottomKm);
    p.uAuroraTopKm = static_cast<float>(a.topKm);
    p.uAuroraStepKm = static_cast<float>(a.stepKm);
    p.uAuroraResolveKm = static_cast<float>(a.resolveKm);
    p.uAuroraResolveCells = static_cast<float>(a.resolveCells);
    p.uSkipEmptySpace = a.skipEmptySpace ? 1 : 0;
    p.uCurtainCount = static_cast<int>(states.size());
    p.uCurtainReachKm = 0.0;
    const physics::EmissionTables tables = physics::buildEmissionTables(emissionTableSpec(a));
    const int nodes = tables.nodeCount();
    std::vector<float> rows(4 * size_t(nodes) * std::max<size_t>(states.size(), 1), 0.0f);
    for (size_t i = 0; i < states.size(); ++i) {
        const glm::vec4 state = curtainStateUniform(model, i, states[i], build.pointCounts[i]);
        p.uCurtainState[i] = state;
        p.uCurtainDetail[i] = curtainDetailUniform(model, i, states[i]);
        p.uCurtainLengthKm[i] = build.lengthsKm[i];
        p.uCurtainCornerSlope[i] = build.cornerSlopes[i];
        if (state.x > 0.0f)
            p.uCurtainReachKm = std::max<double>(p.uCurtainReachKm, state.w);
        physics::emissionRow(tables, state.y, &rows[4 * size_t(nodes) * i]);
    }
    if (editRows)
        editRows(rows, nodes, tables.nodeSpacingKm());
    p.uCurtainEmission = sampler(nodes, 1, static_cast<int>(std::max<size_t>(states.size(), 1)), std::move(rows));
    p.uCurtainEmissionAxes = tables.axes();
    p.uCurtainPolylines = sampler(build.polylineWidth, build.polylineRows, 1, std::move(build.polylineTexels));
    const physics::FootprintMap& map = build.map;
    p.uFootprintCentre = glm::vec3(map.centre);
    p.uFootprintEast = glm::vec3(map.east);
    p.uFootprintAngularRadius = static_cast<float>(map.angularRadius);
    p.uFootprintSize = static_cast<float>(map.spec.size);
    p.uFootprintMarginKm = static_cast<float>(map.marginKm);
    p.uFootprintMap = sampler(map.spec.size, map.spec.size, 1, map.texels);
}

// What roles::FluxColumnTexture binds for these frames.
void setFluxTables(f64::DetailProgram& p, const roles::FluxFrames& frames, const roles::DetailShape& shape,
                   double stripWidthKm)
{
    roles::FluxTables t = roles::packFluxTables(roles::fluxColumns(frames), roles::fluxRows(frames));
    p.uFluxStrip = glm::vec4(shape.stripLengthKm, stripWidthKm, t.frames, shape.peakScale);
    p.uFluxLayout = glm::vec4(t.nx, t.ny, t.columnTiles, t.rowTiles);
    p.uFluxTables = sampler(t.width, t.frames, t.layers, std::move(t.texels));
}

template <class Program>
class AuroraMarch : public scene::ReferenceShader {
public:
    explicit AuroraMarch(std::unique_ptr<Program> program) : program_(std::move(program)) {}
    // shadeAurora of aurora_curtains.glsl.
    scene::f64::Ray shade(scene::f64::Ray ray) const override { return program_->shadeAurora(ray); }

private:
    std::unique_ptr<Program> program_;
};

} // namespace

std::unique_ptr<scene::ReferenceShader> makeAuroraMarch(const Settings& aurora, double planetRadiusKm, double timeS,
                                                        const roles::FluxFrames* frames,
                                                        const std::optional<roles::DetailShape>& shape,
                                                        double stripWidthKm, const EditEmissionRows& editRows)
{
    const CurtainModel model(aurora, planetRadiusKm, shape ? &*shape : nullptr);
    if (!frames) {
        auto program = std::make_unique<f64::SmoothProgram>();
        setCurtains(*program, aurora, planetRadiusKm, model, timeS, editRows);
        return std::make_unique<AuroraMarch<f64::SmoothProgram>>(std::move(program));
    }
    auto program = std::make_unique<f64::DetailProgram>();
    setCurtains(*program, aurora, planetRadiusKm, model, timeS, editRows);
    setFluxTables(*program, *frames, *shape, stripWidthKm);
    program->uAuroraExactSubSteps = aurora.exactSubSteps;
    return std::make_unique<AuroraMarch<f64::DetailProgram>>(std::move(program));
}

} // namespace aurorawall::components::aurora
