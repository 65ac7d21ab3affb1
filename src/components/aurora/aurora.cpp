#include "components/aurora/aurora.h"

#include "components/aurora/aurora_march.h"
#include "components/aurora/aurora_reference.h"
#include "components/aurora/aurora_tables.h"
#include "components/aurora/curtain_field.h"
#include "components/aurora/curtain_frames.h"
#include "components/aurora/physics/curtain_geometry.h"
#include "components/roles/curtain_detail.h"
#include "common/data_dir.h"
#include "gl/context.h"
#include "gl/shader_program.h"
#include "scene/scene.h"
#include "components/roles/lower_atmosphere.h"
#include "components/roles/names.h"

namespace aurorawall::components::aurora {

namespace {

// Auto resolved for the current context's renderer.
MapBuilder resolvedMapBuilder(MapBuilder choice)
{
    if (choice != MapBuilder::Auto)
        return choice;
    return gl::isSoftwareRenderer(gl::currentRendererName()) ? MapBuilder::Cpu : MapBuilder::Gpu;
}

class Renderer : public scene::ComponentRenderer {
public:
    Renderer(const Settings& s, double planetRadiusKm, const roles::DetailShape* detail)
        : s_(s), tables_(s), model_(s, planetRadiusKm, detail),
          field_(model_, resolvedMapBuilder(s.footprintMapBuild), common::dataDirectory() + "/shaders")
    {
    }
    std::string precomputationLog() const override { return tables_.summary(); }
    void whileDrawing() override { field_.uploadAhead(); }
    void setFrame(gl::Program& program, const cluster::FrameState& frame) override
    {
        program.set("uAuroraBottomKm", static_cast<float>(s_.bottomKm));
        program.set("uAuroraTopKm", static_cast<float>(s_.topKm));
        program.set("uAuroraStepKm", static_cast<float>(s_.stepKm));
        program.set("uAuroraResolveKm", static_cast<float>(s_.resolveKm));
        program.set("uAuroraResolveCells", static_cast<float>(s_.resolveCells));
        program.set("uSkipEmptySpace", s_.skipEmptySpace ? 1 : 0);
        field_.update(frame.timeS, frame.nextTimeS);
        tables_.update(field_.energiesKeV());
    }
    void bind(gl::Program& program) const override
    {
        tables_.bind(program);
        field_.bind(program);
    }
    std::string frameLog() const override { return field_.summary(); }

private:
    const Settings& s_;
    AuroraTables tables_;
    CurtainModel model_;
    CurtainField field_;
};

// The fields a key may set; `c` holds the defaults (the curtain's own keys, or the previous key).
CurtainKey readCurtainKey(const config::TableReader& t, CurtainKey c)
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

// A key's curtain, sampled as the renderer samples it, must fit one row of the polylines' texture.
void checkPolylineFits(const config::TableReader& t, const CurtainKey& key, double planetRadiusKm, double spacingKm)
{
    // Every span between control points gives at least one point: a quick refusal of huge arrays.
    if (key.pointsLatLonDeg.size() > size_t(kMaxPolylinePoints))
        t.fail("points_lat_lon_deg", std::to_string(key.pointsLatLonDeg.size()) + " control points, more than the " +
                                         std::to_string(kMaxPolylinePoints) + " points a curtain may have");
    size_t points = 0;
    try {
        points = physics::sampleCurtain(key.pointsLatLonDeg, planetRadiusKm, spacingKm).points.size();
    } catch (const std::invalid_argument& e) {
        t.fail("points_lat_lon_deg", std::string(e.what()).substr(std::string("sampleCurtain: ").size()));
    }
    if (points > size_t(kMaxPolylinePoints))
        t.fail("points_lat_lon_deg", "the curtain sampled every aurora.polyline_spacing_km has " +
                                         std::to_string(points) + " points, more than the " +
                                         std::to_string(kMaxPolylinePoints) + " a curtain may have");
}

// A curtain is either one state (its own keys) or a list of [[aurora.curtain.key]] tables, each
// with time_s; a key leaves out what does not change from the key before it.
Curtain readCurtain(const config::TableReader& t, double planetRadiusKm, double spacingKm)
{
    Curtain c;
    c.thicknessKm = t.number("thickness_km", 0.01, 1000, c.thicknessKm);
    c.driftKmPerS = t.number("drift_km_per_s", -1e4, 1e4, c.driftKmPerS);
    c.pulsationPeriodS = t.number("pulsation_period_s", 0, 1e6, c.pulsationPeriodS);
    c.pulsationDepth = t.number("pulsation_depth", 0, 1, c.pulsationDepth);
    if (!t.has("key")) {
        c.keys.push_back(readCurtainKey(t, CurtainKey{}));
        checkPolylineFits(t, c.keys.back(), planetRadiusKm, spacingKm);
    } else {
        CurtainKey previous;
        for (const config::TableReader& k : t.arrayOfTables("key")) {
            CurtainKey key = readCurtainKey(k, previous);
            key.timeS = k.number("time_s", -1e15, 1e15);
            if (!c.keys.empty() && key.timeS <= c.keys.back().timeS)
                k.fail("time_s", "keys must be in increasing time");
            if (!c.keys.empty() && key.pointsLatLonDeg.size() != c.keys.front().pointsLatLonDeg.size())
                k.fail("points_lat_lon_deg", "every key of a curtain needs the same number of points");
            k.rejectUnknownKeys();
            checkPolylineFits(k, key, planetRadiusKm, spacingKm);
            c.keys.push_back(key);
            previous = key;
        }
        if (c.keys.empty())
            t.fail("key", "needs at least one key");
    }
    t.rejectUnknownKeys();
    return c;
}

class Aurora : public scene::ComponentWith<Settings>, public roles::CurtainsProvider {
public:
    std::vector<std::string> needs() const override { return {roles::kGround}; }
    std::vector<std::string> provides() const override { return {roles::kCurtains}; }
    void read(const config::TableReader& t, scene::Scene& scene, scene::ComponentSettings& settings) const override
    {
        auto& a = dynamic_cast<Settings&>(settings);
        a.spectrum = t.choice("spectrum", {"maxwellian", "monoenergetic"},
                              a.spectrum == physics::Spectrum::Maxwellian ? 0 : 1) == 0
                         ? physics::Spectrum::Maxwellian
                         : physics::Spectrum::Monoenergetic;
        a.bottomKm = t.number("bottom_km", 1.0, 5000.0, a.bottomKm);
        a.topKm = t.number("top_km", 1.0, 5000.0, a.topKm);
        if (a.topKm <= a.bottomKm)
            t.fail("top_km", "must be above aurora.bottom_km");
        if (const auto air = roles::lowerAir(scene); air && a.bottomKm < air->topKm)
            t.fail("bottom_km", "must not be below " + air->topKey + " (the layers are composited in order)");
        a.stepKm = t.number("step_km", 0.05, 100.0, a.stepKm);
        a.resolveKm = t.number("resolve_km", 0.01, 100.0, a.resolveKm);
        a.resolveCells = t.number("resolve_cells", 0.05, 100.0, a.resolveCells);
        a.polylineSpacingKm = t.number("polyline_spacing_km", 0.1, 100.0, a.polylineSpacingKm);
        a.footprintMapSize = t.integer("footprint_map_size", 16, 8192, a.footprintMapSize);
        if (a.footprintMapSize & (a.footprintMapSize - 1))
            t.fail("footprint_map_size", "must be a power of two");
        a.footprintMapBuild = static_cast<MapBuilder>(
            t.choice("footprint_map_build", {"auto", "cpu", "gpu"}, static_cast<int>(a.footprintMapBuild)));
        a.skipEmptySpace = t.choice("skip_empty_space", {"no", "yes"}, a.skipEmptySpace) == 1;
        a.exactSubSteps = t.choice("sub_step_flux", {"midpoint", "exact"}, a.exactSubSteps) == 1;
        a.tableAltitudeStepKm = t.number("table_altitude_step_km", 0.05, 10.0, a.tableAltitudeStepKm);
        a.tableEnergyCount = t.integer("table_energy_count", 2, 4096, a.tableEnergyCount);
        if (t.has("curtain")) {
            a.curtains.clear(); // a derived scene's curtains replace its base's
            for (const config::TableReader& c : t.arrayOfTables("curtain"))
                a.curtains.push_back(readCurtain(c, scene.planetRadiusKm, a.polylineSpacingKm));
        }
        if (a.curtains.size() > size_t(kMaxCurtains))
            t.fail("curtain", "at most " + std::to_string(kMaxCurtains) + " curtains are supported");
    }
    std::vector<std::string> shaderDefines(const scene::Scene& scene) const override
    {
        if (scene.settings<Settings>().exactSubSteps)
            return {"AURORA_EXACT_SUB_STEPS"};
        return {};
    }
    std::vector<std::string> shaderModules() const override
    {
        return {"render/angle.glsl", "components/aurora/deposition_coords.glsl", "components/aurora/curtain_emission.glsl",
                "components/aurora/footprint_map.glsl", "components/aurora/gaussian_column.glsl",
                "components/aurora/flux_column.glsl",
                "components/aurora/curtain_profile.glsl",
                "components/aurora/segment_projection.glsl", "components/aurora/curtain_end.glsl",
                "components/aurora/aurora_curtains.glsl"};
    }
    std::string shaderShadeCall() const override { return "shadeAurora(ray)"; }
    scene::Shell shell() const override { return scene::Shell::EmittingStructures; }
    double reachKm(const scene::Scene& scene) const override { return scene.settings<Settings>().topKm; }
    std::unique_ptr<scene::ComponentRenderer> makeRenderer(const scene::Scene& scene,
                                                           const scene::FindRenderer& find) const override
    {
        // The curtain detail comes from its provider, when the scene lists one.
        const auto* provider = dynamic_cast<const roles::CurtainDetailRenderer*>(find(roles::kCurtainDetail));
        return std::make_unique<Renderer>(scene.settings<Settings>(), scene.planetRadiusKm,
                                          provider ? &provider->shape() : nullptr);
    }
    std::unique_ptr<scene::ReferenceShader> makeReference(const scene::Scene& scene,
                                                          const scene::ReferenceContext& context) const override
    {
        const roles::CurtainDetailProvider* provider = roles::curtainDetailProvider(scene);
        const roles::FluxFrames* frames = roles::referenceFrames(context);
        if ((provider != nullptr) != (frames != nullptr))
            throw std::invalid_argument(
                "the reference needs the detail frames exactly when the scene lists a provider of the curtain detail");
        std::optional<roles::DetailShape> shape;
        double stripWidthKm = 0.0;
        if (provider) {
            shape = provider->referenceShape(scene, *frames);
            stripWidthKm = provider->stripWidthKm(scene);
        }
        if (context.shaderSteps)
            return makeAuroraMarch(scene.settings<Settings>(), scene.planetRadiusKm, context.timeS, frames, shape,
                                   stripWidthKm);
        return std::make_unique<AuroraReference>(scene.settings<Settings>(), scene.planetRadiusKm, context.timeS,
                                                 context.stepKm, frames, shape, stripWidthKm);
    }
    roles::DetailPhase firstCurtainDetailPhase(const scene::Scene& scene, double stripLengthKm) const override
    {
        const std::vector<Curtain>& curtains = scene.settings<Settings>().curtains;
        if (curtains.empty() || curtains.front().keys.empty())
            return [](double) { return 0.0; };
        return [curtain = curtains.front(), stripLengthKm](double timeS) {
            return curtainAt(curtain, timeS, stripLengthKm).detailPhase;
        };
    }
};

} // namespace

const scene::Component& component()
{
    static const Aurora instance;
    return instance;
}

} // namespace aurorawall::components::aurora
