#pragma once
// The emission lines the renderer draws (the aurora's and the airglow's): their wavelengths and CIE
// 1931 2° colour matching values. Their yields are the aurora's (src/components/aurora/physics/
// emission.h). See docs/aurora-physics.md, "Emission".
#include <glm/glm.hpp>

namespace aurorawall::physics {

enum class EmissionLine {
    Blue4278 = 0,        // N2+ first negative (0,1) band, 427.8 nm, prompt
    Green5577 = 1,       // O(1S → 1D), 557.7 nm, τ ≈ 0.75 s
    Red6300 = 2,         // O(1D → 3P), 630.0 nm, τ ≈ 134 s
    N2FirstPositive = 3, // N2 B → A first positive group, visible red bands, prompt (drawn at 670 nm)
};
inline constexpr int kLineCount = 4;

struct LineInfo {
    const char* name;
    double wavelengthNm;
    glm::dvec3 cieXyz; // CIE 1931 2° colour matching functions (x̄, ȳ, z̄) at the wavelength
};
const LineInfo& lineInfo(EmissionLine line);

} // namespace aurorawall::physics
