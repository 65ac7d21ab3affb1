// airglow_cost: error against run time of the airglow column along a ray, on the CPU in float (the
// GPU's precision): the closed form of airglow_layer.glsl against midpoint marches of N steps over
// the same shell parts, each against a fine march in double (0.01 km). The rays: 12 random
// directions and the grazing ones from the ground, 1 m, 50 km, inside the layer, 400 km and
// 36000 km, for the green and the red layer. Not a test (timings); run by launch/accuracy-airglow.
#include "airglow_columns.h"
#include "components/airglow/airglow.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <vector>

using namespace aurorawall;
namespace f32 = aurorawall::airglow_columns::f32;
using components::airglow::Layer;
using components::airglow::LayerProfile;

namespace {

using airglow_columns::marchedColumn;
constexpr double R = airglow_columns::kPlanetRadiusKm;

struct Case {
    LayerProfile p;
    glm::vec3 o, d;
    f32::ShellSegments shell;
    double exact = 0.0;
};

float closedForm(const Case& c)
{
    const glm::vec4 l(c.p.baseKm, c.p.upperScaleHeightKm, c.p.lowerScaleHeightKm, c.p.rayleighPerKm);
    float sum = 0.0f;
    for (const glm::vec2 part : {c.shell.first, c.shell.second})
        if (part.x < part.y)
            sum += f32::airglowColumn(c.o, c.d, part.x, part.y, l, float(R + c.p.baseKm));
    return sum;
}

float march(const Case& c, int steps)
{
    const float base = float(c.p.baseKm), hu = float(c.p.upperScaleHeightKm), hl = float(c.p.lowerScaleHeightKm);
    float sum = 0.0f;
    for (const glm::vec2 part : {c.shell.first, c.shell.second}) {
        if (!(part.x < part.y))
            continue;
        const float h = (part.y - part.x) / float(steps);
        for (int k = 0; k < steps; ++k) {
            const float x = glm::length(c.o + (part.x + (float(k) + 0.5f) * h) * c.d) - float(R) - base;
            sum += h * (x > 0.0f ? std::exp(-x / hu) - std::exp(-x / hl) : 0.0f);
        }
    }
    return float(c.p.rayleighPerKm) * sum;
}

} // namespace

int main()
{
    std::vector<Case> cases;
    std::mt19937 random(7);
    const std::vector<Layer> layers = components::airglow::Settings().layers;
    for (const Layer& layer : {layers[0], layers[2]}) {
        const LayerProfile p = components::airglow::layerProfile(layer);
        for (const airglow_columns::Ray& ray : airglow_columns::layerRays(layer, random)) {
            Case c{p, glm::vec3(ray.o), glm::vec3(ray.d), {}, marchedColumn(p, ray.o, ray.d, 0.01)};
            if (c.exact < 1e-3 * layer.zenithRayleigh)
                continue;
            c.shell = airglow_columns::shellParts(p, ray.o, ray.d);
            cases.push_back(c);
        }
    }
    std::printf("method,max_rel_error,rms_rel_error,ns_per_ray\n");
    auto report = [&](const char* name, const std::function<float(const Case&)>& f) {
        double worst = 0.0, sq = 0.0, sink = 0.0;
        for (const Case& c : cases) {
            const double e = std::abs(f(c) - c.exact) / c.exact;
            worst = std::max(worst, e);
            sq += e * e;
        }
        const int repeats = 200;
        const auto start = std::chrono::steady_clock::now();
        for (int r = 0; r < repeats; ++r)
            for (const Case& c : cases)
                sink += f(c);
        const double ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count() /
                          (double(repeats) * cases.size());
        std::printf("%s,%.3g,%.3g,%.1f%s\n", name, worst, std::sqrt(sq / cases.size()), ns, sink < 0 ? " " : "");
    };
    report("closed-form", closedForm);
    for (int n : {16, 64, 256, 1024}) {
        const std::string name = "march" + std::to_string(n);
        report(name.c_str(), [n](const Case& c) { return march(c, n); });
    }
    std::printf("rays,%zu\n", cases.size());
    return 0;
}
