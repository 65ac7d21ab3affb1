#pragma once
// The glory's tables: the phase function of a cloud's drops over the angle from the antisolar point
// and the wavelength (Mie scattering by water drops, averaged over their sizes), the same smeared by the
// light source's disc, and its colour per angle. The glory is radially symmetric about the antisolar
// point, so one angle describes it.
#include "components/glory/mie/drop_size_distribution.h"
#include "components/glory/optics/light_source.h"

#include <glm/glm.hpp>

#include <vector>

namespace aurorawall::components::glory::optics {

// Angles γ from the antisolar point (γ = π − the scattering angle), in radians, in three even
// segments: gloryCount samples from 0 to glorySpanRad (the rings), middleCount samples above it up to
// π − forwardSpanRad (the cloudbow near 40°, the side scattering), and forwardCount samples over the
// last forwardSpanRad up to π (the forward diffraction peak around the light: about 1° wide for 10 µm
// drops).
struct AngleGrid {
    double glorySpanRad = 0.3490658503988659;   // 20°
    int gloryCount = 401;                        // 0.05° apart
    int middleCount = 150;                       // 1° apart
    double forwardSpanRad = 0.17453292519943295; // 10°
    int forwardCount = 100;                      // 0.1° apart

    int size() const { return gloryCount + middleCount + forwardCount; }
    double angle(int i) const;
    // The continuous sample index of γ (the inverse of angle(), linear between samples), in
    // [0, size() − 1]; the shader's lookup (shaders/components/glory/glory_angle.glsl) is the same map.
    double index(double gammaRad) const;
};

struct GloryTableSpec {
    AngleGrid angles;
    int wavelengthCount = 41;     // evenly from firstNm to lastNm
    double firstNm = 380.0;
    double lastNm = 780.0;
    double sizeParameterStep = 0.1; // the radius quadrature's step in size parameter x = 2πr/λ
    int threads = 0;                // 0: one per hardware thread (the result does not depend on it)
};

// P(γ, λ): the size-averaged phase function at each grid angle and wavelength, normalised so that
// ∫ P dΩ / 4π = 1 at each wavelength.
struct PhaseTable {
    AngleGrid angles;
    std::vector<double> wavelengthsNm;
    std::vector<double> values; // values[w * angles.size() + a]
    long long mieSeries = 0;     // Mie series summed to build it

    double at(int wavelength, int angle) const { return values[size_t(wavelength) * size_t(angles.size()) + size_t(angle)]; }
    // Linear between the grid's angles; γ clamped to [0, π].
    double interpolate(int wavelength, double gammaRad) const;
};

// The table's angles and wavelengths for `spec`, every value 0.
PhaseTable emptyPhaseTable(const GloryTableSpec& spec);

// The phase table of `drops` in water (waterRefractiveIndex at each wavelength):
//   P(θ) = 4π ∫ n(r) S11(θ, r) dr / (k² ∫ n(r) C_sca(r) dr),   S11 = (|S1|² + |S2|²)/2,
// over the radii of DropSizeDistribution::radiusRangeUm by the trapezoid rule on nodes evenly spaced
// in size parameter (step sizeParameterStep; the integrand vanishes smoothly at both ends, so the
// rule's error is that of sampling the Mie ripple, measured in docs/GLORY.md); a single size is one
// Mie series per wavelength. S1, S2 from the Mie coefficients with the angular functions πₙ, τₙ of
// every grid angle computed once (Bohren & Huffman 1983, eq. 4.47).
PhaseTable phaseTable(const mie::DropSizeDistribution& drops, const GloryTableSpec& spec);

// phaseTable's work: the Mie series' terms summed (each radius node's, about x + 4x^(1/3) of them)
// times the angles each term reaches, over every wavelength; its time is proportional to it.
double phaseTableWork(const mie::DropSizeDistribution& drops, const GloryTableSpec& spec);

// The table seen by the light of a uniform disc of angular radius ρ: at each angle the average of P
// over the disc, P̄(γ) = (1/πρ²) ∫∫ P(γ') s ds dφ with cos γ' = cos γ cos s + sin γ sin s cos φ (the
// spherical law of cosines: exact at every γ), by 8-point Gauss–Legendre in s and 24 midpoints in φ
// over [0, π] (P̄ is symmetric in φ), P linear between the grid's angles. ρ = 0: the table itself.
PhaseTable smearedByDisc(const PhaseTable& table, double discRadiusRad);

// CIE XYZ per grid angle of the light single-scattered toward the viewer per unit of the deck's
// geometric factor (cloud_deck.glsl): 683 lm/W ∫ E(λ) P(γ, λ)/(4π) (x̄, ȳ, z̄)(λ) dλ over the table's
// wavelengths by the trapezoid rule, E the light's spectral irradiance. Y in cd/m².
std::vector<glm::dvec3> gloryXyz(const PhaseTable& table, const LightSource& light);

// Linear sRGB of the XYZ table, gamut mapped as the aurora's colours (src/physics/colour.h).
std::vector<glm::dvec3> gloryLinearSrgb(const std::vector<glm::dvec3>& xyz);

// A colour table of `grid` (one colour per angle) linear between the grid's angles at γ (clamped
// to [0, π]).
glm::dvec3 colourAtAngle(const AngleGrid& grid, const std::vector<glm::dvec3>& colours, double gammaRad);

} // namespace aurorawall::components::glory::optics
