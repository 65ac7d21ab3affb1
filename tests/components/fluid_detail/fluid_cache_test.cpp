// The fluid_detail frames through the on-disk cache: read back bit-identical to a fresh simulation,
// rebuilt for a changed spec, a corrupt file detected and rebuilt.
#include "components/fluid_detail/cached_flux_frames.h"
#include "io/table_cache.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

namespace aurorawall::components::fluid_detail {
namespace {

namespace fs = std::filesystem;

class FluidCache : public ::testing::Test {
protected:
    void SetUp() override
    {
        std::string pattern = (fs::temp_directory_path() / "aw_fluid_cache_XXXXXX").string();
        ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
        folder_ = pattern;
        spec_.nx = 64;
        spec_.ny = 16;
        spec_.stripLengthKm = 16.0;
        spec_.stripWidthKm = 4.0;
        spec_.frames = 4;
        spec_.stepsPerFrame = 2;
    }
    void TearDown() override { fs::remove_all(folder_); }

    std::string folder_;
    simulation::CurtainDetailSpec spec_;
};

void expectBitIdentical(const roles::FluxFrames& a, const roles::FluxFrames& b)
{
    EXPECT_EQ(a.nx, b.nx);
    EXPECT_EQ(a.ny, b.ny);
    EXPECT_EQ(a.frames, b.frames);
    EXPECT_EQ(a.texelKmX, b.texelKmX);
    EXPECT_EQ(a.texelKmY, b.texelKmY);
    ASSERT_EQ(a.flux.size(), b.flux.size());
    EXPECT_EQ(std::memcmp(a.flux.data(), b.flux.data(), a.flux.size() * sizeof(float)), 0);
}

TEST_F(FluidCache, ReadBackEqualsAFreshSimulation)
{
    const roles::FluxFrames fresh = simulation::simulateCurtainDetail(spec_);
    const CachedFluxFrames built = cachedFluxFrames(spec_, folder_);
    EXPECT_EQ(built.outcome, "built, cached");
    const CachedFluxFrames read = cachedFluxFrames(spec_, folder_);
    EXPECT_EQ(read.outcome, "read from cache");
    expectBitIdentical(built.frames, fresh);
    expectBitIdentical(read.frames, fresh);
}

// Each field of the spec is part of the key: changing any one of them must miss the cache.
TEST_F(FluidCache, EverySpecFieldChangesTheKey)
{
    const std::string base = fluxFramesCacheKey(spec_);
    std::vector<simulation::CurtainDetailSpec> changed(15, spec_);
    changed[0].nx = 128;
    changed[1].ny = 32;
    changed[2].stripLengthKm = 16.5;
    changed[3].stripWidthKm = 4.5;
    changed[4].shearVelocity = 1.0 + 1e-15;
    changed[5].shearThicknessKm = 1.1;
    changed[6].fluxWidthKm = 0.9;
    changed[7].perturbation = 0.03;
    changed[8].frames = 5;
    changed[9].timeBetweenFramesS = 4.0;
    changed[10].stepsPerFrame = 3;
    changed[11].pressureSolver = simulation::PressureSolver::Multigrid;
    changed[12].multigridCycles = 21;
    changed[13].multigridTolerance = 1e-7;
    changed[14].seed = 2;
    for (size_t i = 0; i < changed.size(); ++i)
        EXPECT_NE(fluxFramesCacheKey(changed[i]), base) << "field " << i;
    EXPECT_NE(base.find(io::executableDigest()), std::string::npos);
}

TEST_F(FluidCache, AChangedSpecRebuilds)
{
    cachedFluxFrames(spec_, folder_);
    simulation::CurtainDetailSpec other = spec_;
    other.seed = 7;
    const CachedFluxFrames rebuilt = cachedFluxFrames(other, folder_);
    EXPECT_EQ(rebuilt.outcome, "built, cached");
    expectBitIdentical(rebuilt.frames, simulation::simulateCurtainDetail(other));
}

TEST_F(FluidCache, ACorruptFileIsRebuilt)
{
    cachedFluxFrames(spec_, folder_);
    const std::string path = io::cachedTablePath(folder_, "fluid_detail", fluxFramesCacheKey(spec_));
    std::vector<char> bytes;
    {
        std::ifstream in(path, std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    ASSERT_GT(bytes.size(), 1000u);
    bytes[bytes.size() / 2] ^= 0x01; // one bit of one flux value
    {
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    }
    const CachedFluxFrames rebuilt = cachedFluxFrames(spec_, folder_);
    EXPECT_EQ(rebuilt.outcome, "cache corrupt, rebuilt");
    expectBitIdentical(rebuilt.frames, simulation::simulateCurtainDetail(spec_));
    fs::resize_file(path, bytes.size() - 3);
    EXPECT_EQ(cachedFluxFrames(spec_, folder_).outcome, "cache corrupt, rebuilt");
    EXPECT_EQ(cachedFluxFrames(spec_, folder_).outcome, "read from cache");
}

} // namespace
} // namespace aurorawall::components::fluid_detail
