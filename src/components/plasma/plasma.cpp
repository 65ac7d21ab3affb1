#include "physics/constants.h"
#include "components/plasma/plasma.h"

#include "components/plasma/box_reference.h"
#include "components/plasma/box_renderer.h"
#include "components/plasma/simulation/plasma_parameters.h"
#include "components/roles/curtain_detail.h"
#include "io/table_cache.h"
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

// The keys of kind = "box" (rejected with kind = "curls", where they would do nothing).
const char* const kBoxKeys[] = {"box_cells", "box_side_km", "box_electron_density_m3", "box_magnetic_field_t",
                                "box_time_step_s", "box_particles_per_cell_axis", "box_seed_mode",
                                "box_seed_amplitude_km", "box_frames", "box_time_between_frames_s",
                                "box_latitude_deg", "box_longitude_deg", "box_altitude_km", "box_play_s",
                                "box_rayleigh_per_km", "box_steps_per_cell"};

void readBox(const config::TableReader& t, Settings& p)
{
    p.boxCells = t.integer("box_cells", 8, 64, p.boxCells);
    if (p.boxCells % 2 != 0)
        t.fail("box_cells", "must be even");
    p.boxSideKm = t.number("box_side_km", 0.1, 100.0, p.boxSideKm);
    p.boxElectronDensityM3 = t.numberAbove("box_electron_density_m3", 0.0, 1e14, p.boxElectronDensityM3);
    p.boxMagneticFieldT = t.numberAbove("box_magnetic_field_t", 0.0, 1.0, p.boxMagneticFieldT);
    p.boxTimeStepS = t.numberAbove("box_time_step_s", 0.0, 1.0, p.boxTimeStepS);
    // The leapfrog is unstable from ω_pΔt = 2 on (Birdsall & Langdon 1991, §4-2).
    const double wpDt = simulation::plasmaFrequency(p.boxElectronDensityM3) * p.boxTimeStepS;
    if (!(wpDt < 2.0))
        t.fail("box_time_step_s", "omega_p dt = " + number(wpDt) + " must be below 2 (the leapfrog is unstable)");
    p.boxParticlesPerCellAxis = t.integer("box_particles_per_cell_axis", 1, 4, p.boxParticlesPerCellAxis);
    const double particles = 2.0 * std::pow(double(p.boxCells) * p.boxParticlesPerCellAxis, 3.0);
    if (particles > 4e6)
        t.fail("box_particles_per_cell_axis", number(particles) + " electrons; at most 4e6");
    p.boxSeedMode = t.integer("box_seed_mode", 1, p.boxCells / 4, p.boxSeedMode);
    // k a < 1: the seed's displacement never reorders the electrons along z.
    p.boxSeedAmplitudeKm =
        t.number("box_seed_amplitude_km", 0.0, 0.99 * p.boxSideKm / (2.0 * physics::kPi * p.boxSeedMode), p.boxSeedAmplitudeKm);
    const double beamSpeed = boxBeamSpeed(boxFramesSpec(p));
    if (beamSpeed > 0.3 * physics::kSpeedOfLight)
        t.fail("box_seed_mode", "the beams' speed " + number(beamSpeed) +
                                    " m/s exceeds 0.3 c, beyond this non-relativistic model (raise box_seed_mode "
                                    "or lower box_side_km)");
    // The explicit push's Courant condition: a beam electron crosses less than one cell a step, or its
    // charge skips cells and the box heats without bound (Birdsall & Langdon 1991, ch. 4).
    const double cellsPerStep = beamSpeed * p.boxTimeStepS / (1e3 * p.boxSideKm / p.boxCells);
    if (!(cellsPerStep < 1.0))
        t.fail("box_time_step_s", "the beams cross " + number(cellsPerStep) +
                                      " cells a step; at most 1 (lower box_time_step_s)");
    p.boxFrames = t.integer("box_frames", 2, 256, p.boxFrames);
    p.boxTimeBetweenFramesS = t.number("box_time_between_frames_s", p.boxTimeStepS, 1e3, p.boxTimeBetweenFramesS);
    const double steps = (p.boxFrames - 1) * std::round(p.boxTimeBetweenFramesS / p.boxTimeStepS);
    if (steps > 1e4)
        t.fail("box_time_between_frames_s",
               "the frames need " + number(steps) +
                   " time steps; at most 1e4 (raise box_time_step_s or lower box_frames)");
    p.boxLatitudeDeg = t.number("box_latitude_deg", -90.0, 90.0, p.boxLatitudeDeg);
    p.boxLongitudeDeg = t.number("box_longitude_deg", -180.0, 360.0, p.boxLongitudeDeg);
    p.boxAltitudeKm = t.number("box_altitude_km", 80.0, 1000.0, p.boxAltitudeKm);
    if (p.boxAltitudeKm - 0.5 * p.boxSideKm < 75.0)
        t.fail("box_altitude_km", "the box's bottom (box_altitude_km - box_side_km / 2) must be above 75 km");
    p.boxPlayS = t.numberAbove("box_play_s", 0.0, 1e6, p.boxPlayS);
    p.boxRayleighPerKm = t.number("box_rayleigh_per_km", 0.0, 1e6, p.boxRayleighPerKm);
    p.boxStepsPerCell = t.integer("box_steps_per_cell", 1, 64, p.boxStepsPerCell);
}

// It provides the curtain detail: the aurora's curtain profile samples the strip's frames
// (curtain_profile.glsl under HAS_CURTAIN_DETAIL), and the aurora's reference samples them in double
// (referenceFrames): the curls add no reference step of their own; the box adds its emission
// (box_reference.h).
class Plasma : public scene::ComponentWith<Settings>, public roles::CurtainDetailProvider {
public:
    std::vector<std::string> needs() const override { return {roles::kCurtains}; }
    std::vector<std::string> provides() const override { return {roles::kCurtainDetail}; }
    void read(const config::TableReader& t, scene::Scene&, scene::ComponentSettings& settings) const override
    {
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
        const double wpDt = simulation::plasmaFrequency(p.electronDensityM3) * p.timeStepS;
        if (!(wpDt < 2.0))
            t.fail("time_step_s", "omega_p dt = " + number(wpDt) +
                                      " must be below 2 (the leapfrog is unstable); omega_p = " +
                                      number(simulation::plasmaFrequency(p.electronDensityM3)) + " rad/s");
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
        // A derived scene keeps its base's device and kind unless it gives them (the words in enum order).
        p.device = static_cast<Settings::Device>(t.choice("device", {"cpu", "gpu"}, static_cast<int>(p.device)));
        p.kind = static_cast<Settings::Kind>(t.choice("kind", {"curls", "box"}, static_cast<int>(p.kind)));
        if (p.kind == Settings::Kind::Box)
            readBox(t, p);
        else
            for (const char* key : kBoxKeys)
                if (t.has(key))
                    t.fail(key, "is a key of kind = \"box\"");
    }
    // The modules take no scene, so every plasma scene has the box's step; with kind = "curls" it
    // marches nothing (uPlasmaBox.y = 0 steps). The box glows inside the aurora's shell: its emission,
    // like the aurora's, is added unabsorbed behind the lower atmosphere, so the order among the two
    // does not change the sum; 41 puts it after the aurora, before the cloud deck and the ground.
    std::vector<std::string> shaderModules() const override
    {
        return {"components/plasma/plasma_box_density.glsl", "components/plasma/plasma_box_march.glsl",
                "components/plasma/plasma_box.glsl"};
    }
    std::string shaderShadeCall() const override { return "shadePlasmaBox(ray)"; }
    // The box's emission: after the curtains in the same shell (it needs the aurora).
    scene::Shell shell() const override { return scene::Shell::EmittingStructures; }
    // The box's highest corner (half a diagonal of the cube above its centre); the curls are the
    // curtains' detail, drawn within the curtains' provider.
    double reachKm(const scene::Scene& scene) const override
    {
        const Settings& p = scene.settings<Settings>();
        return p.kind == Settings::Kind::Box ? p.boxAltitudeKm + 0.5 * std::sqrt(3.0) * p.boxSideKm : 0.0;
    }
    std::unique_ptr<scene::ComponentRenderer> makeRenderer(const scene::Scene& scene,
                                                           const scene::FindRenderer&) const override
    {
        return std::make_unique<BoxRenderer>(scene.settings<Settings>(), scene, scene.planetRadiusKm);
    }
    // The box's emission (box_reference.h); with kind = "curls" nothing of its own.
    std::unique_ptr<scene::ReferenceShader> makeReference(const scene::Scene& scene,
                                                          const scene::ReferenceContext& context) const override
    {
        if (scene.settings<Settings>().kind == Settings::Kind::Box)
            return makeBoxReference(scene.settings<Settings>(), scene.planetRadiusKm, context.timeS);
        return nullptr;
    }
    std::shared_ptr<const roles::FluxFrames> referenceFrames(const scene::Scene& scene) const override
    {
        return std::make_shared<const roles::FluxFrames>(
            cachedSheetFrames(sheetFramesSpec(scene.settings<Settings>()), io::defaultCacheDirectory()).frames);
    }
    roles::DetailShape referenceShape(const scene::Scene& scene, const roles::FluxFrames& frames) const override
    {
        return sheetDetailShape(sheetFramesSpec(scene.settings<Settings>()), frames);
    }
    double stripWidthKm(const scene::Scene& scene) const override
    {
        return sheetFramesSpec(scene.settings<Settings>()).sheet.widthM * 1e-3;
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
    s.sheet.cyclotronFrequencyTimesDt = simulation::cyclotronFrequency(p.magneticFieldT) * p.timeStepS;
    s.sheet.particlesPerCellPerAxis = p.particlesPerCellAxis;
    s.sheet.mode = p.seedMode;
    s.sheet.seedDisplacementM = p.seedAmplitudeKm * 1e3;
    s.frames = p.frames;
    s.stepsPerFrame = static_cast<int>(std::round(p.timeBetweenFramesS / p.timeStepS));
    return s;
}

BoxFramesSpec boxFramesSpec(const Settings& p)
{
    BoxFramesSpec s;
    s.cells = p.boxCells;
    s.sideM = p.boxSideKm * 1e3;
    s.electronDensity = p.boxElectronDensityM3;
    s.magneticFieldT = p.boxMagneticFieldT;
    s.timeStepS = p.boxTimeStepS;
    s.particlesPerCellAxis = p.boxParticlesPerCellAxis;
    s.seedMode = p.boxSeedMode;
    s.seedAmplitudeM = p.boxSeedAmplitudeKm * 1e3;
    s.frames = p.boxFrames;
    s.stepsPerFrame = static_cast<int>(std::round(p.boxTimeBetweenFramesS / p.boxTimeStepS));
    return s;
}

long curlsStep(const SheetFramesSpec& spec, double detailPhase)
{
    return std::lround(detailPhase * (spec.frames - 1) * spec.stepsPerFrame);
}

double boxFramePosition(const Settings& p, double timeS)
{
    const double cycle = timeS / p.boxPlayS;
    return (cycle - std::floor(cycle)) * (p.boxFrames - 1);
}

long boxStep(const Settings& p, double timeS)
{
    return std::lround(boxFramePosition(p, timeS) * boxFramesSpec(p).stepsPerFrame);
}

} // namespace aurorawall::components::plasma
