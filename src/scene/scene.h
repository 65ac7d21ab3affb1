#pragma once
// A scene: the components it lists and their settings, the camera and the clock, read from a
// TOML file (config/scenes/*.toml; the format is described in docs/scenes.md).
// Units: kilometres, degrees, seconds, cd/m^2. Planet frame: centre at the origin, z toward the
// north pole, x toward longitude 180 deg and y toward longitude 90 deg W (the frame of the
// paper's published benchmark camera).
#include "scene/camera_path.h"
#include "scene/component.h"

#include <glm/glm.hpp>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace aurorawall::scene {

// The camera: position in planet coordinates (km, double) and an orthonormal frame. The field
// of view is not here: the wall's physical screens and eye position set it (a keyed path may zoom it).
struct Camera {
    glm::dvec3 positionKm{0.0};
    glm::dvec3 forward{0.0, 1.0, 0.0};
    glm::dvec3 up{0.0, 0.0, 1.0};
    double speedKmPerS = 0.0; // flies along `forward` as animation time runs
    // A keyed flight ([[camera.key]]); when given it sets the camera at every animation time and the
    // pose above is its first key's.
    CameraPath path;
};

struct Scene {
    std::string sourceFile;
    // The base scenes it derives from ([scene] base), nearest first.
    std::vector<std::string> baseFiles;
    std::string name;
    // Radius of the planet every layer is measured from (the planet component's radius_km).
    double planetRadiusKm = 6371.0;
    Camera camera;
    double startTimeS = 0.0;
    double timeStepS = 1.0 / 30.0;
    double exposure = 1.0;

    Scene() = default;
    Scene(const Scene& other);
    Scene& operator=(const Scene& other);
    Scene(Scene&&) = default;
    Scene& operator=(Scene&&) = default;

    // The listed components, in registry order (the order their settings are read, their shader
    // modules assembled and their GPU parts made).
    const std::vector<const Component*>& components() const { return components_; }
    bool has(const std::string& componentName) const;
    // The listed component that provides `role` (Component::provides), null when none does.
    const Component* provider(const std::string& role) const;
    // The radius about the planet's centre within which the listed components draw everything at a
    // finite distance (km): the planet's radius plus the highest Component::reachKm.
    double reachRadiusKm() const;

    // Lists `c` with its default settings (scene files do this; tests may too, in registry order).
    void add(const Component& c);
    // Unlists a component and drops its settings (no effect if it is not listed).
    void remove(const std::string& componentName);

    // The settings of a listed component; S names it in S::kComponent.
    template <class S>
    const S& settings() const { return dynamic_cast<const S&>(*settings_.at(S::kComponent)); }
    template <class S>
    S& settings() { return dynamic_cast<S&>(*settings_.at(S::kComponent)); }

private:
    friend class SceneLoader;
    std::vector<const Component*> components_;
    std::map<std::string, std::unique_ptr<ComponentSettings>> settings_;
};

// A component with settings S whose GPU part R is made from its settings alone (most are).
template <class S, class R>
class ComponentWithRenderer : public ComponentWith<S> {
public:
    std::unique_ptr<ComponentRenderer> makeRenderer(const Scene& scene, const FindRenderer&) const override
    {
        return std::make_unique<R>(scene.settings<S>());
    }
};

// A point at geographic latitude/longitude (degrees) and distance `radius` from the centre.
glm::dvec3 planetPoint(double latitudeDeg, double longitudeDeg, double radius);

// The altitude (km) of `positionKm` above the sphere of radius `radiusKm`: |position| − R. A point placed
// on the sphere (planetPoint at radius R) comes back within a few ulps of R of it, on either side
// (1e-12 km below R at half of all latitudes); within 8 ulps of R it is on the sphere, altitude 0, so
// that a camera on the ground is not taken to be under it.
double altitudeKm(glm::dvec3 positionKm, double radiusKm);

// The local horizon frame at a site: up (the zenith), north and east, all unit vectors.
struct LocalFrame {
    glm::dvec3 up, north, east;
};
LocalFrame localFrame(double latitudeDeg, double longitudeDeg);

// The unit direction (planet frame) toward something seen from a site at an elevation above its
// horizon and an azimuth clockwise from north (degrees): where a light appears from the site.
glm::dvec3 directionInSky(double latitudeDeg, double longitudeDeg, double elevationDeg, double azimuthDeg);

// How many base scenes a scene may derive from, one above the other ([scene] base): deeper is taken
// for a cycle.
constexpr int kMaxBaseScenes = 8;

// Reads and validates a scene file whose components come from `registry`. Throws InputError
// naming file and line.
Scene loadScene(const std::string& path, const Registry& registry);

// The scene without the components the CPU reference does not model (Component::inReference).
Scene withoutUnmodelled(Scene scene);

} // namespace aurorawall::scene
