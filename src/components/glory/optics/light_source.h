#pragma once
// The light of the glory: the Sun, or the Moon lit by it. Its spectrum, its illuminance on a surface
// facing it above the atmosphere, and the angular size of its disc (which smears the glory's rings).
namespace aurorawall::components::glory::optics {

class LightSpectrum;

struct LightSource {
    enum class Body { Sun, Moon };
    Body body = Body::Sun;
    double angularDiameterDeg = 0.53;    // the Sun's mean 0.533°, the Moon's 0.518°
    double sunIlluminanceLux = 1.28e5;   // the Sun's illuminance above the atmosphere (as the sky component's lights)
    double sunTemperatureK = 5778.0;     // the Sun's spectrum: a black body of the Sun's effective temperature
    double moonGeometricAlbedo = 0.12;   // the Moon's geometric albedo (Allen's Astrophysical Quantities)
    double moonPhaseAngleDeg = 0.0;      // Sun–Moon–Earth angle: 0 full, 90 quarter

    // Illuminance above the atmosphere (lux). The Moon as a Lambert sphere of radius R at distance d:
    // E = E_sun p (R/d)² Φ(α), Φ(α) = (sin α + (π − α) cos α)/π (Russell 1916), R = 1737.4 km,
    // d = 384 400 km: 0.31 lux at full moon for E_sun = 1.28e5 lux (measured full moons: 0.1–0.3 lux at
    // the ground). The real Moon is brighter near full (the opposition surge) and darker at quarter.
    double illuminanceLux() const;

    // Spectral irradiance (W m⁻² nm⁻¹), a black body of sunTemperatureK (the Moon's light taken as the
    // Sun's, its slight reddening neglected), scaled so that 683 lm/W ∫ E ȳ dλ over 380–780 nm is
    // illuminanceLux() (the integral by the trapezoid rule every 1 nm over the CIE table).
    double spectralIrradiance(double wavelengthNm) const;
    // The same as a function of wavelength whose normalising integral is computed once, for loops
    // over many wavelengths.
    LightSpectrum spectrum() const;

    double discRadiusRad() const;
};

// LightSource::spectralIrradiance with the luminous integral of the black body computed once.
class LightSpectrum {
public:
    explicit LightSpectrum(const LightSource& light);
    double operator()(double wavelengthNm) const; // W m⁻² nm⁻¹

private:
    double illuminanceLux_;
    double temperatureK_;
    double luminousPerIrradiance_; // 683 lm/W ∫ B ȳ dλ of the unscaled black body
};

} // namespace aurorawall::components::glory::optics
