#include "common/constants.h"
#include "components/glory/gpu_table.h"

#include "components/glory/mie/log_derivative.h"
#include "components/glory/mie/mie_coefficients.h"
#include "components/glory/optics/water.h"
#include "gl/functions.h"
#include "gl/shader_program.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace aurorawall::glory {

namespace {

using namespace gl; // the GL function pointers (gl/functions.h)

constexpr int kWorkGroupSize = 64; // local_size_x of mie_table.comp
constexpr int kChunkNodes = 32;    // nodes per invocation of pass 2: at most 32 × 430 loop steps to x = 400

// mie_table.comp's Node, std430.
struct Node {
    float x, weight, sinX, cosX;
    std::int32_t terms, startIndex;
    float startLogDerivative;
    std::int32_t unused;
};

// One wavelength's radius nodes: those of phaseTable() (optics/glory_table.cpp), trapezoid weights times
// n(r)/n(mode); the weighted cross-section ∫ n π r² Qsca dr is summed later from the nodes' Qsca.
struct Row {
    double k = 0.0; // wavenumber, µm⁻¹
    std::vector<double> radiiUm;
    std::vector<Node> nodes;
};

// The recurrences' starts as mieCoefficients() makes them (mie/mie_coefficients.h), m real.
Node node(double x, double m, double weight)
{
    const int terms = mie::wiscombeTermCount(x);
    const int start = std::max(terms, int(std::ceil(m * x))) + 15;
    return {float(x), float(weight), float(std::sin(x)), float(std::cos(x)), terms, start,
            float(mie::logDerivativeContinuedFraction(m * x, start).real()), 0};
}

Row radiusNodes(const mie::DropSizeDistribution& drops, double wavelengthNm, double sizeParameterStep)
{
    Row row;
    row.k = 2.0 * kPi / (wavelengthNm * 1e-3);
    const double m = waterRefractiveIndex(wavelengthNm);
    if (drops.isSingleSize()) {
        row.radiiUm.push_back(drops.effectiveRadiusUm());
        row.nodes.push_back(node(row.k * drops.effectiveRadiusUm(), m, 1.0));
        return row;
    }
    const auto [lo, hi] = drops.radiusRangeUm();
    const int intervals = std::max(2, static_cast<int>(std::ceil(row.k * (hi - lo) / sizeParameterStep)));
    const double dr = (hi - lo) / intervals;
    const double logMode = drops.logDensity(drops.effectiveRadiusUm());
    for (int j = 0; j <= intervals; ++j) {
        const double r = lo + j * dr;
        const double weight = ((j == 0 || j == intervals) ? 0.5 : 1.0) * std::exp(drops.logDensity(r) - logMode);
        row.radiiUm.push_back(r);
        row.nodes.push_back(node(row.k * r, m, weight));
    }
    return row;
}

GLuint storageBuffer(GLsizeiptr bytes, const void* data, GLuint binding)
{
    GLuint buffer = 0;
    glCreateBuffers(1, &buffer);
    glNamedBufferStorage(buffer, std::max<GLsizeiptr>(bytes, 4), data, 0);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, buffer);
    return buffer;
}

gl::Program pass(const gl::ShaderModule& module, int number)
{
    return gl::Program::compute({{"MIE_TABLE_PASS " + std::to_string(number)}, {module}});
}

GLuint groups(int invocations) { return GLuint((invocations + kWorkGroupSize - 1) / kWorkGroupSize); }

} // namespace

PhaseTable phaseTableOnGpu(const mie::DropSizeDistribution& drops, const GloryTableSpec& spec,
                           const std::string& shaderDir)
{
    PhaseTable table = emptyPhaseTable(spec);
    const int angleCount = spec.angles.size();
    const int wavelengthCount = spec.wavelengthCount;

    std::vector<Row> rows;
    std::vector<Node> nodes;
    std::vector<int> firstNode, firstChunk;
    int maxNodes = 0, termStride = 0, chunks = 0;
    for (double nm : table.wavelengthsNm) {
        rows.push_back(radiusNodes(drops, nm, spec.sizeParameterStep));
        firstNode.push_back(int(nodes.size()));
        firstChunk.push_back(chunks);
        chunks += (int(rows.back().nodes.size()) + kChunkNodes - 1) / kChunkNodes;
        nodes.insert(nodes.end(), rows.back().nodes.begin(), rows.back().nodes.end());
        maxNodes = std::max(maxNodes, int(rows.back().nodes.size()));
        for (const Node& n : rows.back().nodes)
            termStride = std::max(termStride, int(n.terms));
    }
    // cos θ = −cos γ (θ = π − γ) as σ(1 − s) (mie_table.comp): s = 2 sin²(γ/2) toward the antisolar
    // point, 2 cos²(γ/2) toward the light.
    std::vector<glm::vec2> cosines;
    for (int a = 0; a < angleCount; ++a) {
        const double gamma = spec.angles.angle(a);
        cosines.push_back(gamma <= 0.5 * kPi ? glm::vec2(-1.0f, float(2.0 * std::pow(std::sin(0.5 * gamma), 2)))
                                              : glm::vec2(1.0f, float(2.0 * std::pow(std::cos(0.5 * gamma), 2))));
    }

    // One wavelength's coefficients in one storage block: GL 4.5 guarantees 16 MiB (the default table
    // needs 13 MB); larger drops or finer steps may not fit.
    const GLsizeiptr coefficientBytes = GLsizeiptr(maxNodes) * termStride * GLsizeiptr(4 * sizeof(float));
    GLint largestBlock = 0;
    glGetIntegerv(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &largestBlock);
    if (coefficientBytes > GLsizeiptr(largestBlock))
        throw std::runtime_error("glory phase table on the GPU: " + std::to_string(coefficientBytes >> 20) +
                                 " MiB of Mie coefficients per wavelength exceed the GL's largest storage block (" +
                                 std::to_string(largestBlock >> 20) + " MiB)");

    const gl::ShaderModule module = gl::readShaderModule(shaderDir + "/components/glory/mie_table.comp");
    gl::Program coefficients = pass(module, 1);
    gl::Program sums = pass(module, 2);
    const GLuint buffers[5] = {
        storageBuffer(GLsizeiptr(nodes.size() * sizeof(Node)), nodes.data(), 0),
        storageBuffer(coefficientBytes, nullptr, 1),
        storageBuffer(GLsizeiptr(nodes.size() * sizeof(float)), nullptr, 2),
        storageBuffer(GLsizeiptr(cosines.size() * sizeof(glm::vec2)), cosines.data(), 3),
        storageBuffer(GLsizeiptr(chunks) * angleCount * GLsizeiptr(sizeof(float)), nullptr, 4)};
    for (gl::Program* p : {&coefficients, &sums}) {
        p->set("uTermStride", termStride);
        p->set("uAngleCount", angleCount);
        p->set("uChunkNodes", kChunkNodes);
    }
    for (int w = 0; w < wavelengthCount; ++w) {
        const int count = int(rows[size_t(w)].nodes.size());
        for (gl::Program* p : {&coefficients, &sums}) {
            p->set("uFirstNode", firstNode[size_t(w)]);
            p->set("uNodeCount", count);
            p->set("uIndex", float(waterRefractiveIndex(table.wavelengthsNm[size_t(w)])));
            p->set("uFirstChunk", firstChunk[size_t(w)]);
        }
        coefficients.use();
        glDispatchCompute(groups(count), 1, 1);
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
        sums.use();
        glDispatchCompute(groups(angleCount), GLuint((count + kChunkNodes - 1) / kChunkNodes), 1);
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
        table.mieSeries += count;
    }
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<float> s11(size_t(chunks) * size_t(angleCount));
    std::vector<float> efficiencies(nodes.size());
    glGetNamedBufferSubData(buffers[4], 0, GLsizeiptr(s11.size() * sizeof(float)), s11.data());
    glGetNamedBufferSubData(buffers[2], 0, GLsizeiptr(efficiencies.size() * sizeof(float)), efficiencies.data());
    glDeleteBuffers(5, buffers);
    glUseProgram(0);

    // P = 4π Σ w S11 / (k² Σ w π r² Qsca) (phaseTable()'s normalisation): the chunks and the
    // cross-section summed in double here.
    for (int w = 0; w < wavelengthCount; ++w) {
        const Row& row = rows[size_t(w)];
        double crossSection = 0.0;
        for (size_t j = 0; j < row.nodes.size(); ++j)
            crossSection += double(row.nodes[j].weight) * kPi * row.radiiUm[j] * row.radiiUm[j] *
                            double(efficiencies[size_t(firstNode[size_t(w)]) + j]);
        const int end = w + 1 < wavelengthCount ? firstChunk[size_t(w) + 1] : chunks;
        for (int a = 0; a < angleCount; ++a) {
            double sum = 0.0;
            for (int c = firstChunk[size_t(w)]; c < end; ++c)
                sum += double(s11[size_t(c) * size_t(angleCount) + size_t(a)]);
            table.values[size_t(w) * size_t(angleCount) + size_t(a)] = 4.0 * kPi * sum / (row.k * row.k * crossSection);
        }
    }
    return table;
}

} // namespace aurorawall::glory
