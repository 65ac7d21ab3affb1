#include "physics/constants.h"
#include "components/glory/optics/light_source.h"

#include "physics/colour_matching.h"
#include "physics/spectra.h"

#include <cmath>

namespace aurorawall::components::glory::optics {

namespace {
constexpr double kMoonRadiusKm = 1737.4;
constexpr double kMoonDistanceKm = 384400.0;
} // namespace

double LightSource::illuminanceLux() const
{
    if (body == Body::Sun)
        return sunIlluminanceLux;
    const double alpha = moonPhaseAngleDeg * physics::kPi / 180.0;
    const double phase = (std::sin(alpha) + (physics::kPi - alpha) * std::cos(alpha)) / physics::kPi;
    const double size = kMoonRadiusKm / kMoonDistanceKm;
    return sunIlluminanceLux * moonGeometricAlbedo * size * size * phase;
}

LightSpectrum::LightSpectrum(const LightSource& light)
    : illuminanceLux_(light.illuminanceLux()), temperatureK_(light.sunTemperatureK), luminousPerIrradiance_(0.0)
{
    // 683 ∫ B ȳ dλ of the unscaled black body, trapezoid every 1 nm.
    for (double nm = physics::kCieFirstNm; nm <= physics::kCieLastNm; nm += 1.0) {
        const double weight = (nm == physics::kCieFirstNm || nm == physics::kCieLastNm) ? 0.5 : 1.0;
        luminousPerIrradiance_ += weight * physics::planckRadiance(nm, temperatureK_) * physics::colourMatching(nm).y;
    }
    luminousPerIrradiance_ *= physics::kLumensPerWatt;
}

double LightSpectrum::operator()(double wavelengthNm) const
{
    return illuminanceLux_ * physics::planckRadiance(wavelengthNm, temperatureK_) / luminousPerIrradiance_;
}

LightSpectrum LightSource::spectrum() const { return LightSpectrum(*this); }

double LightSource::spectralIrradiance(double wavelengthNm) const { return spectrum()(wavelengthNm); }

double LightSource::discRadiusRad() const { return 0.5 * angularDiameterDeg * physics::kPi / 180.0; }

} // namespace aurorawall::components::glory::optics
