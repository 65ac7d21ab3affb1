#include "common/constants.h"
#include "components/glory/optics/light_source.h"

#include "components/glory/optics/colour_matching.h"

#include <cmath>

namespace aurorawall::glory {

namespace {
constexpr double kMoonRadiusKm = 1737.4;
constexpr double kMoonDistanceKm = 384400.0;
} // namespace

double planckRadiance(double wavelengthNm, double temperatureK)
{
    constexpr double h = 6.62607015e-34, c = 2.99792458e8, k = 1.380649e-23; // SI 2019, exact
    const double lambda = wavelengthNm * 1e-9;
    return 2.0 * h * c * c / std::pow(lambda, 5) / std::expm1(h * c / (lambda * k * temperatureK));
}

double LightSource::illuminanceLux() const
{
    if (body == Body::Sun)
        return sunIlluminanceLux;
    const double alpha = moonPhaseAngleDeg * kPi / 180.0;
    const double phase = (std::sin(alpha) + (kPi - alpha) * std::cos(alpha)) / kPi;
    const double size = kMoonRadiusKm / kMoonDistanceKm;
    return sunIlluminanceLux * moonGeometricAlbedo * size * size * phase;
}

LightSpectrum::LightSpectrum(const LightSource& light)
    : illuminanceLux_(light.illuminanceLux()), temperatureK_(light.sunTemperatureK), luminousPerIrradiance_(0.0)
{
    // 683 ∫ B ȳ dλ of the unscaled black body, trapezoid every 1 nm.
    for (double nm = kCieFirstNm; nm <= kCieLastNm; nm += 1.0) {
        const double weight = (nm == kCieFirstNm || nm == kCieLastNm) ? 0.5 : 1.0;
        luminousPerIrradiance_ += weight * planckRadiance(nm, temperatureK_) * colourMatching(nm).y;
    }
    luminousPerIrradiance_ *= kLumensPerWatt;
}

double LightSpectrum::operator()(double wavelengthNm) const
{
    return illuminanceLux_ * planckRadiance(wavelengthNm, temperatureK_) / luminousPerIrradiance_;
}

LightSpectrum LightSource::spectrum() const { return LightSpectrum(*this); }

double LightSource::spectralIrradiance(double wavelengthNm) const { return spectrum()(wavelengthNm); }

double LightSource::discRadiusRad() const { return 0.5 * angularDiameterDeg * kPi / 180.0; }

} // namespace aurorawall::glory
