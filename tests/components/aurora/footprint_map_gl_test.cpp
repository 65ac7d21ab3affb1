// The footprint map built on the GPU (EGL; Mesa llvmpipe in CI) against brute force in double and the
// CPU's build (src/components/aurora/physics/footprint_map.h): in the band every texel names a nearest
// curtain point, at most 2ε farther than the nearest, and stores its distance to within ε; elsewhere a
// lower bound to within ε, ε = footprintGpuAllowanceKm (derived in footprint_map_gpu.h).
#include "physics/random_curtains.h"
#include "components/aurora/curtain_build.h"
#include "components/aurora/footprint_map_gpu.h"
#include "gl/context.h"
#include "gl/debug_layer.h"
#include "gl/functions.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

using namespace aurorawall;
using components::aurora::physics::CurtainPolyline;
using components::aurora::physics::FootprintMap;
using components::aurora::physics::FootprintMapSpec;
using components::aurora::physics::random_curtains::angle;
using components::aurora::physics::random_curtains::kR;
using components::aurora::FootprintMapGpu;

namespace {

const std::string kShaders = std::string(AURORAWALL_SOURCE_DIR) + "/shaders";

// The polylines as the curtain field uploads them (curtain_build.h).
gl::Texture polylineTexture(const std::vector<CurtainPolyline>& curtains)
{
    int width = 0, rows = 0;
    const std::vector<float> texels = components::aurora::polylineTexels(curtains, width, rows);
    gl::Texture texture =
        gl::Texture::create2D(width, rows, gl::TexelFormat::RGBA32F, gl::Filter::Nearest, gl::Wrap::Clamp);
    texture.upload(texels);
    return texture;
}

struct GpuBuild {
    FootprintMap frame; // the GPU map's frame (margin and band with the float allowance)
    std::vector<float> texels;
};

GpuBuild buildOnGpu(const std::vector<CurtainPolyline>& curtains, const FootprintMapSpec& spec)
{
    GpuBuild out{FootprintMapGpu::gpuFrame(components::aurora::physics::footprintMapFrame(curtains, spec, kR)), {}};
    const gl::Texture polylines = polylineTexture(curtains);
    const gl::Texture map = gl::Texture::create2D(spec.size, spec.size, gl::TexelFormat::RGBA32F, gl::Filter::Nearest,
                                                  gl::Wrap::Clamp);
    std::vector<size_t> counts;
    for (const CurtainPolyline& c : curtains)
        counts.push_back(c.points.size());
    FootprintMapGpu builder(kShaders);
    builder.build(out.frame, polylines, counts, map);
    out.texels.resize(size_t(spec.size) * spec.size * 4);
    gl::glGetTextureImage(map.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(out.texels.size() * sizeof(float)),
                          out.texels.data());
    return out;
}

// The nearest point of every curtain from p, by brute force in double: per curtain (distance km, point).
std::vector<std::pair<double, int>> nearestPerCurtain(const std::vector<CurtainPolyline>& curtains, const glm::dvec3& p)
{
    std::vector<std::pair<double, int>> out;
    for (const CurtainPolyline& c : curtains) {
        double bestDot = -2.0;
        int point = -1;
        for (size_t k = 0; k < c.points.size(); ++k)
            if (glm::dot(p, c.points[k]) > bestDot) {
                bestDot = glm::dot(p, c.points[k]);
                point = int(k);
            }
        out.push_back({kR * angle(p, c.points[size_t(point)]), point});
    }
    return out;
}

} // namespace

TEST(FootprintMapOnTheGpu, AgreesWithBruteForceAndTheCpuBuild)
{
    const auto context = gl::createContext(gl::Backend::Egl);
    std::mt19937_64 rng(11);
    struct Case {
        int size;
        double reachKm, centreLatitudeDeg, centreLongitudeDeg, angularRadiusDeg;
        int curtains;
    };
    // North-pole and oblique frames; coarse maps of the full size and of a quarter of it.
    for (const Case& k : {Case{64, 20.0, 90.0, 0.0, 40.0, 8}, Case{128, 60.0, 72.0, 35.0, 50.0, 6},
                          Case{256, 30.0, 90.0, 0.0, 35.0, 10}, Case{512, 45.0, 75.0, -20.0, 48.0, 6}}) {
        const std::vector<CurtainPolyline> curtains =
            components::aurora::physics::random_curtains::randomCurtains(rng, k.curtains, 1000.0, k.size >= 256 ? 10.0 : 5.0);
        FootprintMapSpec spec;
        spec.size = k.size;
        spec.reachKm = k.reachKm;
        spec.centreLatitudeDeg = k.centreLatitudeDeg;
        spec.centreLongitudeDeg = k.centreLongitudeDeg;
        spec.angularRadiusDeg = k.angularRadiusDeg;
        const GpuBuild gpu = buildOnGpu(curtains, spec);
        const FootprintMap cpu = components::aurora::physics::buildFootprintMap(curtains, spec, kR);
        const double eps = components::aurora::footprintGpuAllowanceKm(cpu);
        ASSERT_NEAR(gpu.frame.marginKm, cpu.marginKm + eps, 1e-12 * cpu.marginKm);
        const double band = gpu.frame.exactWithinKm;
        const double h = kR * 2.0 * cpu.angularRadius / k.size;
        long bandTexels = 0, farTexels = 0, sameSeedAsCpu = 0, withOther = 0;
        for (int j = 0; j < k.size; ++j)
            for (int i = 0; i < k.size; ++i) {
                const glm::dvec3 p = components::aurora::physics::footprintTexelDirection(cpu, i, j);
                if (angle(p, cpu.centre) > cpu.angularRadius + std::sqrt(0.5) * h / kR)
                    continue; // never read: beyond the cap by more than half a texel diagonal
                const float* texel = &gpu.texels[4 * (size_t(j) * k.size + i)];
                const float* reference = &cpu.texels[4 * (size_t(j) * k.size + i)];
                const auto nearest = nearestPerCurtain(curtains, p);
                int first = 0;
                for (size_t c = 1; c < nearest.size(); ++c)
                    if (nearest[c].first < nearest[first].first)
                        first = int(c);
                const double trueKm = nearest[first].first;
                const std::string where = "N=" + std::to_string(k.size) + " texel " + std::to_string(i) + "," +
                                          std::to_string(j);
                if (trueKm <= band - eps) {
                    ++bandTexels;
                    const int c = int(texel[0]), point = int(texel[1]);
                    ASSERT_TRUE(c >= 0 && c < int(curtains.size())) << where;
                    ASSERT_TRUE(point >= 0 && point < int(curtains[c].points.size())) << where;
                    ASSERT_LE(kR * angle(p, curtains[c].points[point]), trueKm + 2.0 * eps) << where;
                    ASSERT_NEAR(texel[2], trueKm, eps) << where;
                    sameSeedAsCpu += texel[0] == reference[0] && texel[1] == reference[1];
                    // The other curtain: the nearest point of a curtain other than the stored one, if within the band.
                    double otherKm = 1e30;
                    for (size_t o = 0; o < nearest.size(); ++o)
                        if (int(o) != c)
                            otherKm = std::min(otherKm, nearest[o].first);
                    if (texel[3] >= 0.0f) {
                        ++withOther;
                        const int packed = int(texel[3]);
                        const int oc = packed / components::aurora::physics::kSecondPointStride, op = packed % components::aurora::physics::kSecondPointStride;
                        ASSERT_NE(oc, c) << where;
                        ASSERT_TRUE(oc < int(curtains.size()) && op < int(curtains[oc].points.size())) << where;
                        ASSERT_LE(kR * angle(p, curtains[oc].points[op]), otherKm + 2.0 * eps) << where;
                    } else {
                        ASSERT_GT(otherKm, band - eps) << where;
                    }
                } else if (trueKm > band + eps) {
                    ++farTexels;
                    ASSERT_LE(texel[2], trueKm + eps) << where;
                    ASSERT_GE(texel[2], float(band) * (1.0f - 1e-6f)) << where;
                    ASSERT_EQ(texel[3], -1.0f) << where;
                }
            }
        std::printf("N=%d: %ld band texels (%ld name the CPU's point, %ld another curtain), %ld far texels, "
                    "allowance %.4f km\n",
                    k.size, bandTexels, sameSeedAsCpu, withOther, farTexels, eps);
        EXPECT_GT(bandTexels, 100);
        EXPECT_GT(farTexels, 100);
    }
}

TEST(FootprintMapOnTheGpu, WithoutCurtainsEveryTexelSaysNone)
{
    const auto context = gl::createContext(gl::Backend::Egl);
    FootprintMapSpec spec;
    spec.size = 32;
    const GpuBuild gpu = buildOnGpu({}, spec);
    const FootprintMap cpu = components::aurora::physics::buildFootprintMap({}, spec, kR);
    for (size_t t = 0; t < gpu.texels.size(); t += 4) {
        ASSERT_EQ(gpu.texels[t], -1.0f);
        ASSERT_EQ(gpu.texels[t + 1], -1.0f);
        ASSERT_NEAR(gpu.texels[t + 2], cpu.texels[t + 2], 1e-6 * cpu.texels[t + 2]);
        ASSERT_EQ(gpu.texels[t + 3], -1.0f);
    }
}

// The same inputs give the same bytes, also with the workgroups run from the last and new buffers
// filled with NaN (the atomic minima do not depend on the order; every texel read was written).
TEST(FootprintMapOnTheGpu, SameInputsSameBytesInAnyWorkgroupOrder)
{
    const auto context = gl::createContext(gl::Backend::Egl);
    std::mt19937_64 rng(12);
    const std::vector<CurtainPolyline> curtains = components::aurora::physics::random_curtains::randomCurtains(rng, 5, 800.0, 5.0);
    FootprintMapSpec spec;
    spec.size = 128;
    spec.reachKm = 40.0;
    const std::vector<float> first = buildOnGpu(curtains, spec).texels;
    EXPECT_EQ(buildOnGpu(curtains, spec).texels, first);
    gl::DebugModes reordered;
    reordered.reverseWorkgroups = reordered.nanFill = true;
    gl::installDebugLayer(reordered);
    const std::vector<float> reversed = buildOnGpu(curtains, spec).texels;
    gl::installDebugLayer(gl::debugModes());
    EXPECT_EQ(reversed, first);
}
