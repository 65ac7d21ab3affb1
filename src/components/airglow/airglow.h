#pragma once
// The airglow component: the night sky's own light from thin emitting layers of the upper
// atmosphere (Leinert et al. 1998; Khomich, Semenov & Shefov 2008), each a volume emission with a
// Chapman-like altitude profile (shaders/components/airglow/airglow_layer.glsl) whose zenith column
// brightness, peak height and thickness the scene gives. Seen edge-on from orbit a layer is the thin
// bright line above the limb; from the ground it brightens toward the horizon (van Rhijn).
#include "scene/component.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace aurorawall::components::airglow {

// The emission lines a layer may emit.
enum class Line { Green5577, Sodium5893, Red6300 };

struct Layer {
    Line line = Line::Green5577;
    double zenithRayleigh = 250.0; // column brightness seen at the zenith from below the layer
    double peakKm = 97.0;          // height of the largest volume emission rate
    double fwhmKm = 10.0;          // full width at half maximum of the profile
};

// The profile eps(h) = A (exp(-(h - b)/Hu) - exp(-(h - b)/Hl)) for h >= b, Hl = Hu/2, with the
// layer's peak, FWHM and zenith column: with y = exp(-(h - b)/Hu), eps = A (y - y^2) peaks at y = 1/2
// (h = b + Hu ln 2) and is half its peak at y = (1 +- sqrt(1/2))/2, so FWHM = Hu ln((1 + sqrt(1/2)) /
// (1 - sqrt(1/2))) = 1.7627 Hu; the zenith column A (Hu - Hl) gives A.
struct LayerProfile {
    double baseKm = 0.0;             // b: no emission below
    double upperScaleHeightKm = 0.0; // Hu
    double lowerScaleHeightKm = 0.0; // Hl
    double rayleighPerKm = 0.0;      // A
};
LayerProfile layerProfile(const Layer& layer);
// Volume emission rate at height h (rayleigh per km of path).
double volumeEmission(const LayerProfile& p, double altitudeKm);

// Wavelength (nm) and CIE 1931 2° colour matching values (x̄, ȳ, z̄) of a line.
double wavelengthNm(Line line);
glm::dvec3 cieXyz(Line line);

struct Settings : scene::SettingsOf<Settings> {
    static constexpr const char* kComponent = "airglow";
    static constexpr size_t kMaxLayers = 4; // AIRGLOW_MAX_LAYERS of airglow.glsl
    // Quiet-sky defaults (Leinert et al. 1998, Khomich et al. 2008): green 250 R at 97 km, sodium
    // 80 R at 92 km, red 100 R at 250 km.
    std::vector<Layer> layers = {{Line::Green5577, 250.0, 97.0, 10.0},
                                 {Line::Sodium5893, 80.0, 92.0, 10.0},
                                 {Line::Red6300, 100.0, 250.0, 75.0}};
};

const scene::Component& component();

} // namespace aurorawall::components::airglow
