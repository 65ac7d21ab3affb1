#include "components/glory/tools/glory_accuracy.h"

#include "common/data_dir.h"
#include "common/formatted.h"
#include "components/glory/glory.h"
#include "components/registry.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <ostream>
#include <stdexcept>

namespace aurorawall::components::glory::tools {

namespace {

using GlorySettings = glory::Settings;
using namespace accuracy;

double secondsSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The colour per angle of a table built from `settings` (uncached, timed).
struct ColourTable {
    optics::AngleGrid grid;
    std::vector<glm::dvec3> rgb;
    double seconds = 0.0;
    long long mieSeries = 0;

    glm::dvec3 at(double gamma) const { return optics::colourAtAngle(grid, rgb, gamma); }
};

ColourTable colourTable(const GlorySettings& s)
{
    const auto start = std::chrono::steady_clock::now();
    const optics::PhaseTable table =
        optics::smearedByDisc(optics::phaseTable(s.drops(), s.table), s.light.discRadiusRad());
    ColourTable c{table.angles, optics::gloryLinearSrgb(optics::gloryXyz(table, s.light)), 0.0, table.mieSeries};
    c.seconds = secondsSince(start);
    return c;
}

struct TableVariant {
    std::string knob, value;
    std::function<void(optics::GloryTableSpec&)> apply;
};

std::vector<TableVariant> tableVariants(const optics::GloryTableSpec& base)
{
    std::vector<TableVariant> v;
    v.push_back({"default", "-", [](optics::GloryTableSpec&) {}});
    for (int factor : {4, 2})
        v.push_back({"glory_angles", std::to_string((base.angles.gloryCount - 1) / factor + 1),
                     [factor](optics::GloryTableSpec& t) { t.angles.gloryCount = (t.angles.gloryCount - 1) / factor + 1; }});
    for (int count : {11, 21, 81})
        v.push_back({"table_wavelengths", std::to_string(count), [count](optics::GloryTableSpec& t) { t.wavelengthCount = count; }});
    for (double step : {0.4, 0.2, 0.05}) {
        char text[16];
        std::snprintf(text, sizeof text, "%g", step);
        v.push_back({"size_parameter_step", text, [step](optics::GloryTableSpec& t) { t.sizeParameterStep = step; }});
    }
    return v;
}

// Relative colour error |c − r| / |r| over the reference's angles in [0, span] (the glory) and over
// all its angles.
struct ColourError {
    double gloryRms = 0.0, gloryMax = 0.0, allMax = 0.0;
};

ColourError colourError(const ColourTable& table, const ColourTable& reference)
{
    ColourError e;
    size_t count = 0;
    for (int i = 0; i < reference.grid.size(); ++i) {
        const double gamma = reference.grid.angle(i);
        const glm::dvec3 r = reference.rgb[size_t(i)];
        const double error = glm::length(table.at(gamma) - r) / std::max(glm::length(r), 1e-300);
        e.allMax = std::max(e.allMax, error);
        if (gamma <= reference.grid.glorySpanRad) {
            e.gloryRms += error * error;
            e.gloryMax = std::max(e.gloryMax, error);
            ++count;
        }
    }
    e.gloryRms = std::sqrt(e.gloryRms / double(std::max<size_t>(count, 1)));
    return e;
}

void printTableKnobs(const GlorySettings& base, std::ostream& out)
{
    GlorySettings fine = base;
    fine.table = glory::referenceTableSpec(base.table);
    // The reference's table through the cache: the renders below use the same one.
    const glory::GloryTables tables = glory::gloryTables(fine);
    const ColourTable reference{tables.phase.angles, optics::gloryLinearSrgb(optics::gloryXyz(tables.phase, fine.light)),
                                tables.seconds, tables.phase.mieSeries};
    out << common::formatted(
                  "table resolution (reference: %d + %d + %d angles, %d wavelengths, size-parameter step %g; %.1f s, %s, "
                  "%lld Mie series)\n",
                  fine.table.angles.gloryCount, fine.table.angles.middleCount, fine.table.angles.forwardCount,
                  fine.table.wavelengthCount,
                  fine.table.sizeParameterStep, reference.seconds, tables.outcome.c_str(), reference.mieSeries);
    char line[256];
    out << "knob                 value   rms_rel_glory max_rel_glory max_rel_all build_s mie_series\n";
    for (const TableVariant& variant : tableVariants(base.table)) {
        GlorySettings s = base;
        variant.apply(s.table);
        const ColourTable table = colourTable(s);
        const ColourError e = colourError(table, reference);
        std::snprintf(line, sizeof line, "%-20s %-7s %-13.3g %-13.3g %-11.3g %-7.2f %lld\n", variant.knob.c_str(),
                      variant.value.c_str(), e.gloryRms, e.gloryMax, e.allMax, table.seconds, table.mieSeries);
        out << line << std::flush;
    }
}

std::vector<glm::dvec3> allPixels(const io::Image& image)
{
    std::vector<glm::dvec3> values;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            values.push_back(pixelRadiance(image, x, y));
    return values;
}

void printWavelengthSampling(const scene::Scene& base, const SceneView& view, const std::string& shaderDir,
                             const SceneAccuracySettings& settings, std::ostream& out)
{
    scene::Scene finest = base;
    auto& fine = finest.settings<GlorySettings>();
    fine.table = glory::referenceTableSpec(fine.table);
    const std::vector<glm::dvec3> reference = allPixels(renderView(finest, view, shaderDir, 1).image);
    const double floor = 1.0 / (255.0 * base.exposure);
    out << "colour per pixel (error against the GPU render with the reference's table and colour table, every pixel)\n";
    out << "sampling       wavelengths rms_rel  max_rel  ms_per_frame\n";
    struct Variant {
        glory::WavelengthSampling sampling;
        int count;
    };
    std::vector<Variant> variants = {{glory::WavelengthSampling::ColourTable, 0}};
    for (auto sampling : {glory::WavelengthSampling::Uniform, glory::WavelengthSampling::Importance})
        for (int count : {1, 2, 4, 8, 16, 32})
            variants.push_back({sampling, count});
    for (const Variant& v : variants) {
        scene::Scene s = base;
        auto& glory = s.settings<GlorySettings>();
        glory.sampling = v.sampling;
        if (v.count > 0)
            glory.wavelengthsPerPixel = v.count;
        const TimedRender render = renderView(s, view, shaderDir, settings.runs);
        const RelativeError e = relativeError(allPixels(render.image), reference, floor);
        const char* name = v.sampling == glory::WavelengthSampling::ColourTable ? "colour-table"
                           : v.sampling == glory::WavelengthSampling::Uniform   ? "uniform"
                                                                                            : "importance";
        char line[160];
        std::snprintf(line, sizeof line, "%-14s %-11s %-8.3g %-8.3g %.1f\n", name,
                      v.count > 0 ? std::to_string(v.count).c_str() : "all", e.rms, e.max, render.msPerFrame);
        out << line << std::flush;
    }
}

} // namespace

void runGloryAccuracy(const accuracy::SceneAccuracySettings& settings, std::ostream& out)
{
    const std::string dataDir = common::dataDirectory();
    const std::string wallFile = settings.wallFile.empty() ? dataDir + "/config/walls/single.toml" : settings.wallFile;
    const scene::Scene scene = components::loadScene(settings.sceneFile);
    if (!scene.has("glory"))
        throw std::runtime_error(settings.sceneFile + ": the scene does not list glory");
    const GlorySettings& glory = scene.settings<GlorySettings>();
    out << "scene: " << settings.sceneFile << ", drops " << glory.effectiveRadiusUm << " um, effective variance "
        << glory.effectiveVariance << "\n";
    printTableKnobs(glory, out);
    const SceneView view = sceneView(scene, wallFile, settings.sizePx, settings.frame);
    const auto context = openAccuracyContext(out, settings.sizePx);
    out << settings.sizePx.x << "x" << settings.sizePx.y << " px, field of view of " << wallFile << "; ms per frame: median of "
        << settings.runs << " frames after one warm-up\n";
    printWavelengthSampling(scene, view, dataDir + "/shaders", settings, out);
}

} // namespace aurorawall::components::glory::tools
