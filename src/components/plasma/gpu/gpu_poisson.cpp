#include "physics/constants.h"
#include "components/plasma/gpu/gpu_poisson.h"

#include "components/plasma/gpu/gpu_limits.h"
#include "components/plasma/simulation/plasma_parameters.h"
#include "gl/functions.h"
#include "gl/shader_program.h"

#include <array>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <utility>

namespace aurorawall::components::plasma::gpu {
namespace {

using namespace gl; // the GL function pointers (gl/functions.h)

constexpr int kWorkGroupSize = 64; // local_size_x of poisson_sweep.comp
enum Binding { QuantaBinding = 2, PotentialBinding = 3, SourceBinding = 5, PotentialOutBinding = 6, CoarseBinding = 7 };
enum Pass { SourcePass = 1, JacobiPass = 2, SorPass = 3, ResidualPass = 4, RestrictionPass = 5, ProlongationPass = 6 };

GLuint groupsFor(const simulation::PeriodicGrid& grid) { return GLuint((grid.nodeCount() + kWorkGroupSize - 1) / kWorkGroupSize); }

// The next coarser grid (half the cells, twice the spacing), or none when some axis of the
// dimension has an odd count or at most 4 cells.
bool coarsens(const simulation::PeriodicGrid& grid)
{
    for (int d = 0; d < grid.dimension; ++d)
        if (grid.cells[d] % 2 != 0 || grid.cells[d] <= 4)
            return false;
    return true;
}

simulation::PeriodicGrid coarser(const simulation::PeriodicGrid& grid)
{
    std::array<int, 3> cells = grid.cells;
    std::array<double, 3> spacing = grid.spacing;
    for (int d = 0; d < grid.dimension; ++d) {
        cells[d] /= 2;
        spacing[d] *= 2.0;
    }
    return simulation::PeriodicGrid(grid.dimension, cells, spacing);
}

GLuint floatBuffer(std::size_t count)
{
    GLuint buffer = 0;
    const std::vector<float> zeros(count, 0.0f);
    glCreateBuffers(1, &buffer);
    glNamedBufferStorage(buffer, GLsizeiptr(count * sizeof(float)), zeros.data(), GL_DYNAMIC_STORAGE_BIT);
    return buffer;
}

} // namespace

double jacobiFactor(const simulation::PeriodicGrid& grid, int kx, int ky, int kz)
{
    const int k[3] = {kx, ky, kz};
    double weighted = 0.0, total = 0.0;
    for (int d = 0; d < grid.dimension; ++d) {
        const double inverseSquare = 1.0 / (grid.spacing[d] * grid.spacing[d]);
        weighted += std::cos(2.0 * physics::kPi * k[d] / grid.cells[d]) * inverseSquare;
        total += inverseSquare;
    }
    return weighted / total;
}

double sorOverRelaxation(const simulation::PeriodicGrid& grid)
{
    // The longest non-constant waves are one cycle along one axis; μ₁ is the largest of them.
    double largest = -1.0;
    for (int d = 0; d < grid.dimension; ++d)
        if (grid.cells[d] > 1)
            largest = std::max(largest, jacobiFactor(grid, d == 0, d == 1, d == 2));
    return 2.0 / (1.0 + std::sqrt(1.0 - largest * largest));
}

struct GpuPoisson::Programs {
    gl::Program source, sweep, residual, restriction, prolongation;
};

GpuPoisson::GpuPoisson(const simulation::PeriodicGrid& grid, GpuPoissonMethod method, const std::string& shaderDir)
    : grid_(grid), method_(method), overRelaxation_(sorOverRelaxation(grid))
{
    if (method != GpuPoissonMethod::Jacobi)
        for (int d = 0; d < grid.dimension; ++d)
            if (grid.cells[d] % 2 != 0)
                throw std::invalid_argument("red-black SOR and multigrid need an even number of cells along each axis (got " +
                                            std::to_string(grid.cells[d]) + ")");
    requireFitsGpu(currentGpuLimits(), grid.nodeCount(), "grid nodes", kWorkGroupSize, sizeof(float));
    const gl::ShaderModule module = gl::readShaderModule(shaderDir + "/components/plasma/poisson_sweep.comp");
    const auto program = [&](int pass) {
        return gl::Program::compute(
            {{"PLASMA_DIMENSION " + std::to_string(grid.dimension), "POISSON_PASS " + std::to_string(pass)}, {module}});
    };
    const bool multigrid = method == GpuPoissonMethod::Multigrid;
    programs_ = std::make_unique<Programs>(
        Programs{program(SourcePass), program(method == GpuPoissonMethod::Jacobi ? JacobiPass : SorPass),
                 program(ResidualPass), program(RestrictionPass), program(ProlongationPass)});
    for (gl::Program* p : {&programs_->source, &programs_->sweep}) {
        p->set("uCells", glm::vec3(grid.cells[0], grid.cells[1], grid.cells[2]));
        p->set("uSpacing", glm::vec3(grid.spacing[0], grid.spacing[1], grid.spacing[2]));
        p->set("uCount", int(grid.nodeCount()));
    }
    if (method == GpuPoissonMethod::RedBlackSor)
        programs_->sweep.set("uOverRelaxation", float(overRelaxation_));
    for (unsigned& buffer : buffers_)
        buffer = floatBuffer(grid.nodeCount());
    levels_.push_back({grid, buffers_[0], buffers_[1], buffers_[2]});
    while (multigrid && coarsens(levels_.back().grid)) {
        const simulation::PeriodicGrid coarse = coarser(levels_.back().grid);
        levels_.push_back({coarse, floatBuffer(coarse.nodeCount()), floatBuffer(coarse.nodeCount()),
                           floatBuffer(coarse.nodeCount())});
    }
}

GpuPoisson::~GpuPoisson()
{
    glDeleteBuffers(3, buffers_);
    for (std::size_t l = 1; l < levels_.size(); ++l) {
        const GLuint level[3] = {levels_[l].potential, levels_[l].source, levels_[l].residual};
        glDeleteBuffers(3, level);
    }
}

void GpuPoisson::setGrid(int level) const
{
    const simulation::PeriodicGrid& g = levels_[level].grid;
    for (gl::Program* p : {&programs_->sweep, &programs_->residual, &programs_->restriction, &programs_->prolongation}) {
        p->set("uCells", glm::vec3(g.cells[0], g.cells[1], g.cells[2]));
        p->set("uSpacing", glm::vec3(g.spacing[0], g.spacing[1], g.spacing[2]));
        p->set("uCount", int(g.nodeCount()));
    }
}

void GpuPoisson::redBlackSweep(int level, float overRelaxation) const
{
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, PotentialBinding, levels_[level].potential);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SourceBinding, levels_[level].source);
    programs_->sweep.set("uOverRelaxation", overRelaxation);
    programs_->sweep.use();
    for (int colour = 0; colour < 2; ++colour) {
        programs_->sweep.set("uColour", colour);
        glDispatchCompute(groupsFor(levels_[level].grid), 1, 1);
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    }
}

void GpuPoisson::vCycle(int level) const
{
    const Level& fine = levels_[level];
    setGrid(level);
    const bool coarsest = level + 1 == int(levels_.size());
    for (int sweep = 0; sweep < (coarsest ? kCoarsestSweeps : kSmoothingSweeps); ++sweep)
        redBlackSweep(level, 1.0f);
    if (coarsest)
        return;
    const Level& coarse = levels_[level + 1];
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, PotentialBinding, fine.potential);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SourceBinding, fine.source);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, PotentialOutBinding, fine.residual);
    programs_->residual.use();
    glDispatchCompute(groupsFor(fine.grid), 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

    setGrid(level + 1);
    programs_->restriction.set("uOtherCells", glm::vec3(fine.grid.cells[0], fine.grid.cells[1], fine.grid.cells[2]));
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SourceBinding, coarse.source);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, PotentialBinding, coarse.potential); // set to 0 there
    programs_->restriction.use();
    glDispatchCompute(groupsFor(coarse.grid), 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    vCycle(level + 1);

    setGrid(level);
    programs_->prolongation.set("uOtherCells",
                                glm::vec3(coarse.grid.cells[0], coarse.grid.cells[1], coarse.grid.cells[2]));
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, PotentialBinding, fine.potential);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, CoarseBinding, coarse.potential);
    programs_->prolongation.use();
    glDispatchCompute(groupsFor(fine.grid), 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    for (int sweep = 0; sweep < kSmoothingSweeps; ++sweep)
        redBlackSweep(level, 1.0f);
}

void GpuPoisson::setChargeDensity(const std::vector<double>& chargeDensity)
{
    if (chargeDensity.size() != grid_.nodeCount())
        throw std::invalid_argument("GpuPoisson: the charge density is not on the grid");
    const double mean = std::accumulate(chargeDensity.begin(), chargeDensity.end(), 0.0) / double(chargeDensity.size());
    std::vector<float> source(chargeDensity.size());
    for (std::size_t i = 0; i < source.size(); ++i)
        source[i] = float((chargeDensity[i] - mean) / simulation::kVacuumPermittivity);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT); // after the last solve's reads of the source
    glNamedBufferSubData(buffers_[1], 0, GLsizeiptr(source.size() * sizeof(float)), source.data());
}

void GpuPoisson::setChargeFromQuanta(unsigned quantaBuffer, std::size_t particles, double weight, int quantumBits)
{
    const double mean = std::ldexp(double(particles), quantumBits) / double(grid_.nodeCount());
    const double whole = std::floor(mean);
    programs_->source.set("uMeanWhole", int(whole));
    programs_->source.set("uMeanFraction", float(mean - whole));
    programs_->source.set("uSourceScale", float(-simulation::kElementaryCharge * weight / grid_.cellVolume() /
                                                std::ldexp(1.0, quantumBits) / simulation::kVacuumPermittivity));
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, QuantaBinding, quantaBuffer);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SourceBinding, buffers_[1]);
    programs_->source.use();
    glDispatchCompute(GLuint((grid_.nodeCount() + kWorkGroupSize - 1) / kWorkGroupSize), 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void GpuPoisson::clearPotential()
{
    const std::vector<float> zeros(grid_.nodeCount(), 0.0f);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT); // after the last solve's accesses of φ
    glNamedBufferSubData(buffers_[0], 0, GLsizeiptr(zeros.size() * sizeof(float)), zeros.data());
}

void GpuPoisson::solve(int sweeps)
{
    const GLuint groups = GLuint((grid_.nodeCount() + kWorkGroupSize - 1) / kWorkGroupSize);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    if (method_ == GpuPoissonMethod::Multigrid) {
        for (int cycle = 0; cycle < sweeps; ++cycle)
            vCycle(0);
        return;
    }
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SourceBinding, buffers_[1]);
    programs_->sweep.use();
    for (int sweep = 0; sweep < sweeps; ++sweep) {
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, PotentialBinding, buffers_[0]);
        if (method_ == GpuPoissonMethod::Jacobi) {
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, PotentialOutBinding, buffers_[2]);
            glDispatchCompute(groups, 1, 1);
            glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
            std::swap(buffers_[0], buffers_[2]);
            continue;
        }
        for (int colour = 0; colour < 2; ++colour) {
            programs_->sweep.set("uColour", colour);
            glDispatchCompute(groups, 1, 1);
            glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
        }
    }
}

std::vector<double> GpuPoisson::potential() const
{
    std::vector<float> values(grid_.nodeCount());
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glGetNamedBufferSubData(buffers_[0], 0, GLsizeiptr(values.size() * sizeof(float)), values.data());
    return std::vector<double>(values.begin(), values.end());
}

} // namespace aurorawall::components::plasma::gpu
