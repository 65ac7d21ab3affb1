#include "components/aurora/aurora_tables.h"

#include <chrono>
#include <cstdio>

namespace aurorawall::components::aurora {

physics::DepositionTableSpec emissionTableSpec(const Settings& a)
{
    physics::DepositionTableSpec spec;
    spec.altitudeStepKm = a.tableAltitudeStepKm;
    spec.energyCount = a.tableEnergyCount;
    spec.spectrum = a.spectrum;
    return spec;
}

namespace {

// A layer of nodes × 1 texels per curtain (at least one layer), filtered along the altitude only.
gl::Texture emissionTexture(int nodes, int curtains)
{
    return gl::Texture::create2DArray(nodes, 1, std::max(curtains, 1), gl::TexelFormat::RGBA32F, gl::Filter::Linear,
                                      gl::Wrap::Clamp);
}

} // namespace

AuroraTables::AuroraTables(const Settings& a) : emission_(emissionTexture(1, 1))
{
    const auto start = std::chrono::steady_clock::now();
    tables_ = physics::buildEmissionTables(emissionTableSpec(a));
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    char text[160];
    std::snprintf(text, sizeof text, "aurora deposition table %d x %d (%s), line yields %zu: %.1f ms",
                  tables_.deposition.altitudeCount, tables_.deposition.energyCount,
                  a.spectrum == physics::Spectrum::Maxwellian ? "maxwellian" : "monoenergetic",
                  tables_.lineYields.size(), ms);
    summary_ = text;
}

void AuroraTables::update(const std::vector<float>& energiesKeV)
{
    const size_t nodes = static_cast<size_t>(tables_.nodeCount());
    const bool resized = energiesKeV.size() != energiesKeV_.size() || rows_.empty();
    if (resized) {
        energiesKeV_.assign(energiesKeV.size(), -1.0f); // no energy: every row is built
        rows_.assign(4 * nodes * std::max<size_t>(energiesKeV.size(), 1), 0.0f);
        emission_ = emissionTexture(static_cast<int>(nodes), static_cast<int>(energiesKeV.size()));
    }
    bool changed = resized;
    for (size_t c = 0; c < energiesKeV.size(); ++c) {
        if (energiesKeV[c] == energiesKeV_[c])
            continue;
        physics::emissionRow(tables_, energiesKeV[c], &rows_[4 * nodes * c]);
        energiesKeV_[c] = energiesKeV[c];
        changed = true;
    }
    if (changed)
        emission_.upload(rows_);
}

void AuroraTables::bind(gl::Program& program) const
{
    program.bindTexture("uCurtainEmission", 0, emission_.id());
    program.set("uCurtainEmissionAxes", tables_.axes());
}

} // namespace aurorawall::components::aurora
