#pragma once
// Spectra of light sources, per wavelength.
namespace aurorawall::physics {

// Planck's law, spectral radiance of a black body in W m⁻² sr⁻¹ m⁻¹ at λ (nm) and temperature T (K).
double planckRadiance(double wavelengthNm, double temperatureK);

} // namespace aurorawall::physics
