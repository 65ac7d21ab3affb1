#pragma once
// The aurora component's emission tables: Lazarev deposition over altitude and electron energy (in decibels)
// and the emission-line yields over altitude, built once per rank at start-up, deterministically
// (src/components/aurora/physics), and from them, each frame, one row per curtain of its electrons' emission
// over altitude, the texture shaders/components/aurora/curtain_emission.glsl reads.
#include "gl/shader_program.h"
#include "gl/texture.h"
#include "components/aurora/aurora.h"
#include "components/aurora/physics/emission_table.h"

#include <string>
#include <vector>

namespace aurorawall::components::aurora {

// The deposition table's resolution and spectrum of these settings.
physics::DepositionTableSpec emissionTableSpec(const Settings& aurora);

class AuroraTables {
public:
    explicit AuroraTables(const Settings& aurora);

    // Rebuilds the rows of the curtains whose energy (keV) differs from the last update's, and uploads.
    void update(const std::vector<float>& energiesKeV);

    // Binds the rows to texture unit 0 and sets their uniforms (per context: texture bindings are not
    // shared between the GLFW windows' contexts).
    void bind(gl::Program& program) const;

    // The rows as uploaded (a layer per curtain) and the tables they are built from.
    const gl::Texture& emission() const { return emission_; }
    const physics::EmissionTables& tables() const { return tables_; }

    // "aurora deposition table 1081 x 128 (maxwellian), line yields 1081: 12.3 ms"
    const std::string& summary() const { return summary_; }

private:
    physics::EmissionTables tables_;
    std::vector<float> energiesKeV_; // of the rows built
    std::vector<float> rows_;        // RGBA, one row of tables_.nodeCount() texels per curtain
    gl::Texture emission_;
    std::string summary_;
};

} // namespace aurorawall::components::aurora
