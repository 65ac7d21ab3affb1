#pragma once
// The aurora component (Lawlor & Genetti 2011): keyframed curtains of precipitating electrons in
// an emissive shell, their light from Lazarev deposition and the emission lines' yields.
#include "components/aurora/physics/lazarev.h"
#include "scene/component.h"

#include <glm/glm.hpp>

#include <vector>


namespace aurorawall::components::aurora {


// One keyframe of a curtain: its footprint (a spline on the sphere through latitude/longitude
// control points) and its electrons at one moment of the substorm.
struct CurtainKey {
    double timeS = 0.0;
    std::vector<glm::dvec2> pointsLatLonDeg;
    double energyFluxErgPerCm2S = 1.0; // peak precipitating energy flux on the centre line
    double energyKeV = 5.0;            // (characteristic) electron energy: sets the curtain's height
    double detailPhase = 0.0;          // fluid detail: 0 the smooth start ... 1 fully turbulent
};

// An auroral curtain, keyframed through the phases of a substorm; between keys everything is
// interpolated smoothly (curtain_frames.h). Every key has the same number of points.
struct Curtain {
    std::vector<CurtainKey> keys;  // ordered by time
    double thicknessKm = 1.0;      // across the curtain: twice the standard deviation of its flux
    double driftKmPerS = 0.0;      // the detail pattern slides along the curtain
    double pulsationPeriodS = 0.0; // pulsating aurora (recovery): brightness modulated; 0 = steady
    double pulsationDepth = 0.0;   // 0..1: fraction of the brightness that pulsates
};

// Where the footprint map is built: on the GPU in compute shaders (footprint_map_gpu.h), or on the
// CPU on a worker thread and uploaded (curtain_build.h). Auto: the CPU on Mesa's CPU renderers,
// whose "GPU" is the same CPU (there the compute build costs 50 ms a frame at 512², the worker
// thread's build none of the frame's time), the GPU everywhere else.
enum class MapBuilder { Auto, Cpu, Gpu };

// The most curtains a scene may have (the shaders' uniform arrays).
inline constexpr int kMaxCurtains = 16;
// The most points of a curtain's sampled polyline: one texture row each, and every GL 4.5 device
// holds rows of 16384 texels (GL_MAX_TEXTURE_SIZE ≥ 16384). At the default 2 km spacing a curtain
// may be 32,768 km long.
inline constexpr int kMaxPolylinePoints = 16384;

struct Settings : scene::SettingsOf<Settings> {
    static constexpr const char* kComponent = "aurora";
    physics::Spectrum spectrum = physics::Spectrum::Maxwellian; // of the precipitating electrons
    double bottomKm = 85.0;
    double topKm = 300.0;
    double stepKm = 12.0;             // march step inside curtains (curtain coordinates once per step)
    double resolveKm = 1.0;           // sub-steps: altitude and position along a curtain change by at most this
    double resolveCells = 0.75;       // and, with curtain detail and the middle column, the coordinate a
                                      // sub-step is not integrated over (along or across) by at most this many
                                      // detail cells
    bool exactSubSteps = true;        // sub_step_flux = "exact": with curtain detail, each step's flux integrated
                                      // exactly along its slanted path, in pieces cut at the detail's cell
                                      // centres (about 3 texture reads a cell); "midpoint": the middle column,
                                      // 2 reads a sub-step (AURORA_EXACT_SUB_STEPS selects the code)
    double polylineSpacingKm = 2.0;   // curtain splines are sampled this finely for the shader
    int footprintMapSize = 512;       // texels per side of the jump-flooded footprint map
    MapBuilder footprintMapBuild = MapBuilder::Auto; // where the map is built each frame
    bool skipEmptySpace = true;       // long steps where the footprint map proves no curtain is near
    double tableAltitudeStepKm = 0.5; // deposition table resolution (src/components/aurora/physics/deposition_table.h)
    int tableEnergyCount = 128;
    std::vector<Curtain> curtains;
};

const scene::Component& component();

} // namespace aurorawall::components::aurora
