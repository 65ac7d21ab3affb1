#pragma once
// The verification cases of `aurorawall plasma verify`: each runs the simulation (or its push) in a
// setting where theory gives the answer, and returns what it measured beside what the theory, or the
// scheme's own exact dispersion, expects. Frequencies and rates are in units of ω_p. Each case sets
// up its electrons and analyses what it measured the same way on either device; the PicDevice only
// advances them (ElectrostaticPic in double on the CPU, GpuPic in float on the GPU).
#include "components/plasma/simulation/electrostatic_pic.h"
#include "components/plasma/simulation/particles.h"
#include "components/plasma/simulation/periodic_grid.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace aurorawall::components::plasma::simulation {

struct VerifyRow {
    std::string parameter;
    double measured = 0.0;
    // Absent for a setting of the run (ω_pΔt, ω_cΔt, Δx/λ_D, particle and cell counts) and for a
    // measurement without a closed form (the heating rate).
    std::optional<double> expected;
    // |measured − expected|/|expected|, or |measured − expected| where expected is 0.
    double relativeError() const;
};

// The samples a case measured, for plotting and refitting: one row per time (in 1/ω_p, or 1/ω_D for
// diocotron), the first column the time; an empty cell (NaN) where a column has no value then. The
// fit's window, its result and the theory's value as named numbers; the fitted and the theory's line
// (where the case has them) evaluated at every row as columns.
struct VerifyHistory {
    std::vector<std::string> columns;
    std::vector<std::vector<double>> rows;
    std::vector<std::pair<std::string, double>> fit;
};

// The history as CSV: a comment line "# name = value" for each fit number, the column names, the rows.
void writeHistoryCsv(std::ostream& out, const VerifyHistory& history);

// A particle-in-cell run of a case: electrons advanced one step at a time in their own field.
class PicRun {
public:
    virtual ~PicRun() = default;
    // Advances from step n to n + 1.
    virtual void step() = 0;
    // The same step, returning the energies at step n as ElectrostaticPic::step does.
    virtual StepEnergies stepWithEnergies() = 0;
    // The field at the nodes (V/m), the positions (m), the velocities (m/s, half a step behind) and
    // the charge density at the nodes (C/m³, Σρ = 0) of the current step.
    virtual const std::vector<glm::dvec3>& nodeField() = 0;
    virtual std::vector<glm::dvec3> positions() = 0;
    virtual std::vector<glm::dvec3> velocities() = 0;
    virtual std::vector<double> chargeDensity() = 0;
};

// Where the cases run.
class PicDevice {
public:
    virtual ~PicDevice() = default;
    // A run from electrons at time 0 on `grid` in a uniform magneticField (T) with step dt (s).
    virtual std::unique_ptr<PicRun> run(const PeriodicGrid& grid, const Particles& electrons,
                                        glm::dvec3 magneticField, double dt) const = 0;
    // The velocities (m/s) v_0 … v_steps of one electron without charge of its own in uniform fields
    // (V/m, T), starting at `start`.
    virtual std::vector<glm::dvec3> testParticleVelocities(glm::dvec3 start, glm::dvec3 electricField,
                                                           glm::dvec3 magneticField, double dt, long steps) const = 0;
    // Rows of the device's own settings for a run of `particles` particles in `dimension` D.
    virtual std::vector<VerifyRow> settings(std::size_t particles, int dimension) const = 0;
};

// ElectrostaticPic and the Boris push in double on the CPU, depositing and gathering with `shape`
// (a run with TSC adds the row particle_shape_nodes_per_axis = 3 to its settings).
const PicDevice& cpuDevice(ParticleShape shape = ParticleShape::CloudInCell);

// The frequency ωΔt of a leapfrog mode from its samples s_n: a sampled cosine obeys
// s_{n+1} + s_{n−1} = 2 cos(ωΔt) s_n exactly, so cos(ωΔt) by least squares over the samples.
double sampledCosineFrequency(const std::vector<double>& s);

// Each case fills `history`, where given, with the samples its measurement used.

// The time steps the cases take (std::domain_error outside): ω_pΔt in [kMinVerifyWpDt, 2), the leapfrog
// being unstable from 2 on and the runs' step counts growing as 1/ω_pΔt (every case at 0.01 takes about
// 10 minutes on a 2-core CPU; at 1e-300 the counts overflowed); ω_cΔt in [kMinVerifyWcDt, kMaxVerifyWcDt],
// where the E×B case's velocity circle is resolved (its centre came out NaN below 1e-150 and at 1e16).
inline constexpr double kMinVerifyWpDt = 0.01;
inline constexpr double kMinVerifyWcDt = 1e-6;
inline constexpr double kMaxVerifyWcDt = 1e6;

// Cold plasma oscillation: frequency against sin(ωΔt/2) = ω_pΔt/2.
std::vector<VerifyRow> verifyLangmuir(double plasmaFrequencyTimesDt, const PicDevice& device = cpuDevice(),
                                      VerifyHistory* history = nullptr);
// The same on a 2D grid, the wave along the diagonal of a square box.
std::vector<VerifyRow> verifyLangmuir2D(double plasmaFrequencyTimesDt, int cellsPerAxis = 256,
                                        const PicDevice& device = cpuDevice(), VerifyHistory* history = nullptr);
// The same on a 3D grid, the wave vector 2π(1, 1, 1)/L along the body diagonal of a cube.
std::vector<VerifyRow> verifyLangmuir3D(double plasmaFrequencyTimesDt, int cellsPerAxis = 32,
                                        const PicDevice& device = cpuDevice(), VerifyHistory* history = nullptr);
// One electron in a uniform B: rotation per step against 2·atan(ω_cΔt/2), and the relative change of
// its speed over the run (expected 0: rounding only).
std::vector<VerifyRow> verifyBoris(double cyclotronFrequencyTimesDt, long steps = 1000,
                                   const PicDevice& device = cpuDevice());
// One electron in crossed uniform E and B: the centre of its velocity circle (the gyrocentre's
// velocity) against E×B/B², in units of |E|/|B|, along E×B and along E.
std::vector<VerifyRow> verifyExB(double cyclotronFrequencyTimesDt, const PicDevice& device = cpuDevice());
// Cold symmetric two-stream at k v₀ = √(3/8) ω_p: the growth rate of the field amplitude.
std::vector<VerifyRow> verifyTwoStream(double plasmaFrequencyTimesDt, const PicDevice& device = cpuDevice(),
                                       VerifyHistory* history = nullptr);
// A thermal plasma (random start, Δx = λ_D) over a long run: the relative drift of the total energy.
// With a history the energies of every step are kept (on the GPU each costs a read-back).
std::vector<VerifyRow> verifyEnergy(double plasmaFrequencyTimesDt, const PicDevice& device = cpuDevice(),
                                    VerifyHistory* history = nullptr);
// The heating case runs to this time (1/ω_p), fitting from 10 /ω_p on.
inline constexpr double kHeatingRunEndWp = 200.0;
// Numerical heating of a thermal plasma (random start, `seed`, particlesPerCell on 64 cells) on a grid
// of spacing dxOverDebyeLength · λ_D: the rate d(kT)/dt/(kT ω_p) of the temperature along x, from a
// least-squares line through kT_x(t). No closed form: the grid's aliasing heats ever faster as Δx/λ_D
// grows past ~1 (Birdsall & Langdon 1991, ch. 12). dxOverDebyeLength in [kMinHeatingDxDebye,
// kMaxHeatingDxDebye]: below, no heating is resolved (already at 0.5 the rate is noise); above, kT_x
// grows a hundredfold within the run, so the line is no rate (at 1e300 the grid's length overflowed).
// particlesPerCell ≥ 1.
std::vector<VerifyRow> verifyHeating(double plasmaFrequencyTimesDt, double dxOverDebyeLength, std::uint64_t seed = 1,
                                     const PicDevice& device = cpuDevice(), int particlesPerCell = 64,
                                     VerifyHistory* history = nullptr);
inline constexpr double kMinHeatingDxDebye = 0.01;
inline constexpr double kMaxHeatingDxDebye = 100.0;
// The kλ_D the landau case measures (see verifyLandau).
inline constexpr double kLandauMinKDebye = 0.35;
inline constexpr double kLandauMaxKDebye = 0.7;
// Landau damping of a Langmuir wave at kDebyeLength = kλ_D (a quiet Maxwellian of `particles`, a
// power of two, on 64 cells, a 1% density wave): frequency and damping rate against the root of the
// kinetic dispersion relation (landauRoot). std::domain_error outside [kLandauMinKDebye,
// kLandauMaxKDebye].
std::vector<VerifyRow> verifyLandau(double plasmaFrequencyTimesDt, double kDebyeLength = 0.5, int particles = 1 << 20,
                                    const PicDevice& device = cpuDevice(), VerifyHistory* history = nullptr);

// The diocotron instability of a cold electron strip (thickness 2a, mode 1 at ka = 0.4) in a strong
// B on a 2D grid: the exponential growth rate of the mode's field energy, halved, against the
// guiding-centre rate diocotronGrowthRate, in units of ω_D = ω_p²/ω_c. ω_p/ω_c in (0, 1).
std::vector<VerifyRow> verifyDiocotron(double cyclotronFrequencyTimesDt, double plasmaOverCyclotronFrequency = 0.1,
                                       const PicDevice& device = cpuDevice(), VerifyHistory* history = nullptr);

} // namespace aurorawall::components::plasma::simulation
