#include "components/plasma/gpu/gpu_pic.h"

#include "components/plasma/gpu/gpu_limits.h"
#include "components/plasma/simulation/plasma_parameters.h"
#include "gl/context.h"
#include "gl/functions.h"
#include "gl/shader_program.h"

#include <glm/vec4.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

namespace aurorawall::components::plasma::gpu {
namespace {

using namespace gl; // the GL function pointers (gl/functions.h)

constexpr int kWorkGroupSize = 64; // local_size_x of pic_step.comp
constexpr double kChargeOverMass = -simulation::kElementaryCharge / simulation::kElectronMass; // C/kg
enum Buffer { Positions, Velocities, ChargeQuanta, Potential, NodeField };

GLuint storageBuffer(std::size_t bytes, const void* data, GLuint binding)
{
    GLuint buffer = 0;
    glCreateBuffers(1, &buffer);
    glNamedBufferStorage(buffer, GLsizeiptr(std::max<std::size_t>(bytes, 16)), data, GL_DYNAMIC_STORAGE_BIT);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, buffer);
    return buffer;
}

std::vector<glm::vec4> packed(const std::vector<glm::dvec3>& values)
{
    std::vector<glm::vec4> out;
    out.reserve(values.size());
    for (const glm::dvec3& v : values)
        out.emplace_back(glm::vec3(v), 0.0f);
    return out;
}

std::vector<glm::dvec3> readVectors(GLuint buffer, std::size_t count)
{
    std::vector<glm::vec4> values(count);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glGetNamedBufferSubData(buffer, 0, GLsizeiptr(count * sizeof(glm::vec4)), values.data());
    std::vector<glm::dvec3> out;
    out.reserve(count);
    for (const glm::vec4& v : values)
        out.emplace_back(glm::dvec3(glm::vec3(v)));
    return out;
}

GLuint groups(std::size_t invocations) { return GLuint((invocations + kWorkGroupSize - 1) / kWorkGroupSize); }

} // namespace

int depositQuantumBits(std::size_t particleCount, int dimension)
{
    constexpr long long kLimit = (1LL << 31) - 1;
    for (int bits = 20; bits >= 8; --bits)
        if ((long long)particleCount * ((1LL << bits) + (1LL << dimension)) <= kLimit)
            return bits;
    throw std::invalid_argument(std::to_string(particleCount) + " particles exceed the fixed-point deposit's limit of " +
                                std::to_string(kLimit / ((1LL << 8) + (1LL << dimension))) + " in " +
                                std::to_string(dimension) + "D (32-bit node sums at 2^-8 of a particle)");
}

GpuPicSolver preferredGpuPicSolver(const simulation::PeriodicGrid& grid, const std::string& rendererName)
{
    if (gl::isSoftwareRenderer(rendererName))
        return GpuPicSolver::FftCpu;
    for (int d = 0; d < grid.dimension; ++d)
        if (grid.cells[d] % 2 != 0)
            return GpuPicSolver::FftCpu;
    return GpuPicSolver::Multigrid;
}

int picSorSweeps(const simulation::PeriodicGrid& grid)
{
    return int(std::ceil(std::log(1e-6) / std::log(sorOverRelaxation(grid) - 1.0)));
}

struct GpuPic::Programs {
    gl::Program deposit, field, push;
};

const simulation::PeriodicGrid& GpuPic::checkedAgainstGpuLimits(const simulation::PeriodicGrid& grid, std::size_t particleCount)
{
    depositQuantumBits(particleCount, grid.dimension);
    const GpuLimits limits = currentGpuLimits();
    requireFitsGpu(limits, particleCount, "particles", kWorkGroupSize, sizeof(glm::vec4));
    requireFitsGpu(limits, grid.nodeCount(), "grid nodes", kWorkGroupSize, sizeof(glm::vec4));
    return grid;
}

GpuPic::GpuPic(const simulation::PeriodicGrid& grid, const simulation::Particles& electrons, glm::dvec3 magneticField, double dt,
               const std::string& shaderDir, glm::dvec3 externalField, GpuPicSolver solver)
    : grid_(checkedAgainstGpuLimits(grid, electrons.position.size())), solver_(solver), poisson_(grid), particleCount_(electrons.position.size()), weight_(electrons.weight),
      quantumBits_(depositQuantumBits(electrons.position.size(), grid.dimension)), dt_(dt),
      zeroQuanta_(grid.nodeCount(), 0)
{
    if (!(dt > 0.0) || electrons.position.size() != electrons.velocity.size())
        throw std::invalid_argument("GpuPic: needs dt > 0 and a velocity per particle");
    std::vector<gl::ShaderModule> modules;
    for (const char* name : {"cloud_in_cell.glsl", "electric_field.glsl", "boris_push.glsl", "pic_step.comp"})
        modules.push_back(gl::readShaderModule(shaderDir + "/components/plasma/" + name));
    const auto program = [&](int pass) {
        return gl::Program::compute(
            {{"PLASMA_DIMENSION " + std::to_string(grid.dimension), "PLASMA_PASS " + std::to_string(pass)}, modules});
    };
    programs_ = std::make_unique<Programs>(Programs{program(1), program(2), program(3)});
    if (solver != GpuPicSolver::FftCpu)
        gpuPoisson_ = std::make_unique<GpuPoisson>(grid,
                                                   solver == GpuPicSolver::Jacobi        ? GpuPoissonMethod::Jacobi
                                                   : solver == GpuPicSolver::Multigrid ? GpuPoissonMethod::Multigrid
                                                                                        : GpuPoissonMethod::RedBlackSor,
                                                   shaderDir);
    const glm::vec3 cells(grid.cells[0], grid.cells[1], grid.cells[2]);
    const glm::vec3 spacing(grid.spacing[0], grid.spacing[1], grid.spacing[2]);
    for (gl::Program* p : {&programs_->deposit, &programs_->field, &programs_->push}) {
        p->set("uCells", cells);
        p->set("uSpacing", spacing);
        p->set("uCount", int(p == &programs_->field ? grid.nodeCount() : particleCount_));
    }
    programs_->deposit.set("uQuantumBits", quantumBits_);
    programs_->push.set("uExternalField", glm::vec3(externalField));
    programs_->push.set("uMagneticField", glm::vec3(magneticField));
    programs_->push.set("uChargeOverMass", float(kChargeOverMass));

    const std::vector<glm::vec4> x = packed(electrons.position), v = packed(electrons.velocity);
    buffers_[Positions] = storageBuffer(x.size() * sizeof(glm::vec4), x.data(), Positions);
    buffers_[Velocities] = storageBuffer(v.size() * sizeof(glm::vec4), v.data(), Velocities);
    buffers_[ChargeQuanta] = storageBuffer(grid.nodeCount() * sizeof(std::int32_t), nullptr, ChargeQuanta);
    buffers_[Potential] = storageBuffer(grid.nodeCount() * sizeof(float), nullptr, Potential);
    buffers_[NodeField] = storageBuffer(grid.nodeCount() * sizeof(glm::vec4), nullptr, NodeField);
    solveFields();
    push(-0.5 * dt_, false);
}

GpuPic::~GpuPic()
{
    glDeleteBuffers(5, buffers_);
}

void GpuPic::bindBuffers() const
{
    for (GLuint b = 0; b < 5; ++b)
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, b, buffers_[b]);
    if (gpuPoisson_)
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, Potential, gpuPoisson_->potentialBuffer());
}

void GpuPic::push(double dt, bool movePositions)
{
    bindBuffers();
    programs_->push.set("uDt", float(dt));
    programs_->push.set("uMovePositions", movePositions ? 1 : 0);
    programs_->push.use();
    glDispatchCompute(groups(particleCount_), 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void GpuPic::deposit()
{
    bindBuffers();
    // The upload waits for the last step's shader accesses of the sums, and the sums' readers (the
    // GPU solvers' source pass, or chargeDensity's read-back) for the deposit's atomics.
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glNamedBufferSubData(buffers_[ChargeQuanta], 0, GLsizeiptr(zeroQuanta_.size() * sizeof(std::int32_t)),
                         zeroQuanta_.data());
    programs_->deposit.use();
    glDispatchCompute(groups(particleCount_), 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

const std::vector<double>& GpuPic::chargeDensity() const
{
    if (chargeDensityStep_ == steps_)
        return chargeDensity_;
    const std::size_t nodes = grid_.nodeCount();
    std::vector<std::int32_t> quanta(nodes);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glGetNamedBufferSubData(buffers_[ChargeQuanta], 0, GLsizeiptr(nodes * sizeof(std::int32_t)), quanta.data());
    // ρ_i = (q/ΔV) 2^-bits (S_i − ΣS/N): the background subtracted exactly, as N·S_i − ΣS in integers
    // (ΣS = particles · 2^bits; |N·S_i| < 2^31 · N fits 64 bits), then scaled once.
    const long long total = (long long)particleCount_ << quantumBits_;
    const double scale = -simulation::kElementaryCharge * weight_ / grid_.cellVolume() / double(1LL << quantumBits_) / double(nodes);
    chargeDensity_.resize(nodes);
    for (std::size_t i = 0; i < nodes; ++i)
        chargeDensity_[i] = double((long long)nodes * quanta[i] - total) * scale;
    chargeDensityStep_ = steps_;
    return chargeDensity_;
}

void GpuPic::solvePotential()
{
    if (gpuPoisson_) {
        gpuPoisson_->setChargeFromQuanta(buffers_[ChargeQuanta], particleCount_, weight_, quantumBits_);
        gpuPoisson_->solve(solver_ == GpuPicSolver::Jacobi      ? kPicJacobiSweeps
                           : solver_ == GpuPicSolver::Multigrid ? kPicMultigridCycles
                                                                : picSorSweeps(grid_));
        return;
    }
    const std::vector<double> potential = poisson_.solve(chargeDensity());
    const std::vector<float> potentialFloat(potential.begin(), potential.end());
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT); // after the last field pass read φ
    glNamedBufferSubData(buffers_[Potential], 0, GLsizeiptr(potentialFloat.size() * sizeof(float)),
                         potentialFloat.data());
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void GpuPic::computeNodeField()
{
    bindBuffers();
    programs_->field.use();
    glDispatchCompute(groups(grid_.nodeCount()), 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void GpuPic::solveFields()
{
    deposit();
    solvePotential();
    computeNodeField();
}

void GpuPic::step()
{
    push(dt_, true);
    ++steps_;
    solveFields();
}

StepTimes GpuPic::timedStep()
{
    using Clock = std::chrono::steady_clock;
    const auto since = [](Clock::time_point start) {
        glFinish();
        return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    };
    glFinish();
    StepTimes t;
    Clock::time_point start = Clock::now();
    push(dt_, true);
    t.pushMs = since(start);
    ++steps_;
    start = Clock::now();
    deposit();
    t.depositMs = since(start);
    start = Clock::now();
    solvePotential();
    t.solveMs = since(start);
    start = Clock::now();
    computeNodeField();
    t.fieldMs = since(start);
    return t;
}

std::vector<glm::dvec3> GpuPic::positions() const { return readVectors(buffers_[Positions], particleCount_); }
std::vector<glm::dvec3> GpuPic::velocities() const { return readVectors(buffers_[Velocities], particleCount_); }
std::vector<glm::dvec3> GpuPic::nodeField() const { return readVectors(buffers_[NodeField], grid_.nodeCount()); }

std::vector<double> GpuPic::potential() const
{
    if (gpuPoisson_)
        return gpuPoisson_->potential();
    std::vector<float> values(grid_.nodeCount());
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glGetNamedBufferSubData(buffers_[Potential], 0, GLsizeiptr(values.size() * sizeof(float)), values.data());
    return {values.begin(), values.end()};
}

} // namespace aurorawall::components::plasma::gpu
