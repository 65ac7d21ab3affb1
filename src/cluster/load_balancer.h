#pragma once
// Dynamic load balancing across the wall (the idea of Equalizer's load equalizer,
// Eilemann et al. 2009): every screen is cut into horizontal bands; each frame every band is
// rendered by some rank, and bands rendered away from their screen's rank travel to it before the
// swap. The split follows the measured cost of each band, smoothed so it does not oscillate.
// Pure bookkeeping: no MPI, no GL.
#include "wall/wall.h"

#include <vector>

namespace aurorawall::cluster {

struct Band {
    int screen = 0; // index into wall.screens
    int y0 = 0;     // first row (from the screen's top)
    int height = 0;
    int owner = 0;  // the rank that shows this screen
};

// Band boundaries fall on multiples of this many rows: rasterizers shade blocks of pixels (llvmpipe
// 4x4, GPUs 2x2 quads in groups of 32), and a band whose height is not a multiple of the block pays
// for the missing rows.
constexpr int kBandRowBlock = 8;

// Every screen cut into `bandsPerScreen` bands of nearly equal height, each a multiple of
// kBandRowBlock rows except the screen's last (at most one band per kBandRowBlock rows; a screen
// shorter than that is one band).
std::vector<Band> makeBands(const wall::Wall& wall, int bandsPerScreen);

class LoadBalancer {
public:
    // Each band's cost is predicted by double exponential smoothing (Holt 1957): a level that
    // moves `levelWeight` of the way to each new measurement, and a trend (the camera keeps
    // flying, so costs keep drifting) that moves `trendWeight` of the way to the level's change.
    LoadBalancer(std::vector<Band> bands, int ranks, double levelWeight = 0.8, double trendWeight = 0.3);

    const std::vector<Band>& bands() const { return bands_; }

    // Which rank renders each band next frame. Before any measurement every band stays with its
    // owner. Then, heaviest band first, a band goes to its previous renderer while that rank stays
    // within `tolerance` of the mean load (hysteresis: no band hops for a tiny gain), else to its
    // owner under the same condition, else to the least loaded rank. Deterministic.
    std::vector<int> assign(double tolerance = 0.02);

    // The measured cost of each band this frame (ms, any consistent unit; NaN: not measured).
    void observe(const std::vector<double>& bandCost);

    // The predicted cost of each band next frame: level + trend, at least 0.
    std::vector<double> predictedCosts() const;

private:
    std::vector<Band> bands_;
    int ranks_;
    double levelWeight_, trendWeight_;
    int measurements_ = 0;
    std::vector<double> level_, trend_;
    std::vector<int> previous_;
};

} // namespace aurorawall::cluster
