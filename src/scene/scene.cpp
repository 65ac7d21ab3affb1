#include "scene/scene.h"

#include "common/input_error.h"
#include "common/planet_frame.h"
#include "config/toml_reader.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace aurorawall::scene {

using config::parseTomlFile, config::TableReader, config::TomlValue;

namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

const Component kAllComponents[] = {Component::Planet, Component::PlanetTexture, Component::Atmosphere,
                                    Component::Sky,    Component::Aurora,        Component::FluidDetail,
                                    Component::Stars};

// The local horizon frame at a site: up (the zenith), north and east, all unit vectors.
struct LocalFrame {
    glm::dvec3 up, north, east;
};

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

Camera readCamera(const TableReader& t, double planetRadiusKm)
{
    Camera c;
    if (t.has("position_radii") || t.has("position_km")) {
        // Explicit vectors, e.g. the paper's benchmark view in planet radii.
        c.positionKm = t.has("position_radii") ? t.vector3("position_radii") * planetRadiusKm
                                               : t.vector3("position_km");
        c.forward = t.vector3("direction");
        c.up = t.vector3("up");
    } else {
        // Geographic: where the viewer stands and where they look.
        const double lat = t.number("latitude_deg", -90, 90), lon = t.number("longitude_deg", -360, 360);
        const double alt = t.number("altitude_km", -planetRadiusKm + 1, 1e9);
        const double heading = t.number("heading_deg", -360, 360) * kDeg;
        const double elevation = t.number("elevation_deg", -90, 90) * kDeg;
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
    if (glm::length(c.forward) < 1e-12)
        t.fail("direction", "must not be zero");
    c.forward = glm::normalize(c.forward);
    c.up = c.up - c.forward * glm::dot(c.up, c.forward);
    if (glm::length(c.up) < 1e-9)
        t.fail("up", "must not be parallel to the view direction");
    c.up = glm::normalize(c.up);
    t.rejectUnknownKeys();
    return c;
}

// A light is given as seen from a site: where it stands in that sky (elevation above the
// horizon, azimuth clockwise from north), and its illuminance above the atmosphere.
SkyLight readSkyLight(const TableReader& t)
{
    SkyLight l;
    const double lat = t.number("site_latitude_deg", -90, 90), lon = t.number("site_longitude_deg", -360, 360);
    const double elevation = t.number("elevation_deg", -90, 90) * kDeg;
    const double azimuth = t.number("azimuth_deg", -360, 360) * kDeg;
    const LocalFrame local = localFrame(lat, lon);
    l.direction = std::cos(elevation) * (std::cos(azimuth) * local.north + std::sin(azimuth) * local.east) +
                  std::sin(elevation) * local.up;
    const double lux = t.number("illuminance_lux", 0.0, 1e7, 1.28e5);
    l.illuminanceLux = glm::dvec3(lux);
    t.rejectUnknownKeys();
    return l;
}

// The fields a key may set; `c` holds the defaults (the curtain's own keys, or the previous key).
CurtainKey readCurtainKey(const TableReader& t, CurtainKey c)
{
    if (t.has("points_lat_lon_deg") || c.pointsLatLonDeg.empty())
        c.pointsLatLonDeg = t.pairs("points_lat_lon_deg", {-90, -360}, {90, 360});
    if (c.pointsLatLonDeg.size() < 2)
        t.fail("points_lat_lon_deg", "needs at least 2 points");
    c.energyFluxErgPerCm2S = t.number("energy_flux_erg_cm2_s", 0, 1e4, c.energyFluxErgPerCm2S);
    c.energyKeV = t.number("energy_kev", 0.5, 50, c.energyKeV); // the deposition table's range
    c.detailPhase = t.number("detail_phase", 0, 1, c.detailPhase);
    return c;
}

// A curtain is either one state (its own keys) or a list of [[aurora.curtain.key]] tables, each
// with time_s; a key leaves out what does not change from the key before it.
Curtain readCurtain(const TableReader& t)
{
    Curtain c;
    c.thicknessKm = t.number("thickness_km", 0.01, 1000, c.thicknessKm);
    c.driftKmPerS = t.number("drift_km_per_s", -1e4, 1e4, c.driftKmPerS);
    c.pulsationPeriodS = t.number("pulsation_period_s", 0, 1e6, c.pulsationPeriodS);
    c.pulsationDepth = t.number("pulsation_depth", 0, 1, c.pulsationDepth);
    if (!t.has("key")) {
        c.keys.push_back(readCurtainKey(t, CurtainKey{}));
    } else {
        CurtainKey previous;
        for (const TableReader& k : t.arrayOfTables("key")) {
            CurtainKey key = readCurtainKey(k, previous);
            key.timeS = k.number("time_s", -1e15, 1e15);
            if (!c.keys.empty() && key.timeS <= c.keys.back().timeS)
                k.fail("time_s", "keys must be in increasing time");
            if (!c.keys.empty() && key.pointsLatLonDeg.size() != c.keys.front().pointsLatLonDeg.size())
                k.fail("points_lat_lon_deg", "every key of a curtain needs the same number of points");
            k.rejectUnknownKeys();
            c.keys.push_back(key);
            previous = key;
        }
        if (c.keys.empty())
            t.fail("key", "needs at least one key");
    }
    t.rejectUnknownKeys();
    return c;
}

} // namespace

// Planet frame: z north, x toward longitude 180 deg, y toward 90 deg W.
glm::dvec3 planetPoint(double latitudeDeg, double longitudeDeg, double radius)
{
    return radius * unitFromLatLon(latitudeDeg, longitudeDeg);
}

const char* componentName(Component c)
{
    switch (c) {
    case Component::Planet: return "planet";
    case Component::PlanetTexture: return "planet_texture";
    case Component::FluidDetail: return "fluid_detail";
    case Component::Sky: return "sky";
    case Component::Atmosphere: return "atmosphere";
    case Component::Aurora: return "aurora";
    case Component::Stars: return "stars";
    }
    return "?";
}

bool Scene::has(Component c) const
{
    return std::find(components.begin(), components.end(), c) != components.end();
}

// depth counts the base scenes above this one (a guard against cycles).
static Scene loadSceneAtDepth(const std::string& path, int depth)
{
    const TomlValue root = parseTomlFile(path);
    const TableReader top(root, path, "");
    const TableReader meta = top.table("scene");
    // A scene may start from another one ([scene] base = "file", relative to this file) and
    // change only what it gives: a camera preset over the substorm, say.
    Scene s;
    const bool derived = meta.has("base");
    if (derived) {
        if (depth >= 8)
            meta.fail("base", "scenes derive from each other more than 8 deep (a cycle?)");
        const std::string base = (std::filesystem::path(path).parent_path() / meta.string("base")).string();
        s = loadSceneAtDepth(base, depth + 1);
    }
    s.sourceFile = path;
    s.name = derived ? meta.string("name", s.name) : meta.string("name");
    if (!derived || meta.has("components"))
        s.components.clear();
    for (const std::string& name : derived && !meta.has("components") ? std::vector<std::string>{}
                                                                        : meta.strings("components")) {
        auto known = std::find_if(std::begin(kAllComponents), std::end(kAllComponents),
                                  [&](Component c) { return name == componentName(c); });
        if (known == std::end(kAllComponents))
            meta.fail("components", "unknown component '" + name +
                                        "' (known: planet, planet_texture, atmosphere, sky, aurora, fluid_detail, stars)");
        if (s.has(*known))
            meta.fail("components", "component '" + name + "' listed twice");
        s.components.push_back(*known);
    }
    s.startTimeS = meta.number("start_time_s", -1e15, 1e15, s.startTimeS);
    s.timeStepS = meta.number("time_step_s", 0.0, 1e9, s.timeStepS);
    s.exposure = meta.number("exposure", 1e-12, 1e12, s.exposure);
    meta.rejectUnknownKeys();

    // A component's table is read only when the component is listed; a table for a component
    // the scene does not list is reported as unknown, so nothing is silently ignored.
    if (s.has(Component::PlanetTexture) && !s.has(Component::Planet))
        meta.fail("components", "'planet_texture' needs 'planet'");
    if (s.has(Component::FluidDetail) && !s.has(Component::Aurora))
        meta.fail("components", "'fluid_detail' needs 'aurora'");
    if (s.has(Component::Planet)) {
        const TableReader t = top.optionalTable("planet");
        s.planet.radiusKm = t.number("radius_km", 1.0, 1e6, s.planet.radiusKm);
        if (s.has(Component::PlanetTexture)) {
            s.planet.nightImage = t.string("night_image", s.planet.nightImage);
            s.planet.nightLightsRadiance = t.number("night_lights_cd_m2", 0.0, 1e6, s.planet.nightLightsRadiance);
        }
        t.rejectUnknownKeys();
    }
    if (s.has(Component::Atmosphere)) {
        if (!s.has(Component::Planet))
            meta.fail("components", "'atmosphere' needs 'planet'");
        const TableReader t = top.optionalTable("atmosphere");
        s.atmosphere.topKm = t.number("top_km", 1.0, 1000.0, s.atmosphere.topKm);
        s.atmosphere.scaleHeightKm = t.number("scale_height_km", 0.1, 1000.0, s.atmosphere.scaleHeightKm);
        t.rejectUnknownKeys();
    }
    if (s.has(Component::Sky)) {
        if (!s.has(Component::Atmosphere))
            meta.fail("components", "'sky' needs 'atmosphere'");
        const TableReader t = top.optionalTable("sky");
        s.sky.topKm = t.number("top_km", 1.0, 1000.0, s.sky.topKm);
        s.sky.viewSteps = static_cast<int>(t.number("view_steps", 1, 1024, s.sky.viewSteps));
        s.sky.nestedMarch = t.choice("light_method", {"closed-form", "nested-march"}, s.sky.nestedMarch) == 1;
        s.sky.lightSteps = static_cast<int>(t.number("light_steps", 1, 1024, s.sky.lightSteps));
        if (t.has("light")) {
            s.sky.lights.clear();
            for (const TableReader& l : t.arrayOfTables("light"))
                s.sky.lights.push_back(readSkyLight(l));
        }
        if (s.sky.lights.size() > 8)
            t.fail("light", "at most 8 lights");
        t.rejectUnknownKeys();
    }
    if (s.has(Component::Aurora)) {
        if (!s.has(Component::Planet))
            meta.fail("components", "'aurora' needs 'planet'");
        const TableReader t = top.optionalTable("aurora");
        s.aurora.spectrum = t.choice("spectrum", {"maxwellian", "monoenergetic"},
                                     s.aurora.spectrum == ElectronSpectrum::Maxwellian ? 0 : 1) == 0
                                ? ElectronSpectrum::Maxwellian
                                : ElectronSpectrum::Monoenergetic;
        s.aurora.bottomKm = t.number("bottom_km", 1.0, 5000.0, s.aurora.bottomKm);
        s.aurora.topKm = t.number("top_km", 1.0, 5000.0, s.aurora.topKm);
        if (s.aurora.topKm <= s.aurora.bottomKm)
            t.fail("top_km", "must be above aurora.bottom_km");
        if (s.has(Component::Atmosphere) && s.aurora.bottomKm < s.atmosphere.topKm)
            t.fail("bottom_km", "must not be below atmosphere.top_km (the layers are composited in order)");
        s.aurora.stepKm = t.number("step_km", 0.05, 100.0, s.aurora.stepKm);
        s.aurora.polylineSpacingKm = t.number("polyline_spacing_km", 0.1, 100.0, s.aurora.polylineSpacingKm);
        s.aurora.footprintMapSize = static_cast<int>(t.number("footprint_map_size", 16, 8192, s.aurora.footprintMapSize));
        if (s.aurora.footprintMapSize & (s.aurora.footprintMapSize - 1))
            t.fail("footprint_map_size", "must be a power of two");
        s.aurora.skipEmptySpace = t.choice("skip_empty_space", {"no", "yes"}, s.aurora.skipEmptySpace) == 1;
        s.aurora.tableAltitudeStepKm = t.number("table_altitude_step_km", 0.05, 10.0, s.aurora.tableAltitudeStepKm);
        s.aurora.tableEnergyCount = static_cast<int>(t.number("table_energy_count", 2, 4096, s.aurora.tableEnergyCount));
        if (t.has("curtain")) {
            s.aurora.curtains.clear(); // a derived scene's curtains replace its base's
            for (const TableReader& c : t.arrayOfTables("curtain"))
                s.aurora.curtains.push_back(readCurtain(c));
        }
        if (s.aurora.curtains.size() > 16)
            t.fail("curtain", "at most 16 curtains are supported");
        if (s.has(Component::FluidDetail)) {
            const TableReader d = t.optionalTable("detail");
            FluidDetail& f = s.aurora.detail;
            f.cellsAlong = static_cast<int>(d.number("cells_along", 16, 4096, f.cellsAlong));
            f.cellsAcross = static_cast<int>(d.number("cells_across", 4, 4096, f.cellsAcross));
            for (int n : {f.cellsAlong, f.cellsAcross})
                if (n & (n - 1))
                    d.fail(n == f.cellsAlong ? "cells_along" : "cells_across", "must be a power of two");
            f.stripLengthKm = d.number("strip_length_km", 1.0, 1e5, f.stripLengthKm);
            f.stripWidthKm = d.number("strip_width_km", 1.0, 1e4, f.stripWidthKm);
            f.frames = static_cast<int>(d.number("frames", 2, 256, f.frames));
            f.seed = static_cast<unsigned>(d.number("seed", 0, 4294967295.0, f.seed));
            d.rejectUnknownKeys();
        }
        t.rejectUnknownKeys();
    }
    if (s.has(Component::Stars)) {
        const TableReader t = top.optionalTable("stars");
        s.stars.density = t.number("density", 0.0, 1.0, s.stars.density);
        s.stars.brightness = t.number("brightness", 0.0, 1e6, s.stars.brightness);
        t.rejectUnknownKeys();
    }
    if (!derived || top.has("camera"))
        s.camera = readCamera(top.table("camera"), s.planet.radiusKm);
    top.rejectUnknownKeys();
    return s;
}

Scene loadScene(const std::string& path) { return loadSceneAtDepth(path, 0); }

} // namespace aurorawall::scene
