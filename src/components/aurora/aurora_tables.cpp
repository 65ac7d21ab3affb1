#include "components/aurora/aurora_tables.h"

#include "components/aurora/physics/colour.h"
#include "components/aurora/physics/deposition_table.h"
#include "components/aurora/physics/emission.h"

#include <chrono>
#include <cstdio>

namespace aurorawall::components::aurora {

namespace {

physics::DepositionTableSpec specFor(const Settings& a)
{
    physics::DepositionTableSpec spec;
    spec.altitudeStepKm = a.tableAltitudeStepKm;
    spec.energyCount = a.tableEnergyCount;
    spec.spectrum = a.spectrum;
    return spec;
}

} // namespace

AuroraTables::AuroraTables(const Settings& a)
    : deposition_(gl::Texture::create2D(1, 1, gl::TexelFormat::R32F, gl::Filter::Linear, gl::Wrap::Clamp)),
      lineYield_(gl::Texture::create2D(1, 1, gl::TexelFormat::RGBA32F, gl::Filter::Linear, gl::Wrap::Clamp))
{
    const auto start = std::chrono::steady_clock::now();
    const physics::DepositionTableSpec spec = specFor(a);
    const physics::DepositionTable table = physics::buildDepositionTable(spec);
    deposition_ = gl::Texture::create2D(table.altitudeCount, table.energyCount, gl::TexelFormat::R32F,
                                        gl::Filter::Linear, gl::Wrap::Clamp);
    deposition_.upload(table.decibels);
    const std::vector<glm::vec4> yields = physics::buildLineYieldTable(spec);
    lineYield_ = gl::Texture::create2D(static_cast<int>(yields.size()), 1, gl::TexelFormat::RGBA32F,
                                       gl::Filter::Linear, gl::Wrap::Clamp);
    lineYield_.upload(std::vector<float>(&yields[0].x, &yields[0].x + 4 * yields.size()));
    axes_ = table.axes();
    size_ = table.size();
    for (int line = 0; line < physics::kLineCount; ++line)
        lineRgb_.emplace_back(physics::lineLinearSrgbPerRayleigh(static_cast<physics::EmissionLine>(line)));
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    char text[160];
    std::snprintf(text, sizeof text, "aurora deposition table %d x %d (%s), line yields %zu: %.1f ms",
                  table.altitudeCount, table.energyCount,
                  a.spectrum == physics::Spectrum::Maxwellian ? "maxwellian" : "monoenergetic", yields.size(),
                  ms);
    summary_ = text;
}

void AuroraTables::bind(gl::Program& program) const
{
    program.bindTexture("uAuroraDeposition", 0, deposition_.id());
    program.bindTexture("uAuroraLineYield", 1, lineYield_.id());
    program.set("uAuroraDepositionAxes", axes_);
    program.set("uAuroraDepositionSize", size_);
    for (size_t line = 0; line < lineRgb_.size(); ++line)
        program.set("uAuroraLineRgb[" + std::to_string(line) + "]", lineRgb_[line]);
}

} // namespace aurorawall::components::aurora
