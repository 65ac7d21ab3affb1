// The reach of the curtain detail at a detail phase (fluid_detail::DetailShape::reachAtPhaseKm):
// beyond it the flux of the frames that phase blends is negligible, and it is narrower than the
// largest reach while the frames are still smooth.
#include "components/fluid_detail/curtain_detail.h"
#include "components/fluid_detail/simulation/curtain_detail.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace aurorawall::components::fluid_detail {
namespace {

// Every phase from smooth to turbulent: at every position along the strip (every cell and between
// cells) and every lateral distance beyond the phase's reach (out to the strip's edge), the flux
// the shader blends (roles::sampleFlux, bilinear in space and linear between frames) is at most
// 1e-3 of the frames' peak. Default spec: 512 x 128 cells, 16 frames, strip 128 x 32 km.
TEST(DetailReach, BeyondThePhasesReachTheBlendedFluxIsNegligible)
{
    const simulation::CurtainDetailSpec spec;
    const roles::FluxFrames frames = simulation::simulateCurtainDetail(spec);
    const DetailShape shape = detailShape(spec, frames);
    const float peak = *std::max_element(frames.flux.begin(), frames.flux.end());
    ASSERT_EQ(shape.frameReachKm.size(), size_t(frames.frames));
    EXPECT_EQ(shape.reachKm, *std::max_element(shape.frameReachKm.begin(), shape.frameReachKm.end()));
    // The shear layer rolls up: the last frame reaches much farther than the first.
    EXPECT_GT(shape.frameReachKm.back(), 2.0 * shape.frameReachKm.front());

    const double cell = frames.texelKmY;
    for (int i = 0; i <= 40; ++i) {
        const double phase = i / 40.0;
        const double reach = shape.reachAtPhaseKm(phase);
        double largestBeyond = 0.0;
        for (double s = 0.0; s < spec.stripLengthKm; s += 0.5 * frames.texelKmX)
            for (double u = reach; u <= 0.5 * spec.stripWidthKm; u += 0.25 * cell)
                for (double side : {-1.0, 1.0})
                    largestBeyond = std::max(largestBeyond, roles::sampleFlux(frames, s, side * u, phase));
        EXPECT_LE(largestBeyond, 1e-3 * peak) << "phase " << phase << ", reach " << reach << " km";
    }
    // A phase between two frames takes the larger of their reaches; one within rounding of a frame
    // also its neighbours'.
    const int last = frames.frames - 1;
    EXPECT_EQ(shape.reachAtPhaseKm(6.5 / last), std::max(shape.frameReachKm[6], shape.frameReachKm[7]));
    EXPECT_EQ(shape.reachAtPhaseKm(6.0 / last),
              std::max({shape.frameReachKm[5], shape.frameReachKm[6], shape.frameReachKm[7]}));
    EXPECT_EQ(shape.reachAtPhaseKm(1.0), std::max(shape.frameReachKm[last - 1], shape.frameReachKm[last]));
    // Halfway through the roll-up the curtain is much narrower than at its end.
    EXPECT_LT(shape.reachAtPhaseKm(0.5), 0.6 * shape.reachKm);
}

} // namespace
} // namespace aurorawall::components::fluid_detail
