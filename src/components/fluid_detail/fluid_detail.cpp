#include "components/fluid_detail/fluid_detail.h"

#include "components/fluid_detail/cached_flux_frames.h"
#include "components/fluid_detail/curtain_detail.h"
#include "components/roles/curtain_detail.h"
#include "io/table_cache.h"
#include "scene/scene.h"

namespace aurorawall::components::fluid_detail {

namespace {

// It provides the curtain detail (roles/curtain_detail.h): the curtains' profile samples these frames
// (under HAS_CURTAIN_DETAIL), and the curtains' reference samples them in double: the component adds
// no shader module and no reference step of its own.
class FluidDetail : public scene::ComponentWithRenderer<Settings, CurtainDetail>, public roles::CurtainDetailProvider {
public:
    std::vector<std::string> needs() const override { return {roles::kCurtains}; }
    std::vector<std::string> provides() const override { return {roles::kCurtainDetail}; }
    // No shading step: the shell of the curtains it gives their detail to.
    scene::Shell shell() const override { return scene::Shell::EmittingStructures; }
    double reachKm(const scene::Scene&) const override { return 0.0; } // detail of the curtains' provider
    void read(const config::TableReader& t, scene::Scene&, scene::ComponentSettings& settings) const override
    {
        auto& f = dynamic_cast<Settings&>(settings);
        f.cellsAlong = t.integer("cells_along", 16, 4096, f.cellsAlong);
        f.cellsAcross = t.integer("cells_across", 4, 4096, f.cellsAcross);
        for (int n : {f.cellsAlong, f.cellsAcross})
            if (n & (n - 1))
                t.fail(n == f.cellsAlong ? "cells_along" : "cells_across", "must be a power of two");
        f.stripLengthKm = t.number("strip_length_km", 1.0, 1e5, f.stripLengthKm);
        f.stripWidthKm = t.number("strip_width_km", 1.0, 1e4, f.stripWidthKm);
        f.frames = t.integer("frames", 2, 256, f.frames);
        f.seed = static_cast<unsigned>(t.integer64("seed", 0, 4294967295LL, f.seed));
        f.pressureSolver = t.choice("pressure_solver", {"fft", "multigrid"},
                                    f.pressureSolver == simulation::PressureSolver::Fft ? 0 : 1) == 0
                               ? simulation::PressureSolver::Fft
                               : simulation::PressureSolver::Multigrid;
    }
    std::vector<std::string> shaderModules() const override { return {}; }
    std::unique_ptr<scene::ReferenceShader> makeReference(const scene::Scene&,
                                                          const scene::ReferenceContext&) const override
    {
        return nullptr;
    }
    std::shared_ptr<const roles::FluxFrames> referenceFrames(const scene::Scene& scene) const override
    {
        return std::make_shared<const roles::FluxFrames>(
            cachedFluxFrames(curtainDetailSpec(scene.settings<Settings>()), io::defaultCacheDirectory()).frames);
    }
    DetailShape referenceShape(const scene::Scene& scene, const roles::FluxFrames& frames) const override
    {
        return detailShape(curtainDetailSpec(scene.settings<Settings>()), frames);
    }
    double stripWidthKm(const scene::Scene& scene) const override
    {
        return curtainDetailSpec(scene.settings<Settings>()).stripWidthKm;
    }
};

} // namespace

const scene::Component& component()
{
    static const FluidDetail instance;
    return instance;
}

} // namespace aurorawall::components::fluid_detail
