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
    glm::dvec3 surfaceRadiance{0.0004, 0.0005, 0.0007}; // night ground lit by sky and aurora
};

// The lower atmosphere: exponential density, scatters and absorbs.
struct Atmosphere {
    double topKm = 75.0;
    double scaleHeightKm = 8.0;
    // Rayleigh extinction at sea level per km for the R, G, B primaries (Bruneton & Neyret 2008).
    glm::dvec3 extinctionPerKm{5.8e-3, 13.5e-3, 33.1e-3};
    // Night-sky glow added per km of sea-level-equivalent air (airglow seen through the air).
    glm::dvec3 glowPerKm{2.0e-6, 3.0e-6, 4.0e-6};
};

// An auroral curtain: its footprint is a curve on the sphere through latitude/longitude points.
struct Curtain {
    std::vector<glm::dvec2> pointsLatLonDeg;
    double brightness = 1.0;  // relative flux
    double thicknessKm = 1.0; // across the curtain
    double energyKeV = 5.0;   // characteristic electron energy: sets the curtain's height
    double foldAmplitudeKm = 0.0; // first light: sinusoidal folds along the curtain
    double foldWavelengthKm = 50.0;
    double driftKmPerS = 0.0;     // folds travel along the curtain
};

struct Aurora {
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
