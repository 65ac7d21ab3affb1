#include "components/plasma/plasma.h"

#include "common/input_error.h"
#include "components/plasma/plasma_detail.h"
#include "components/plasma/simulation/plasma_parameters.h"
#include "scene/scene.h"

#include <cmath>
#include <cstdio>

namespace aurorawall::components::plasma {

namespace {

std::string number(double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", value);
    return text;
}

// The aurora's curtain profile samples these frames (curtain_profile.glsl under HAS_PLASMA), and the
// aurora's reference samples them in double: the component adds no shader module and no reference
// step of its own.
class Plasma : public scene::ComponentWith<Settings> {
public:
    std::vector<std::string> needs() const override { return {"aurora"}; }
    void read(const config::TableReader& t, scene::Scene& scene, scene::ComponentSettings& settings) const override
    {
        if (scene.has("fluid_detail"))
            throw inputError(t.file(), t.line(),
                             "the scene lists both plasma and fluid_detail: the aurora takes its curtain detail "
                             "from one of them");
        auto& p = dynamic_cast<Settings&>(settings);
        p.cellsAlong = t.integer("cells_along", 16, 4096, p.cellsAlong);
        p.cellsAcross = t.integer("cells_across", 8, 4096, p.cellsAcross);
        p.stripLengthKm = t.number("strip_length_km", 1.0, 1e5, p.stripLengthKm);
        p.stripWidthKm = t.number("strip_width_km", 1.0, 1e4, p.stripWidthKm);
        p.sheetThicknessKm = t.numberAbove("sheet_thickness_km", 0.0, 1e4, p.sheetThicknessKm);
        if (p.sheetThicknessKm >= 0.5 * p.stripWidthKm)
            t.fail("sheet_thickness_km", "must be below half of plasma.strip_width_km");
        if (p.sheetThicknessKm < 2.0 * p.stripWidthKm / p.cellsAcross)
            t.fail("sheet_thickness_km", "must span at least 2 cells across (strip_width_km / cells_across)");
        p.electronDensityM3 = t.numberAbove("electron_density_m3", 0.0, 1e14, p.electronDensityM3);
        p.magneticFieldT = t.numberAbove("magnetic_field_t", 0.0, 1.0, p.magneticFieldT);
        p.timeStepS = t.numberAbove("time_step_s", 0.0, 1.0, p.timeStepS);
        // The leapfrog is unstable from ω_pΔt = 2 on (Birdsall & Langdon 1991, §4-2).
        const double wpDt = aurorawall::plasma::plasmaFrequency(p.electronDensityM3) * p.timeStepS;
        if (!(wpDt < 2.0))
            t.fail("time_step_s", "omega_p dt = " + number(wpDt) +
                                      " must be below 2 (the leapfrog is unstable); omega_p = " +
                                      number(aurorawall::plasma::plasmaFrequency(p.electronDensityM3)) + " rad/s");
        p.particlesPerCellAxis = t.integer("particles_per_cell_axis", 1, 8, p.particlesPerCellAxis);
        p.seedMode = t.integer("seed_mode", 1, p.cellsAlong / 4, p.seedMode);
        p.seedAmplitudeKm = t.number("seed_amplitude_km", 0.0, p.stripWidthKm / 4, p.seedAmplitudeKm);
        p.frames = t.integer("frames", 2, 256, p.frames);
        p.timeBetweenFramesS = t.number("time_between_frames_s", p.timeStepS, 1e3, p.timeBetweenFramesS);
        const double steps = (p.frames - 1) * std::round(p.timeBetweenFramesS / p.timeStepS);
        if (steps > 1e5)
            t.fail("time_between_frames_s", "the frames need " + number(steps) +
                                                " time steps; at most 1e5 (raise time_step_s or lower frames)");
        const double particles = double(p.cellsAlong) * p.particlesPerCellAxis *
                                 std::round(p.sheetThicknessKm * p.cellsAcross / p.stripWidthKm) *
                                 p.particlesPerCellAxis;
        if (particles > 4e6)
            t.fail("particles_per_cell_axis", number(particles) + " electrons; at most 4e6");
    }
    std::vector<std::string> shaderModules() const override { return {}; }
    std::unique_ptr<scene::ComponentRenderer> makeRenderer(const scene::Scene& scene,
                                                           const scene::FindRenderer&) const override
    {
        return std::make_unique<PlasmaDetail>(scene.settings<Settings>());
    }
    std::unique_ptr<scene::ReferenceShader> makeReference(const scene::Scene&,
                                                          const scene::ReferenceContext&) const override
    {
        return nullptr;
    }
};

} // namespace

const scene::Component& component()
{
    static const Plasma instance;
    return instance;
}

SheetFramesSpec sheetFramesSpec(const Settings& p)
{
    SheetFramesSpec s;
    s.sheet.cellsAlong = p.cellsAlong;
    s.sheet.cellsAcross = p.cellsAcross;
    s.sheet.lengthM = p.stripLengthKm * 1e3;
    s.sheet.widthM = p.stripWidthKm * 1e3;
    s.sheet.thicknessM = p.sheetThicknessKm * 1e3;
    s.sheet.electronDensity = p.electronDensityM3;
    s.sheet.magneticFieldT = p.magneticFieldT;
    s.sheet.cyclotronFrequencyTimesDt = aurorawall::plasma::cyclotronFrequency(p.magneticFieldT) * p.timeStepS;
    s.sheet.particlesPerCellPerAxis = p.particlesPerCellAxis;
    s.sheet.mode = p.seedMode;
    s.sheet.seedDisplacementM = p.seedAmplitudeKm * 1e3;
    s.frames = p.frames;
    s.stepsPerFrame = static_cast<int>(std::round(p.timeBetweenFramesS / p.timeStepS));
    return s;
}

} // namespace aurorawall::components::plasma
