// Not a test: the cost of GpuPic's step phase by phase (docs/PLASMA.md, "On the GPU"). A thermal
// plasma (random start, Δx = λ_D) on 64³ cells with 2 particles per cell (524,288 particles), and on
// 256² cells with 1 per cell; prints ns per particle per step for the push and the deposit and ms
// per field solve, the median over the timed steps after two untimed ones.
#include "components/plasma/gpu/gpu_pic.h"
#include "components/plasma/simulation/particle_loading.h"
#include "components/plasma/simulation/plasma_parameters.h"
#include "gl/context.h"

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

using namespace aurorawall;
using namespace aurorawall::plasma;

namespace {

double median(std::vector<double> values)
{
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

void measure(int dimension, int cells, int perCell, int steps)
{
    const double density = 1e12, thermalSpeed = 4.19e5;
    const double lambdaD = debyeLength(thermalSpeed, density);
    const PeriodicGrid grid(dimension, {cells, cells, cells}, {lambdaD, lambdaD, lambdaD});
    const int count = perCell * int(grid.nodeCount());
    GpuPic pic(grid, randomStart(grid, count, density, thermalSpeed, 1), glm::dvec3(0.0, 0.0, 5e-5),
               0.2 / plasmaFrequency(density), std::string(AURORAWALL_SOURCE_DIR) + "/shaders");
    pic.step();
    pic.step();
    std::vector<double> push, deposit, solve, field;
    for (int n = 0; n < steps; ++n) {
        const StepTimes t = pic.timedStep();
        push.push_back(t.pushMs);
        deposit.push_back(t.depositMs);
        solve.push_back(t.solveMs);
        field.push_back(t.fieldMs);
    }
    const double ns = 1e6 / count;
    std::printf("%dD %d^%d cells, %d particles: push (gather + Boris) %.1f ns/particle, deposit %.1f ns/particle, "
                "solve (read-back + FFT + upload) %.2f ms, field %.2f ms, step %.1f ms\n",
                dimension, cells, dimension, count, median(push) * ns, median(deposit) * ns, median(solve),
                median(field), median(push) + median(deposit) + median(solve) + median(field));
}

} // namespace

int main()
{
    const auto context = gl::createContext(gl::Backend::Egl);
    measure(3, 64, 2, 5);
    measure(2, 256, 1, 10);
    return 0;
}
