// The aurora's emission rows on the GPU (EGL; Mesa llvmpipe in CI): after any sequence of per-frame
// updates, the texture holds exactly the rows of the curtains' current energies, as a fresh build would.
#include "components/aurora/aurora_tables.h"
#include "gl/context.h"
#include "gl/functions.h"

#include <gtest/gtest.h>

#include <vector>

using namespace aurorawall;
using components::aurora::AuroraTables;

namespace {

std::vector<float> readBack(const gl::Texture& t)
{
    std::vector<float> texels(size_t(t.width()) * t.height() * t.depth() * 4);
    gl::glGetTextureImage(t.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(texels.size() * sizeof(float)), texels.data());
    return texels;
}

// The rows physics::emissionRow gives for these energies, one after the other.
std::vector<float> expectedRows(const AuroraTables& tables, const std::vector<float>& energiesKeV)
{
    const size_t nodes = static_cast<size_t>(tables.tables().nodeCount());
    std::vector<float> rows(4 * nodes * energiesKeV.size());
    for (size_t c = 0; c < energiesKeV.size(); ++c)
        components::aurora::physics::emissionRow(tables.tables(), energiesKeV[c], &rows[4 * nodes * c]);
    return rows;
}

} // namespace

TEST(AuroraTables, RowsFollowTheCurtainsEnergiesFrameByFrame)
{
    const auto context = gl::createContext(gl::Backend::Egl);
    const components::aurora::Settings settings;
    AuroraTables running(settings);
    // One curtain whose energy changes and then holds, a second that appears, energies that swap.
    const std::vector<std::vector<float>> frames = {{4.0f}, {6.0f}, {6.0f}, {6.0f, 2.0f}, {2.0f, 6.0f}, {2.0f, 9.5f}};
    for (const std::vector<float>& energies : frames) {
        running.update(energies);
        EXPECT_EQ(running.emission().depth(), static_cast<int>(energies.size()));
        const std::vector<float> rows = readBack(running.emission());
        EXPECT_EQ(rows, expectedRows(running, energies)) << "first energy " << energies[0] << " keV";
        AuroraTables fresh(settings);
        fresh.update(energies);
        EXPECT_EQ(rows, readBack(fresh.emission()));
    }
}
