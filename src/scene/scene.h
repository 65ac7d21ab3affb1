#pragma once
// A scene: the components it lists and their parameters, read from a TOML file
// (config/scenes/*.toml; the format is described in docs/scenes.md).
// Units: kilometres, degrees, seconds. Planet frame: centre at the origin, z toward the
// north pole, x toward longitude 180 deg and y toward longitude 90 deg W, the frame of the
// paper's published benchmark camera (../shared/reference.md).
#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace aurorawall::scene {

// What a scene may contain. The renderer compiles shader code and computes tables only for
// the components a scene lists.
enum class Component { Planet, Atmosphere, Aurora, Stars };
const char* componentName(Component c);

struct Planet {
    double radiusKm = 6371.0;
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

// An auroral curtain: its footprint is a curve on the sphere through latitude/longitude points.
struct Curtain {
    std::vector<glm::dvec2> pointsLatLonDeg;
    double energyFluxErgPerCm2S = 1.0; // precipitating electron energy flux at the curtain's centre
    double thicknessKm = 1.0;          // across the curtain
    double energyKeV = 5.0;            // (characteristic) electron energy: sets the curtain's height
    double foldAmplitudeKm = 0.0; // first light: sinusoidal folds along the curtain
    double foldWavelengthKm = 50.0;
    double driftKmPerS = 0.0;     // folds travel along the curtain
};

// Energy spectrum of the precipitating electrons (src/aurora/lazarev.h).
enum class ElectronSpectrum { Monoenergetic, Maxwellian };

struct Aurora {
    ElectronSpectrum spectrum = ElectronSpectrum::Maxwellian;
    double bottomKm = 85.0;
    double topKm = 300.0;
    double stepKm = 2.0; // march step inside curtains
    std::vector<Curtain> curtains;
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
