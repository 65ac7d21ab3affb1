#include "scene/scene.h"

#include "physics/constants.h"
#include "common/input_error.h"
#include "common/planet_frame.h"
#include "config/toml_reader.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <filesystem>
#include <sstream>

namespace aurorawall::scene {

using config::parseTomlFile, config::TableReader, config::TomlValue;

namespace {


// The local horizon at a point of the planet frame: zenith, north and east (unit vectors).
LocalFrame horizonAt(const glm::dvec3& positionKm)
{
    LocalFrame f;
    f.up = glm::normalize(positionKm);
    const glm::dvec3 north = glm::dvec3(0, 0, 1) - f.up * f.up.z;
    f.north = glm::length(north) > 1e-12 ? glm::normalize(north) : glm::dvec3(1, 0, 0); // at a pole: any
    f.east = glm::cross(f.north, f.up);
    return f;
}

// A frame looking along `forward` with up as near the zenith as it can be; looking straight up or
// down, up is `fallbackUp`.
CameraFrame levelFrame(const glm::dvec3& forward, const glm::dvec3& zenith, const glm::dvec3& fallbackUp)
{
    CameraFrame f;
    f.forward = glm::normalize(forward);
    const glm::dvec3 up = zenith - f.forward * glm::dot(zenith, f.forward);
    f.up = glm::length(up) > 1e-9 ? glm::normalize(up) : fallbackUp;
    return f;
}

// A point given as `PREFIXlatitude_deg`, `PREFIXlongitude_deg`, `PREFIXaltitude_km` (above the planet's
// sphere), or as `PREFIXposition_km` or `PREFIXposition_radii` in the planet frame.
glm::dvec3 readPoint(const TableReader& t, const std::string& prefix, double planetRadiusKm)
{
    if (t.has(prefix + "position_km"))
        return t.vector3(prefix + "position_km");
    if (t.has(prefix + "position_radii"))
        return t.vector3(prefix + "position_radii") * planetRadiusKm;
    const double lat = t.number(prefix + "latitude_deg", -90, 90), lon = t.number(prefix + "longitude_deg", -360, 360);
    const double alt = t.number(prefix + "altitude_km", -planetRadiusKm + 1, 1e9);
    return planetPoint(lat, lon, planetRadiusKm + alt);
}

// A camera's position as readPoint gives it, at least 1 km from the planet's centre (as the lowest
// altitude_km allows): the viewer's horizon, and so its heading and pitch, need an up direction.
glm::dvec3 readCameraPosition(const TableReader& t, double planetRadiusKm)
{
    const glm::dvec3 position = readPoint(t, "", planetRadiusKm);
    if (!(glm::length(position) >= 1.0 - 1e-9)) { // the lowest altitude_km gives 1 km to rounding
        const std::string key = t.has("position_km")      ? "position_km"
                                : t.has("position_radii") ? "position_radii"
                                                          : "altitude_km";
        std::ostringstream got;
        got << glm::length(position);
        t.fail(key, "must be at least 1 km from the planet's centre (got " + got.str() + " km)");
    }
    return position;
}

// One [[camera.key]]: its time, a position and one orientation: heading_deg/pitch_deg, a look-at
// point (look_at_km, or look_at_latitude_deg/look_at_longitude_deg/look_at_altitude_km), or explicit
// direction/up vectors; roll_deg (clockwise as seen from behind) turns the first two about the view;
// field_of_view_deg or zoom (optional) zooms the wall (camera_path.h).
// Unit and perpendicular to a few doubles' rounding (1e-15): as a camera's own frame, and as written
// with 17 digits.
bool orthonormal(const CameraFrame& frame)
{
    const double eps = 1e-15;
    return std::abs(glm::length(frame.forward) - 1.0) <= eps && std::abs(glm::length(frame.up) - 1.0) <= eps &&
           std::abs(glm::dot(frame.forward, frame.up)) <= eps;
}

// v divided by its largest component's magnitude (0 stays 0), so that a vector of any nonzero length,
// 1e-300 as well as 1e12, normalizes.
glm::dvec3 scaledByLargest(glm::dvec3 v)
{
    const double largest = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    return largest > 0.0 ? v / largest : v;
}

// The direction and up vectors of a table made orthonormal: up loses its part along the view. Any
// nonzero lengths are taken; an up within 1e-9 rad of the view is refused, naming the key.
CameraFrame orthonormalFrame(const TableReader& t, glm::dvec3 forward, glm::dvec3 up)
{
    forward = scaledByLargest(forward);
    up = scaledByLargest(up);
    if (forward == glm::dvec3(0.0))
        t.fail("direction", "must not be zero");
    if (up == glm::dvec3(0.0))
        t.fail("up", "must not be zero");
    forward = glm::normalize(forward);
    up = glm::normalize(up);
    up -= forward * glm::dot(up, forward);
    if (glm::length(up) < 1e-9)
        t.fail("up", "must not be parallel to the view direction");
    return {forward, glm::normalize(up)};
}

CameraKey readCameraKey(const TableReader& k, double planetRadiusKm)
{
    CameraKey key;
    key.timeS = k.number("time_s", -1e15, 1e15);
    key.positionKm = readCameraPosition(k, planetRadiusKm);
    const LocalFrame horizon = horizonAt(key.positionKm);

    const std::vector<std::string> forms = {"heading_deg", "look_at_km", "look_at_latitude_deg", "direction"};
    std::string given;
    for (const std::string& form : forms)
        if (k.has(form)) {
            if (!given.empty())
                k.fail(form, "give one orientation: heading_deg and pitch_deg, look_at_km, "
                             "look_at_latitude_deg/longitude_deg/altitude_km, or direction and up (" +
                                 given + " is given too)");
            given = form;
        }
    if (given.empty())
        k.fail("heading_deg", "missing: give heading_deg and pitch_deg, look_at_km, "
                              "look_at_latitude_deg/longitude_deg/altitude_km, or direction and up");

    CameraFrame frame;
    if (given == "direction") {
        frame.forward = k.vector3("direction");
        frame.up = k.vector3("up");
        if (!orthonormal(frame)) // a recorded frame is kept as written, so that it replays bit for bit
            frame = orthonormalFrame(k, frame.forward, frame.up);
    } else {
        if (given == "heading_deg") {
            const double heading = k.number("heading_deg", -360, 360) * physics::kDegree;
            const double pitch = k.number("pitch_deg", -90, 90) * physics::kDegree;
            const glm::dvec3 horizontal = std::cos(heading) * horizon.north + std::sin(heading) * horizon.east;
            frame = levelFrame(std::cos(pitch) * horizontal + std::sin(pitch) * horizon.up, horizon.up,
                               pitch > 0 ? -horizontal : horizontal);
        } else {
            const std::string field = given == "look_at_km" ? "look_at_km" : "look_at_latitude_deg";
            const glm::dvec3 target = given == "look_at_km" ? k.vector3("look_at_km")
                                                            : readPoint(k, "look_at_", planetRadiusKm);
            if (glm::length(target - key.positionKm) < 1e-9)
                k.fail(field, "the look-at point is the camera's position");
            frame = levelFrame(target - key.positionKm, horizon.up, horizon.north);
        }
        const double roll = k.number("roll_deg", -180, 180, 0.0) * physics::kDegree;
        const glm::dvec3 right = glm::cross(frame.forward, frame.up);
        frame.up = std::cos(roll) * frame.up + std::sin(roll) * right;
    }
    key.orientation = orientationOf(frame);
    key.frame = frame;
    if (k.has("field_of_view_deg") && k.has("zoom"))
        k.fail("zoom", "give field_of_view_deg or zoom, not both");
    key.zoom = k.numberAbove("zoom", 0.0, 1e6, 1.0);
    if (k.has("field_of_view_deg")) {
        // A pinhole's vertical field of view lies strictly between 0 and 180 degrees.
        key.fieldOfViewDeg = k.number("field_of_view_deg", -1e9, 1e9);
        if (!(key.fieldOfViewDeg > 0.0 && key.fieldOfViewDeg < 180.0)) {
            std::ostringstream got;
            got << key.fieldOfViewDeg;
            k.fail("field_of_view_deg", "must be in (0, 180) degrees, exclusive (got " + got.str() + ")");
        }
    }
    k.rejectUnknownKeys();
    return key;
}

// [[camera.key]]: at least 2 keys in increasing time.
CameraPath readCameraPath(const TableReader& t, double planetRadiusKm)
{
    t.rejectKeysOutside({"key"});
    const std::vector<TableReader> tables = t.arrayOfTables("key");
    if (tables.size() < 2)
        t.fail("key", "a camera path needs at least 2 keys, got " + std::to_string(tables.size()));
    std::vector<CameraKey> keys;
    for (const TableReader& k : tables) {
        keys.push_back(readCameraKey(k, planetRadiusKm));
        if (keys.size() > 1 && !(keys.back().timeS > keys[keys.size() - 2].timeS))
        {
            std::ostringstream previous;
            previous << keys[keys.size() - 2].timeS;
            k.fail("time_s", "keys must be in increasing time (the previous key is at " + previous.str() + " s)");
        }
    }
    return CameraPath(std::move(keys));
}

Camera readCamera(const TableReader& t, double planetRadiusKm)
{
    Camera c;
    if (t.has("key")) {
        c.path = readCameraPath(t, planetRadiusKm);
        const CameraKey& first = c.path.keys().front();
        const CameraFrame frame = c.path.frameAt(first.timeS);
        c.positionKm = first.positionKm;
        c.forward = frame.forward;
        c.up = frame.up;
        return c;
    }
    if (t.has("position_radii") || t.has("position_km")) {
        // Explicit vectors, e.g. the paper's benchmark view in planet radii.
        c.positionKm = readCameraPosition(t, planetRadiusKm);
        c.forward = t.vector3("direction");
        c.up = t.vector3("up");
    } else {
        // Geographic: where the viewer stands and where they look.
        const double lat = t.number("latitude_deg", -90, 90), lon = t.number("longitude_deg", -360, 360);
        const double alt = t.number("altitude_km", -planetRadiusKm + 1, 1e9);
        const double heading = t.number("heading_deg", -360, 360) * physics::kDegree;
        const double elevation = t.number("elevation_deg", -90, 90) * physics::kDegree;
        c.positionKm = planetPoint(lat, lon, planetRadiusKm + alt);
        const LocalFrame local = localFrame(lat, lon);
        const glm::dvec3 zenith = local.up;
        const glm::dvec3 horizontal = std::cos(heading) * local.north + std::sin(heading) * local.east;
        c.forward = std::cos(elevation) * horizontal + std::sin(elevation) * zenith;
        c.up = glm::cross(glm::cross(c.forward, zenith), c.forward);
        if (glm::length(c.up) < 1e-9) // looking straight up or down: up is the heading direction
            c.up = elevation > 0 ? -horizontal : horizontal;
    }
    c.speedKmPerS = t.number("speed_km_per_s", -1e6, 1e6, 0.0);
    const CameraFrame frame = orthonormalFrame(t, c.forward, c.up);
    c.forward = frame.forward;
    c.up = frame.up;
    t.rejectUnknownKeys();
    return c;
}

} // namespace

// Planet frame: z north, x toward longitude 180 deg, y toward 90 deg W.
glm::dvec3 planetPoint(double latitudeDeg, double longitudeDeg, double radius)
{
    return radius * common::unitFromLatLon(latitudeDeg, longitudeDeg);
}

double altitudeKm(glm::dvec3 positionKm, double radiusKm)
{
    const double altitude = glm::length(positionKm) - radiusKm;
    return std::abs(altitude) <= 8.0 * std::numeric_limits<double>::epsilon() * radiusKm ? 0.0 : altitude;
}

LocalFrame localFrame(double latitudeDeg, double longitudeDeg)
{
    LocalFrame f;
    f.up = planetPoint(latitudeDeg, longitudeDeg, 1.0);
    const glm::dvec3 north = glm::dvec3(0, 0, 1) - f.up * f.up.z;
    // At a pole "north" is undefined; take the direction away from the given meridian there.
    f.north = glm::length(north) > 1e-12 ? glm::normalize(north)
                                         : glm::normalize(planetPoint(0, longitudeDeg, 1) * -f.up.z);
    f.east = glm::cross(f.north, f.up);
    return f;
}

glm::dvec3 directionInSky(double latitudeDeg, double longitudeDeg, double elevationDeg, double azimuthDeg)
{
    const LocalFrame local = localFrame(latitudeDeg, longitudeDeg);
    const double elevation = glm::radians(elevationDeg), azimuth = glm::radians(azimuthDeg);
    return std::cos(elevation) * (std::cos(azimuth) * local.north + std::sin(azimuth) * local.east) +
           std::sin(elevation) * local.up;
}

Scene::Scene(const Scene& other)
    : sourceFile(other.sourceFile), baseFiles(other.baseFiles), name(other.name), planetRadiusKm(other.planetRadiusKm), camera(other.camera),
      startTimeS(other.startTimeS), timeStepS(other.timeStepS), exposure(other.exposure),
      components_(other.components_)
{
    for (const auto& [key, value] : other.settings_)
        settings_[key] = value->clone();
}

Scene& Scene::operator=(const Scene& other)
{
    if (this != &other) {
        Scene copy(other);
        *this = std::move(copy);
    }
    return *this;
}

bool Scene::has(const std::string& componentName) const
{
    return settings_.count(componentName) != 0;
}

double Scene::reachRadiusKm() const
{
    double reach = 0.0;
    for (const Component* c : components_)
        reach = std::max(reach, c->reachKm(*this));
    return planetRadiusKm + reach;
}

const Component* Scene::provider(const std::string& role) const
{
    for (const Component* c : components_) {
        const std::vector<std::string> roles = c->provides();
        if (std::count(roles.begin(), roles.end(), role))
            return c;
    }
    return nullptr;
}

void Scene::add(const Component& c)
{
    if (!has(c.name()))
        settings_[c.name()] = c.defaultSettings();
    components_.push_back(&c);
}

void Scene::remove(const std::string& componentName)
{
    settings_.erase(componentName);
    components_.erase(std::remove_if(components_.begin(), components_.end(),
                                     [&](const Component* c) { return c->name() == componentName; }),
                      components_.end());
}

namespace {

// " (provided by A, B)": the registered components that provide `role`; empty when none does (a
// component's name).
std::string providersOf(const std::string& role, const Registry& registry)
{
    std::string names;
    for (const Component* c : registry) {
        const std::vector<std::string> roles = c->provides();
        if (std::count(roles.begin(), roles.end(), role))
            names += (names.empty() ? "" : ", ") + c->name();
    }
    return names.empty() ? "" : " (provided by " + names + ")";
}

} // namespace

// Reads scene files; a friend of Scene, which it fills.
class SceneLoader {
public:
    static void listComponents(Scene& s, const TableReader& meta, const Registry& registry);
    static Scene load(const std::string& path, const Registry& registry, int depth);
};

// Lists the components named in [scene] components, in registry order, keeping the settings of
// those a base scene already had.
void SceneLoader::listComponents(Scene& s, const TableReader& meta, const Registry& registry)
{
    const std::vector<std::string> names = meta.strings("components");
    std::string known;
    for (const Component* c : registry)
        known += (known.empty() ? "" : ", ") + c->name();
    for (const std::string& name : names) {
        if (std::none_of(registry.begin(), registry.end(), [&](const Component* c) { return c->name() == name; }))
            meta.fail("components", "unknown component '" + common::echoedInput(name) + "' (known: " + known + ")");
        if (std::count(names.begin(), names.end(), name) > 1)
            meta.fail("components", "component '" + common::echoedInput(name) + "' listed twice");
    }
    Scene listed;
    listed.planetRadiusKm = s.planetRadiusKm;
    for (const Component* c : registry)
        if (std::count(names.begin(), names.end(), c->name())) {
            listed.add(*c);
            if (s.has(c->name()))
                listed.settings_[c->name()] = s.settings_.at(c->name())->clone();
        }
    s.components_ = listed.components_;
    s.settings_ = std::move(listed.settings_);
    for (const Component* c : s.components_) {
        for (const std::string& needed : c->needs())
            if (!s.has(needed) && !s.provider(needed))
                meta.fail("components", "'" + c->name() + "' needs '" + needed + "'" + providersOf(needed, registry));
        for (const std::string& role : c->provides())
            if (const Component* first = s.provider(role); first != c)
                meta.fail("components", "the scene lists both " + c->name() + " and " + first->name() +
                                            ": both provide the " + role + ", and a scene may list one of them");
    }
}

// depth counts the base scenes above this one (a guard against cycles).
Scene SceneLoader::load(const std::string& path, const Registry& registry, int depth)
{
    const config::TomlFile root = parseTomlFile(path);
    const TableReader top(root.root, path, "", root.lines);
    const TableReader meta = top.table("scene");
    // A scene may start from another one ([scene] base = "file", relative to this file) and
    // change only what it gives: a camera preset over the substorm, say.
    Scene s;
    const bool derived = meta.has("base");
    if (derived) {
        if (depth >= kMaxBaseScenes)
            meta.fail("base", "scenes derive from each other more than " + std::to_string(kMaxBaseScenes) +
                                  " deep (a cycle?)");
        const std::string name = meta.string("base");
        const std::string base = (std::filesystem::path(path).parent_path() / name).string();
        if (name.empty() || !std::filesystem::is_regular_file(base))
            meta.fail("base", "'" + name + "' is not a scene file (" + base + ", relative to this file)");
        s = load(base, registry, depth + 1);
        s.baseFiles.insert(s.baseFiles.begin(), base);
    }
    s.sourceFile = path;
    s.name = derived ? meta.string("name", s.name) : meta.string("name");
    if (!derived || meta.has("components"))
        listComponents(s, meta, registry);
    s.startTimeS = meta.number("start_time_s", -1e15, 1e15, s.startTimeS);
    s.timeStepS = meta.number("time_step_s", 0.0, 1e9, s.timeStepS);
    s.exposure = meta.number("exposure", 1e-12, 1e12, s.exposure);
    meta.rejectUnknownKeys();

    // Each listed component reads its own table, in registry order; a table for a component the
    // scene does not list is reported as unknown, so nothing is silently ignored.
    for (const Component* c : s.components_) {
        const TableReader t = top.optionalTable(c->name());
        c->read(t, s, *s.settings_.at(c->name()));
        t.rejectUnknownKeys();
    }
    if (!derived || top.has("camera"))
        s.camera = readCamera(top.table("camera"), s.planetRadiusKm);
    top.rejectUnknownKeys();
    return s;
}

Scene loadScene(const std::string& path, const Registry& registry) { return SceneLoader::load(path, registry, 0); }

Scene withoutUnmodelled(Scene scene)
{
    std::vector<std::string> unmodelled;
    for (const Component* c : scene.components())
        if (!c->inReference())
            unmodelled.push_back(c->name());
    for (const std::string& name : unmodelled)
        scene.remove(name);
    return scene;
}

} // namespace aurorawall::scene
