#pragma once
// The glory component: a cloud deck whose drops scatter the light of the Sun or the Moon back toward
// the viewer in coloured rings around the antisolar point (the viewer's shadow), from exact Mie
// scattering averaged over the drops' sizes and smeared by the light's disc. The deck is an opaque
// layer about the planet (it ends the rays that meet it): seen from above it shows the single-scattered
// light with the glory over a diffuse background, from below its diffuse transmission.
#include "components/glory/optics/glory_table.h"
#include "scene/component.h"

#include <glm/glm.hpp>

#include <string>

namespace aurorawall::components::glory {

// How the glory's colour is found per pixel: from the colour table (every table wavelength integrated
// at start-up; one lookup), or by summing a few wavelengths of the phase table per pixel, spaced
// evenly or drawn in proportion to the light's spectrum times the colour matching functions.
enum class WavelengthSampling { ColourTable, Uniform, Importance };

struct Settings : scene::SettingsOf<Settings> {
    static constexpr const char* kComponent = "glory";
    // The cloud deck.
    double deckTopKm = 2.0;
    double deckThicknessKm = 0.5;
    double opticalThickness = 10.0;
    // Its drops: a gamma distribution by effective radius and variance (variance 0: one size).
    double effectiveRadiusUm = 10.0;
    double effectiveVariance = 0.01;
    // The light: the Sun or the Moon, from this direction (planet frame, toward the light).
    optics::LightSource light;
    glm::dvec3 lightDirection{0.0, 0.0, 1.0};
    bool lightGiven = false; // a scene (or its base) gave [glory.light]
    // The tables and the per-pixel colour.
    optics::GloryTableSpec table;
    WavelengthSampling sampling = WavelengthSampling::ColourTable;
    int wavelengthsPerPixel = 8;

    mie::DropSizeDistribution drops() const;
};

// The deck's smeared phase table for these settings (cached on disk: io/table_cache.h), and how it
// was obtained ("built, cached", "read from cache", ...).
struct GloryTables {
    optics::PhaseTable phase; // smeared by the light's disc
    std::string outcome;
    double seconds = 0.0;
};
GloryTables gloryTables(const Settings& settings);

// The reference's finer table: twice the angles in each segment, every 5 nm from 380 to 780 nm, half the
// size-parameter step.
optics::GloryTableSpec referenceTableSpec(const optics::GloryTableSpec& spec);

// The asymmetry parameter g of the deck's drops: a drop of the effective radius at 550 nm.
double deckAsymmetry(const Settings& settings);

const scene::Component& component();

} // namespace aurorawall::components::glory
