#include "components/aurora/tools/aurora_accuracy.h"

#include "accuracy/random_views.h"
#include "common/data_dir.h"
#include "gl/context.h"
#include "gl/float_target.h"
#include "gl/full_screen_triangle.h"
#include "components/aurora/aurora.h"
#include "components/registry.h"
#include "components/roles/curtain_detail.h"
#include "components/tools.h"
#include "render/tile_renderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <ostream>

namespace aurorawall::components::aurora::tools {

using AuroraSettings = components::aurora::Settings;
using accuracy::openAccuracyContext;
using accuracy::pixelRadiance;
using accuracy::referencePixels;
using accuracy::relativeError;
using accuracy::RelativeError;
using accuracy::renderView;
using accuracy::SceneAccuracySettings;
using accuracy::SceneView;
using accuracy::sceneView;
using accuracy::TimedRender;

void applyFinestSettings(scene::Scene& s)
{
    s.settings<AuroraSettings>().stepKm = 0.25;
    s.settings<AuroraSettings>().resolveKm = 0.125;
    s.settings<AuroraSettings>().resolveCells = 0.5;
    s.settings<AuroraSettings>().skipEmptySpace = true;
    s.settings<AuroraSettings>().footprintMapSize = 1024;
    s.settings<AuroraSettings>().tableAltitudeStepKm = 0.25;
    s.settings<AuroraSettings>().tableEnergyCount = 128;
    s.settings<AuroraSettings>().polylineSpacingKm = 1.0;
    for (const SweepKnob& knob : componentSweepKnobs(s))
        if (!knob.refinesModel)
            knob.setFinest(s);
}

namespace {

// A scene changed by one knob or feature, with its table label.
struct Variant {
    std::string knob;
    std::string value;
    std::function<void(scene::Scene&)> apply;
    int knobIndex = -1; // the other component's knob (componentSweepKnobs) it sets; -1: the aurora's
};

std::string number(double v)
{
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
}

// The aurora's knobs, then the other components' (their own references), then the polylines'.
std::vector<Variant> knobVariants(const std::vector<SweepKnob>& others)
{
    std::vector<Variant> v;
    v.push_back({"default", "-", [](scene::Scene&) {}});
    for (double step : {0.5, 1.0, 2.0, 4.0, 8.0, 16.0, 32.0})
        v.push_back({"step_km", number(step), [step](scene::Scene& s) { s.settings<AuroraSettings>().stepKm = step; }});
    for (double resolve : {0.25, 0.5, 1.0, 2.0, 100.0})
        v.push_back({"resolve_km", number(resolve), [resolve](scene::Scene& s) { s.settings<AuroraSettings>().resolveKm = resolve; }});
    // resolve_cells acts only with the middle column: its rows take it.
    for (double cells : {0.5, 0.75, 1.0, 1.5, 2.0, 4.0})
        v.push_back({"resolve_cells", number(cells), [cells](scene::Scene& s) {
                         s.settings<AuroraSettings>().resolveCells = cells;
                         s.settings<AuroraSettings>().exactSubSteps = false;
                     }});
    for (bool exact : {false, true})
        v.push_back({"sub_step_flux", exact ? "exact" : "midpoint",
                     [exact](scene::Scene& s) { s.settings<AuroraSettings>().exactSubSteps = exact; }});
    for (bool skip : {true, false})
        v.push_back({"skip_empty_space", skip ? "yes" : "no", [skip](scene::Scene& s) { s.settings<AuroraSettings>().skipEmptySpace = skip; }});
    for (int size : {128, 256, 512, 1024})
        v.push_back({"footprint_map_size", number(size), [size](scene::Scene& s) { s.settings<AuroraSettings>().footprintMapSize = size; }});
    for (double step : {0.25, 0.5, 1.0, 2.0})
        v.push_back({"table_altitude_step_km", number(step),
                     [step](scene::Scene& s) { s.settings<AuroraSettings>().tableAltitudeStepKm = step; }});
    for (int count : {32, 64, 128})
        v.push_back({"table_energy_count", number(count), [count](scene::Scene& s) { s.settings<AuroraSettings>().tableEnergyCount = count; }});
    for (std::size_t k = 0; k < others.size(); ++k)
        for (const auto& [label, set] : others[k].values)
            v.push_back({others[k].name, label, set, static_cast<int>(k)});
    for (double spacing : {1.0, 2.0, 4.0})
        v.push_back({"polyline_spacing_km", number(spacing),
                     [spacing](scene::Scene& s) { s.settings<AuroraSettings>().polylineSpacingKm = spacing; }});
    return v;
}

// Lawlor & Genetti's table 2: the features they timed, each toggled alone, and their published change.
struct Feature {
    Variant variant;
    const char* paper; // the paper's change in frame time, or "-"
};

std::vector<Feature> auroraFeatures()
{
    return {
        {{"default", "-", [](scene::Scene&) {}}, "-"},
        {{"no distance field (skip_empty_space = no)", "", [](scene::Scene& s) { s.settings<AuroraSettings>().skipEmptySpace = false; }}, "+350%"},
        {{"aurora layer 100 km thicker", "", [](scene::Scene& s) { s.settings<AuroraSettings>().topKm += 100.0; }}, "+32%"},
        {{"half the step (paper: 1 km instead of 2)", "", [](scene::Scene& s) { s.settings<AuroraSettings>().stepKm *= 0.5; }}, "+60%"},
        {{"double the step (paper: 4 km instead of 2)", "", [](scene::Scene& s) { s.settings<AuroraSettings>().stepKm *= 2.0; }}, "-33%"},
        {{"deposition table at half resolution", "", [](scene::Scene& s) {
              s.settings<AuroraSettings>().tableAltitudeStepKm *= 2.0;
              s.settings<AuroraSettings>().tableEnergyCount /= 2;
          }}, "-"},
        {{"deposition table at double resolution", "", [](scene::Scene& s) {
              s.settings<AuroraSettings>().tableAltitudeStepKm *= 0.5;
              s.settings<AuroraSettings>().tableEnergyCount *= 2;
          }}, "-"},
    };
}

// Whether the scene lists a component, or a provider of a role, for each of `c`'s needs.
bool needsMet(const scene::Scene& s, const scene::Component& c)
{
    for (const std::string& needed : c.needs())
        if (!s.has(needed) && !s.provider(needed))
            return false;
    return true;
}

// The scene without `component`, and without what then misses something it needs (the scattering
// sky without the air it scatters in).
scene::Scene without(scene::Scene s, const std::string& component)
{
    s.remove(component);
    for (;;) {
        const std::vector<const scene::Component*>& listed = s.components();
        const auto unmet = std::find_if(listed.begin(), listed.end(), [&](const scene::Component* c) { return !needsMet(s, *c); });
        if (unmet == listed.end())
            return s;
        s.remove((*unmet)->name());
    }
}

// The aurora's features, then each other listed component left out ("no NAME", with what needs it)
// that the aurora can do without, in registry order.
std::vector<Feature> featureVariants(const scene::Scene& base)
{
    std::vector<Feature> features = auroraFeatures();
    for (const scene::Component* c : base.components()) {
        std::string name = c->name();
        if (!without(base, name).has(AuroraSettings::kComponent))
            continue;
        std::replace(name.begin(), name.end(), '_', ' ');
        features.push_back({{"no " + name, "", [component = c->name()](scene::Scene& s) { s = without(s, component); }}, "-"});
    }
    return features;
}

std::vector<glm::dvec3> imagePixels(const io::Image& image, const std::vector<glm::ivec2>& pixels)
{
    std::vector<glm::dvec3> values;
    for (const glm::ivec2& p : pixels)
        values.push_back(pixelRadiance(image, p.x, p.y));
    return values;
}

std::vector<glm::ivec2> allPixels(glm::ivec2 size)
{
    std::vector<glm::ivec2> pixels;
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x)
            pixels.emplace_back(x, y);
    return pixels;
}

// `count` pixels evenly spaced (in row-major order) among `lit`.
std::vector<glm::ivec2> evenlySpaced(const std::vector<glm::ivec2>& lit, int count)
{
    std::vector<glm::ivec2> chosen;
    for (int i = 0; i < count && !lit.empty(); ++i)
        chosen.push_back(lit[(size_t(i) * lit.size()) / size_t(count)]);
    chosen.erase(std::unique(chosen.begin(), chosen.end()), chosen.end());
    return chosen;
}

// `count` pixels evenly spaced among those of the GPU reference at or above the floor, so that the CPU
// reference is spent where the error is measured.
std::vector<glm::ivec2> samplePixels(const io::Image& reference, double floor, int count)
{
    std::vector<glm::ivec2> lit;
    for (const glm::ivec2& p : allPixels({reference.width, reference.height}))
        if (glm::length(pixelRadiance(reference, p.x, p.y)) >= floor)
            lit.push_back(p);
    return evenlySpaced(lit, count);
}

// The pixels at or above the floor where the aurora gives at least half the radiance: `image` less
// `withoutAurora` (the same view without the aurora component).
std::vector<glm::ivec2> auroraPixels(const io::Image& image, const io::Image& withoutAurora, double floor)
{
    std::vector<glm::ivec2> pixels;
    for (const glm::ivec2& p : allPixels({image.width, image.height})) {
        const glm::dvec3 all = pixelRadiance(image, p.x, p.y);
        if (glm::length(all) >= floor && glm::length(all - pixelRadiance(withoutAurora, p.x, p.y)) >= 0.5 * glm::length(all))
            pixels.push_back(p);
    }
    return pixels;
}

double secondsSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The two references of a knob's rows: the GPU render at the finest settings and the CPU reference
// at the sampled pixels.
struct References {
    scene::Scene scene;
    TimedRender gpu;
    std::vector<glm::dvec3> cpu;
    double cpuSeconds = 0.0;
};

void computeReferences(References& r, const SceneView& view, const std::vector<glm::ivec2>& pixels, const SceneAccuracySettings& settings)
{
    const auto start = std::chrono::steady_clock::now();
    const std::shared_ptr<const roles::FluxFrames> frames = components::roles::curtainDetailFrames(r.scene);
    render::ReferenceSettings reference;
    reference.stepKm = settings.referenceStepKm;
    const render::ReferenceModel model(r.scene, view.frame.timeS, components::roles::curtainDetailData(frames.get()),
                                       reference);
    r.cpu = referencePixels(model, view, pixels, settings.threads);
    r.cpuSeconds = secondsSince(start);
}

// The references of another component's knob (SweepKnob::refinesModel): both made again at its finest
// on top of the common GPU reference's settings, or the GPU's alone from the scene's defaults.
References knobReferences(const SweepKnob& knob, const scene::Scene& base, const References& common, const SceneView& view,
                          const std::vector<glm::ivec2>& sampled, const std::string& shaderDir,
                          const SceneAccuracySettings& settings)
{
    References r{base, {}, common.cpu, common.cpuSeconds};
    if (knob.refinesModel)
        applyFinestSettings(r.scene);
    knob.setFinest(r.scene);
    r.gpu = renderView(r.scene, view, shaderDir, 0);
    if (knob.refinesModel)
        computeReferences(r, view, sampled, settings);
    return r;
}

// The table's head: the noise floor and both references, and what the other components' knobs compare with.
void printReferences(const scene::Scene& base, const References& common, const std::vector<glm::ivec2>& sampled,
                     const std::vector<SweepKnob>& knobs, const SceneAccuracySettings& settings, std::ostream& out)
{
    const double floor = 1.0 / (255.0 * base.exposure);
    std::string gpuExtras, cpuExtras, notes;
    for (const SweepKnob& k : knobs) {
        gpuExtras += k.gpuReference;
        cpuExtras += k.cpuReference;
        notes += "; for " + k.name + (k.refinesModel ? " both references use " : " the GPU reference is the scene's defaults with ") +
                 k.finest;
    }
    const RelativeError gpuVsCpu = relativeError(imagePixels(common.gpu.image, sampled), common.cpu, floor);
    char line[768];
    std::snprintf(line, sizeof line,
                  "noise floor: |linear RGB| >= %.3g cd/m^2 (one 8-bit step of the linear preview at exposure %g)\n"
                  "GPU reference: step 0.25 km, skipping, footprint map 1024, tables 0.25 km x 128 energies, "
                  "polylines 1 km%s; its error against the CPU reference at the %zu sampled pixels: rms %.3g, max %.3g\n"
                  "CPU reference: double, midpoint rule %.3g km where a curtain is in reach%s; %.1f s on %d threads",
                  floor, base.exposure, gpuExtras.c_str(), sampled.size(), gpuVsCpu.rms, gpuVsCpu.max,
                  settings.referenceStepKm, cpuExtras.c_str(), common.cpuSeconds, settings.threads);
    out << line << notes << "\n";
}

void printKnobTable(const scene::Scene& base, const SceneView& view, const std::string& shaderDir,
                    const SceneAccuracySettings& settings, std::ostream& out)
{
    const double floor = 1.0 / (255.0 * base.exposure);
    const std::vector<glm::ivec2> all = allPixels(settings.sizePx);
    const std::vector<SweepKnob> knobs = componentSweepKnobs(base);

    References common{base, {}, {}, 0.0};
    applyFinestSettings(common.scene);
    common.gpu = renderView(common.scene, view, shaderDir, 0);
    const std::vector<glm::ivec2> sampled = samplePixels(common.gpu.image, floor, settings.pixels);
    if (sampled.empty()) {
        char message[160];
        std::snprintf(message, sizeof message,
                      "no pixel of this view is above the noise floor (%.3g cd/m^2): nothing to compare with the CPU "
                      "reference",
                      floor);
        throw std::runtime_error(message);
    }
    computeReferences(common, view, sampled, settings);
    std::vector<References> own;
    for (const SweepKnob& knob : knobs)
        own.push_back(knobReferences(knob, base, common, view, sampled, shaderDir, settings));

    printReferences(base, common, sampled, knobs, settings, out);
    out << "knob                     value     rms_rel_gpu max_rel_gpu rms_rel_cpu max_rel_cpu ms_per_frame\n";
    for (const Variant& variant : knobVariants(knobs)) {
        const References& ref = variant.knobIndex < 0 ? common : own[variant.knobIndex];
        scene::Scene s = base;
        variant.apply(s);
        const TimedRender render = renderView(s, view, shaderDir, settings.runs);
        const RelativeError gpu =
            relativeError(imagePixels(render.image, all), imagePixels(ref.gpu.image, all), floor);
        const RelativeError cpu = relativeError(imagePixels(render.image, sampled), ref.cpu, floor);
        char line[256];
        std::snprintf(line, sizeof line, "%-24s %-9s %-11.3g %-11.3g %-11.3g %-11.3g %.1f\n", variant.knob.c_str(),
                      variant.value.c_str(), gpu.rms, gpu.max, cpu.rms, cpu.max, render.msPerFrame);
        out << line << std::flush;
    }
}

void printFeatureCosts(const scene::Scene& base, const SceneView& view, const std::string& shaderDir,
                       const SceneAccuracySettings& settings, std::ostream& out)
{
    out << "feature                                   ms_per_frame change   paper\n";
    double defaultMs = 0.0;
    for (const Feature& feature : featureVariants(base)) {
        scene::Scene s = base;
        feature.variant.apply(s);
        const double ms = renderView(s, view, shaderDir, settings.runs).msPerFrame;
        if (feature.variant.knob == "default")
            defaultMs = ms;
        char line[256];
        std::snprintf(line, sizeof line, "%-41s %-12.1f %+6.0f%%  %s\n", feature.variant.knob.c_str(), ms,
                      100.0 * (ms / defaultMs - 1.0), feature.paper);
        out << line << std::flush;
    }
}


// How many pixels where the aurora gives at least half the radiance (auroraPixels) a view needs to be
// measured; a drawn view with fewer (looking past the layer, at the ground or at a sky it does not
// light) is drawn again, up to kViewDrawsPerView times.
constexpr size_t kViewAuroraPixels = 16;
constexpr int kViewDrawsPerView = 200;

std::string vectorText(glm::dvec3 v)
{
    char text[96];
    std::snprintf(text, sizeof text, "%.6f %.6f %.6f", v.x, v.y, v.z);
    return text;
}

// One line of the views' CSV.
void printViewError(const scene::Scene& scene, int index, const ViewError& e, std::ostream& out)
{
    char line[512];
    std::snprintf(line, sizeof line, "%d,%s,%.3f,%.3f,%s,%s,%s,%zu,", index, accuracy::viewKindName(e.kind),
                  scene::altitudeKm(e.frame.cameraPositionKm, scene.planetRadiusKm), e.frame.timeS,
                  vectorText(e.frame.cameraPositionKm).c_str(), vectorText(-e.frame.cameraBack).c_str(),
                  vectorText(e.frame.cameraUp).c_str(), e.auroraPixels);
    out << line;
    if (e.auroraPixels == 0) {
        out << "-,-,-,-\n" << std::flush;
        return;
    }
    std::snprintf(line, sizeof line, "%.3g,%.3g,%.3g,%.3g\n", e.gpu.rms, e.gpu.max, e.cpu.rms, e.cpu.max);
    out << line << std::flush;
}

// The views' table (measureViews) as CSV, then how many views stay within 1% RMS of the CPU reference.
void printViewErrors(const scene::Scene& scene, const SceneView& start, const std::string& shaderDir,
                     const SceneAccuracySettings& settings, std::ostream& out)
{
    out << "views drawn at random from seed " << settings.seed << " (accuracy/random_views.h); the scene's settings "
        << "over the pixels where the aurora gives at least half the radiance, against the GPU reference (every such "
        << "pixel) and the CPU reference (" << settings.pixels << " of them)\n"
        << "view,kind,altitude_km,time_s,position_km,forward,up,aurora_pixels,rms_rel_gpu,max_rel_gpu,rms_rel_cpu,"
           "max_rel_cpu\n";
    int index = 0, measured = 0, withinOnePercent = 0;
    RelativeError worst;
    measureViews(scene, start, shaderDir, settings, [&](const ViewError& e) {
        printViewError(scene, index++, e, out);
        if (e.auroraPixels == 0)
            return;
        ++measured;
        withinOnePercent += e.cpu.rms <= 0.01;
        worst.rms = std::max(worst.rms, e.cpu.rms);
        worst.max = std::max(worst.max, e.cpu.max);
    });
    char summary[256];
    std::snprintf(summary, sizeof summary,
                  "within 1%% RMS of the CPU reference: %d of %d measured views (of %d drawn); largest rms %.3g, "
                  "largest max %.3g\n",
                  withinOnePercent, measured, settings.views, worst.rms, worst.max);
    out << summary;
}

} // namespace

void measureViews(const scene::Scene& scene, const SceneView& start, const std::string& shaderDir,
                  const SceneAccuracySettings& settings, const std::function<void(const ViewError&)>& measured)
{
    const double floor = 1.0 / (255.0 * scene.exposure);
    scene::Scene finest = scene;
    applyFinestSettings(finest);
    const scene::Scene noAurora = without(scene, AuroraSettings::kComponent);
    accuracy::RandomViews draws(settings.seed, {scene.planetRadiusKm});
    for (int k = 0; k < settings.views; ++k) {
        ViewError e;
        e.kind = accuracy::ViewKind(k % accuracy::kViewKinds);
        SceneView view;
        io::Image image;
        std::vector<glm::ivec2> lit;
        for (int draw = 0; draw < kViewDrawsPerView && lit.size() < kViewAuroraPixels; ++draw) {
            view = draws.draw(start, e.kind);
            image = renderView(scene, view, shaderDir, 0).image;
            lit = auroraPixels(image, renderView(noAurora, view, shaderDir, 0).image, floor);
        }
        e.frame = view.frame;
        if (lit.size() >= kViewAuroraPixels) {
            References ref{finest, renderView(finest, view, shaderDir, 0), {}, 0.0};
            const std::vector<glm::ivec2> sampled = evenlySpaced(lit, settings.pixels);
            computeReferences(ref, view, sampled, settings);
            e.auroraPixels = lit.size();
            e.gpu = relativeError(imagePixels(image, lit), imagePixels(ref.gpu.image, lit), floor);
            e.cpu = relativeError(imagePixels(image, sampled), ref.cpu, floor);
        }
        measured(e);
    }
}

namespace {

// The work counts of one frame of the view (render/work_counts.h, the compute march counting): per
// quantity the mean per pixel and the mean over 8x4-pixel blocks of the block's largest count.
void printWorkStats(const scene::Scene& scene, const SceneView& view, const std::string& shaderDir, std::ostream& out)
{
    render::TileRenderer renderer(scene, shaderDir, render::MarchStage::Compute, render::CountWork::Yes);
    const glm::ivec2 size(view.wall.screens.front().widthPx, view.wall.screens.front().heightPx);
    gl::FloatTarget target(size.x, size.y);
    gl::FullScreenTriangle triangle;
    renderer.setFrame(view.frame);
    renderer.renderTile(view.rays, target, triangle);
    const render::WorkSummary work = render::summarizeWork(renderer.workCounts(size), size);
    out << "work of the march per pixel (mean over the " << size.x * size.y
        << " pixels) and per 8x4-pixel block (mean over the blocks of each block's largest)\n"
        << "quantity,mean_per_pixel,mean_block_max\n";
    for (int q = 0; q < render::kWorkQuantities; ++q)
        out << render::kWorkQuantityNames[q] << "," << work.meanPerPixel[q] << "," << work.meanBlockMax[q] << "\n";
}

} // namespace

void runSceneAccuracy(const SceneAccuracySettings& settings, std::ostream& out)
{
    const std::string dataDir = common::dataDirectory();
    const std::string wallFile = settings.wallFile.empty() ? dataDir + "/config/walls/single.toml" : settings.wallFile;
    scene::Scene scene = components::loadScene(settings.sceneFile);
    // Every table of --scene measures the aurora's march.
    if (!scene.has("aurora"))
        throw std::runtime_error(settings.sceneFile + ": the scene does not list aurora");
    if (!settings.featureCosts && !settings.workStats)
        scene = scene::withoutUnmodelled(scene);
    const SceneView view = sceneView(scene, wallFile, settings.sizePx, settings.frame);
    const auto context = openAccuracyContext(out, settings.sizePx);
    out << "scene: " << settings.sceneFile << " (components:";
    for (const scene::Component* c : scene.components())
        out << " " << c->name();
    out << "), frame " << settings.frame << " at t = " << view.frame.timeS << " s, " << settings.sizePx.x << "x" << settings.sizePx.y
        << " px, field of view of " << wallFile << "; ms per frame: median of " << settings.runs
        << " frames (setFrame + renderTile + glFinish, CPU clock) after one warm-up\n";
    if (settings.featureCosts)
        printFeatureCosts(scene, view, dataDir + "/shaders", settings, out);
    else if (settings.workStats)
        printWorkStats(scene, view, dataDir + "/shaders", out);
    else if (settings.views > 0)
        printViewErrors(scene, view, dataDir + "/shaders", settings, out);
    else
        printKnobTable(scene, view, dataDir + "/shaders", settings, out);
}

} // namespace aurorawall::components::aurora::tools
