#include "components/aurora/footprint_map_gpu.h"

#include "components/aurora/aurora.h"
#include "physics/constants.h"
#include "gl/functions.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace aurorawall::components::aurora {

using namespace gl;

namespace {

// The passes of footprint_build.comp.
enum Pass { Start, NearestDistance, NearestSeed, OtherDistance, OtherSeed, Flood, CoarseBound, Assemble };
constexpr int kWorkGroupSize = 64;
constexpr double kUnitRoundoff = 0x1p-24;
constexpr double kTrigError = 0x1p-20;

enum Binding { FineDirections, CoarseDirections, BandBinding, CoarseDistances, FloodIn, FloodOut };

GLuint storageBuffer(size_t bytes)
{
    GLuint buffer = 0;
    glCreateBuffers(1, &buffer);
    glNamedBufferStorage(buffer, GLsizeiptr(bytes), nullptr, 0);
    return buffer;
}

} // namespace

double footprintGpuAllowanceKm(const physics::FootprintMap& frame)
{
    const double R = frame.planetRadiusKm;
    const double farthestKm = R * 2.0 * frame.angularRadius + frame.exactWithinKm;
    return R * (2.0 * kTrigError + 16.0 * kUnitRoundoff) + farthestKm * (kTrigError + 8.0 * kUnitRoundoff);
}

physics::FootprintMap FootprintMapGpu::gpuFrame(physics::FootprintMap cpuFrame)
{
    const double allowanceKm = footprintGpuAllowanceKm(cpuFrame);
    cpuFrame.marginKm += allowanceKm;
    if (cpuFrame.seedCount > 0)
        cpuFrame.exactWithinKm += allowanceKm;
    return cpuFrame;
}

FootprintMapGpu::FootprintMapGpu(const std::string& shaderDir)
    : program_(Program::compute({{"MAX_CURTAINS " + std::to_string(kMaxCurtains)},
                                 {readShaderModule(shaderDir + "/render/angle.glsl"),
                                  readShaderModule(shaderDir + "/components/aurora/footprint_map.glsl"),
                                  readShaderModule(shaderDir + "/components/aurora/footprint_build.comp")}}))
{
}

FootprintMapGpu::~FootprintMapGpu() { glDeleteBuffers(6, buffers_); }

void FootprintMapGpu::ensureBuffers(int size, int coarseSize)
{
    if (size == size_ && coarseSize == coarseSize_)
        return;
    glDeleteBuffers(6, buffers_);
    const size_t fine = size_t(size) * size, coarse = size_t(coarseSize) * coarseSize;
    buffers_[FineDirections] = storageBuffer(fine * 4 * sizeof(float));
    buffers_[CoarseDirections] = storageBuffer(coarse * 4 * sizeof(float));
    buffers_[BandBinding] = storageBuffer(fine * 4 * sizeof(unsigned));
    buffers_[CoarseDistances] = storageBuffer(coarse * sizeof(unsigned));
    buffers_[FloodIn] = storageBuffer(coarse * sizeof(unsigned));
    buffers_[FloodOut] = storageBuffer(coarse * sizeof(unsigned));
    size_ = size;
    coarseSize_ = coarseSize;
}

void FootprintMapGpu::dispatch(int pass, size_t invocations, GLbitfield barriers)
{
    program_.set("uPass", pass);
    glDispatchCompute(GLuint((invocations + kWorkGroupSize - 1) / kWorkGroupSize), 1, 1);
    glMemoryBarrier(barriers);
}

void FootprintMapGpu::build(const physics::FootprintMap& frame, const gl::Texture& polylines,
                            const std::vector<size_t>& pointCounts, const gl::Texture& map)
{
    const int n = frame.spec.size;
    if (map.width() != n || map.height() != n || map.format() != TexelFormat::RGBA32F)
        throw std::invalid_argument("FootprintMapGpu: the map texture must be RGBA32F, " + std::to_string(n) + "^2");
    if (pointCounts.size() > size_t(kMaxCurtains))
        throw std::invalid_argument("FootprintMapGpu: more than " + std::to_string(kMaxCurtains) + " curtains");
    const int coarse = physics::footprintCoarseMapSize(frame);
    ensureBuffers(n, coarse);

    program_.use();
    for (size_t c = 0; c < pointCounts.size(); ++c)
        program_.set("uPointCount[" + std::to_string(c) + "]", int(pointCounts[c]));
    program_.set("uCurtainCount", frame.seedCount > 0 ? int(pointCounts.size()) : 0);
    program_.set("uPolylineWidth", polylines.width());
    program_.set("uCentre", glm::vec3(frame.centre));
    program_.set("uEast", glm::vec3(frame.east));
    program_.set("uAngularRadius", float(frame.angularRadius));
    program_.set("uSize", n);
    program_.set("uCoarseSize", coarse);
    program_.set("uPlanetRadiusKm", float(frame.planetRadiusKm));
    program_.set("uBandKm", float(frame.exactWithinKm));
    const double bandChord = 2.0 * std::sin(0.5 * std::min(frame.exactWithinKm / frame.planetRadiusKm, aurorawall::physics::kPi));
    program_.set("uBandChord2", float(bandChord * bandChord));
    program_.set("uBandBox", physics::footprintBandBoxTexels(frame, frame.exactWithinKm));
    program_.set("uCoarseSlackKm", float(physics::footprintCoarseSlackKm(frame)));
    program_.set("uNoCurtainKm", float(physics::footprintNoCurtainKm(frame)));
    program_.bindTexture("uCurtainPolylines", 0, polylines.id());
    for (int b : {FineDirections, CoarseDirections, BandBinding, CoarseDistances})
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, GLuint(b), buffers_[b]);
    glBindImageTexture(0, map.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);

    // The nearest seeds: the band's and the coarse map's start (written to flood buffer A).
    GLuint flood[2] = {buffers_[FloodIn], buffers_[FloodOut]};
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, FloodIn, flood[1]);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, FloodOut, flood[0]);
    const size_t seeds = size_t(polylines.width()) * polylines.height();
    dispatch(Start, size_t(n) * n);
    for (int pass : {NearestDistance, NearestSeed, OtherDistance, OtherSeed})
        dispatch(pass, seeds);

    // Jump flooding on the coarse map: steps coarse/2, …, 1, then one more step-1 pass (JFA+1).
    std::vector<int> steps;
    for (int step = coarse / 2; step >= 1; step /= 2)
        steps.push_back(step);
    steps.push_back(1);
    for (int step : steps) {
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, FloodIn, flood[0]);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, FloodOut, flood[1]);
        program_.set("uJumpStep", step);
        dispatch(Flood, size_t(coarse) * coarse);
        std::swap(flood[0], flood[1]);
    }
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, FloodIn, flood[0]);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, FloodOut, flood[1]);
    dispatch(CoarseBound, size_t(coarse) * coarse);
    dispatch(Assemble, size_t(n) * n,
             GL_SHADER_STORAGE_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
}

} // namespace aurorawall::components::aurora
