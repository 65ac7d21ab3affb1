// Not a test: the glory's phase table on the CPU (double, 2 threads) against the GPU (float, compute
// shader), in run time and error, for the default table and a smaller one, and the effect on the glory's
// colour (docs/GLORY.md, "The table on the GPU"). Needs an EGL context.
#include "common/constants.h"
#include "components/glory/gpu_table.h"
#include "gl/context.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>

using namespace aurorawall;

namespace {

double secondsOf(const std::function<void()>& work)
{
    const auto start = std::chrono::steady_clock::now();
    work();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

glm::dvec2 chromaticity(const glm::dvec3& xyz) { return glm::dvec2(xyz.x, xyz.y) / (xyz.x + xyz.y + xyz.z); }

void compare(const char* name, const glory::GloryTableSpec& spec, const std::string& shaders)
{
    const auto drops = mie::DropSizeDistribution::gamma(10.0, 0.01);
    glory::PhaseTable cpu, gpu, again;
    const double cpuSeconds = secondsOf([&] { cpu = glory::phaseTable(drops, spec); });
    const double gpuSeconds = secondsOf([&] { gpu = glory::phaseTableOnGpu(drops, spec, shaders); });
    const double gpuAgainSeconds = secondsOf([&] { again = glory::phaseTableOnGpu(drops, spec, shaders); });
    double maxError = 0.0, squares = 0.0;
    size_t worst = 0;
    for (size_t i = 0; i < cpu.values.size(); ++i) {
        const double r = std::abs(gpu.values[i] - cpu.values[i]) / cpu.values[i];
        if (r > maxError) {
            maxError = r;
            worst = i;
        }
        squares += r * r;
    }
    std::printf("%s: %d angles x %d wavelengths, %lld Mie series\n", name, spec.angles.size(), spec.wavelengthCount,
                cpu.mieSeries);
    std::printf("  CPU double, %d threads: %.2f s; GPU float: %.2f s (again %.2f s)\n", spec.threads, cpuSeconds,
                gpuSeconds, gpuAgainSeconds);
    const int angles = spec.angles.size();
    std::printf("  P relative error: max %.3g (at %.2f deg from the antisolar point, %.0f nm, P %.4g), rms %.3g\n",
                maxError, spec.angles.angle(int(worst) % angles) / kDegree,
                cpu.wavelengthsNm[worst / size_t(angles)], cpu.values[worst], std::sqrt(squares / double(cpu.values.size())));

    const glory::LightSource sun;
    const auto colour = [&](const glory::PhaseTable& t) {
        return glory::gloryXyz(glory::smearedByDisc(t, sun.discRadiusRad()), sun);
    };
    const auto cpuXyz = colour(cpu), gpuXyz = colour(gpu);
    double maxLuminance = 0.0, maxChromaticity = 0.0;
    for (size_t a = 0; a < cpuXyz.size(); ++a) {
        maxLuminance = std::max(maxLuminance, std::abs(gpuXyz[a].y - cpuXyz[a].y) / cpuXyz[a].y);
        maxChromaticity =
            std::max(maxChromaticity, glm::length(chromaticity(gpuXyz[a]) - chromaticity(cpuXyz[a])));
    }
    std::printf("  colour (gloryXyz of the Sun's smeared table): max |dY|/Y %.3g, max |d(x,y)| %.3g\n", maxLuminance,
                maxChromaticity);
}

} // namespace

int main(int argc, char** argv)
{
    const std::string shaders = argc > 1 ? argv[1] : std::string(AURORAWALL_SOURCE_DIR) + "/shaders";
    const auto context = gl::createContext(gl::Backend::Egl);
    std::printf("renderer: %s\n", context->rendererName().c_str());
    glory::GloryTableSpec small;
    small.angles.gloryCount = 101;
    small.angles.middleCount = 40;
    small.wavelengthCount = 11;
    small.threads = 2;
    compare("small table", small, shaders);
    glory::GloryTableSpec full;
    full.threads = 2;
    compare("default table", full, shaders);
    return 0;
}
