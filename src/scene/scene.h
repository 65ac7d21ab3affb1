#pragma once
// A scene: the components it lists and their parameters, read from a TOML file
// (config/scenes/*.toml; the format is described in docs/scenes.md).
// Units: kilometres, degrees, seconds. Planet frame: centre at the origin, z toward the
// north pole, x toward longitude 180 deg and y toward longitude 90 deg W, the frame of the
// benchmark camera published with the public GLSL version of Lawlor & Genetti's renderer.
#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace aurorawall::scene {

// What a scene may contain. The renderer compiles shader code and computes tables only for
// the components a scene lists.
enum class Component { Planet, PlanetTexture, Atmosphere, Sky, Aurora, FluidDetail, Stars };
const char* componentName(Component c);

struct Planet {
    double radiusKm = 6371.0;
    // City lights of the night side (planet_texture component): an equirectangular image,
    // Debian's xplanet-images by default; if it is not installed the ground stays uniform.
    std::string nightImage = "/usr/share/xplanet/images/night.jpg";
    double nightLightsRadiance = 5.0e-4; // cd/m^2 of a white texel
    // Night ground lit by starlight, airglow and aurora (cd/m^2; snow under a moonless sky is ~1e-5).
    glm::dvec3 surfaceRadiance{2.0e-5, 2.5e-5, 3.5e-5};
};

// The lower atmosphere: exponential density, scatters and absorbs.
struct Atmosphere {
    double topKm = 75.0;
    double scaleHeightKm = 8.0;
    // Rayleigh extinction at sea level per km for the R, G, B primaries (Bruneton & Neyret 2008).
    glm::dvec3 extinctionPerKm{5.8e-3, 13.5e-3, 33.1e-3};
    // Night-sky glow (cd/m^2): airglow and starlight scattered by the air. A path of transmittance
    // T adds skyGlow (1 - T), so an optically thick path near the horizon tends to skyGlow and the
    // zenith sky comes out near 2e-5 cd/m^2 and the horizon near 2e-4 cd/m^2 (a dark natural night
    // sky is about 1e-4 cd/m^2, 22 mag/arcsec^2).
    glm::dvec3 skyGlow{1.5e-4, 2.0e-4, 2.5e-4};
};

// One keyframe of a curtain: its footprint (a spline on the sphere through latitude/longitude
// control points) and its electrons at one moment of the substorm.
struct CurtainKey {
    double timeS = 0.0;
    std::vector<glm::dvec2> pointsLatLonDeg;
    double energyFluxErgPerCm2S = 1.0; // peak precipitating energy flux on the centre line
    double energyKeV = 5.0;            // (characteristic) electron energy: sets the curtain's height
    double detailPhase = 0.0;          // fluid detail: 0 the smooth start ... 1 fully turbulent
};

// A light source of the single-scattering sky: a direction in the planet frame and its
// illuminance above the atmosphere, per linear-sRGB primary (lux).
struct SkyLight {
    glm::dvec3 direction{0.0, 0.0, 1.0};
    glm::dvec3 illuminanceLux{1.28e5};
};

// Single-scattering sky (Rayleigh) lit by up to 8 sources, each source's light-side optical depth
// from the closed-form airmass (after C. Davis, Tectonics.js: several lights for the price of one).
struct Sky {
    double topKm = 100.0; // air above this height is not lit in the model
    int viewSteps = 16;   // march steps along the view ray
    bool nestedMarch = false; // light-side depth by an inner march of lightSteps instead (the reference)
    int lightSteps = 8;
    std::vector<SkyLight> lights;
};

// An auroral curtain, keyframed through the phases of a substorm; between keys everything is
// interpolated smoothly (src/render/curtain_frames.h). Every key has the same number of points.
struct Curtain {
    std::vector<CurtainKey> keys;  // ordered by time
    double thicknessKm = 1.0;      // across the curtain: twice the standard deviation of its flux
    double driftKmPerS = 0.0;      // the detail pattern slides along the curtain
    double pulsationPeriodS = 0.0; // pulsating aurora (recovery): brightness modulated; 0 = steady
    double pulsationDepth = 0.0;   // 0..1: fraction of the brightness that pulsates
};

// Small-scale curtain detail from the Kelvin-Helmholtz fluid simulation (src/fluid).
struct FluidDetail {
    int cellsAlong = 512;
    int cellsAcross = 128;
    double stripLengthKm = 128.0;
    double stripWidthKm = 32.0;
    int frames = 16;
    unsigned seed = 1;
};

// Energy spectrum of the precipitating electrons (src/aurora/lazarev.h).
enum class ElectronSpectrum { Monoenergetic, Maxwellian };

struct Aurora {
    ElectronSpectrum spectrum = ElectronSpectrum::Maxwellian;
    double bottomKm = 85.0;
    double topKm = 300.0;
    double stepKm = 2.0; // march step inside curtains
    double polylineSpacingKm = 2.0; // curtain splines are sampled this finely for the shader
    int footprintMapSize = 512;     // texels per side of the jump-flooded footprint map
    bool skipEmptySpace = true;     // long steps where the footprint map proves no curtain is near
    double tableAltitudeStepKm = 0.5; // deposition table resolution (src/aurora/deposition_table.h)
    int tableEnergyCount = 128;
    std::vector<Curtain> curtains;
    FluidDetail detail;  // used when the scene lists fluid_detail
};

struct Stars {
    double density = 0.004; // stars per direction cell
    double brightness = 0.05;
};

// The camera: position in planet coordinates (km, double) and an orthonormal frame. The field
// of view is not here: the wall's physical screens and eye position set it.
struct Camera {
    glm::dvec3 positionKm{0.0};
    glm::dvec3 forward{0.0, 1.0, 0.0};
    glm::dvec3 up{0.0, 0.0, 1.0};
    double speedKmPerS = 0.0; // flies along `forward` as animation time runs
};

struct Scene {
    std::string sourceFile;
    std::string name;
    std::vector<Component> components;
    Planet planet;
    Atmosphere atmosphere;
    Sky sky;
    Aurora aurora;
    Stars stars;
    Camera camera;
    double startTimeS = 0.0;
    double timeStepS = 1.0 / 30.0;
    double exposure = 1.0;

    bool has(Component c) const;
};

// A point at geographic latitude/longitude (degrees) and distance `radius` from the centre.
glm::dvec3 planetPoint(double latitudeDeg, double longitudeDeg, double radius);

// Reads and validates a scene file. Throws InputError naming file and line.
Scene loadScene(const std::string& path);

} // namespace aurorawall::scene
