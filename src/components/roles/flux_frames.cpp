#include "components/roles/flux_frames.h"

#include <algorithm>
#include <cmath>

namespace aurorawall::components::roles {

// Bilinear in (s, u) between texel centres, periodic, then linear between two frames:
//   F = (1−t) F_k0(s, u) + t F_k1(s, u), k0 = ⌊p⌋, k1 = min(k0+1, K−1), t = p − k0.
double sampleFlux(const FluxFrames& frames, double sKm, double uKm, double phase)
{
    const double gx = sKm / double(frames.texelKmX) - 0.5;
    const double gy = (uKm + 0.5 * frames.ny * double(frames.texelKmY)) / double(frames.texelKmY) - 0.5;
    const double fx = std::floor(gx);
    const double fy = std::floor(gy);
    const double a = gx - fx;
    const double b = gy - fy;
    const auto wrap = [](double index, int n) {
        const double r = std::fmod(index, double(n));
        return int(r < 0.0 ? r + n : r);
    };
    const int i0 = wrap(fx, frames.nx);
    const int j0 = wrap(fy, frames.ny);
    const int i1 = (i0 + 1) % frames.nx;
    const int j1 = (j0 + 1) % frames.ny;

    const double p = std::clamp(phase, 0.0, 1.0) * (frames.frames - 1);
    const int k0 = std::min(int(p), frames.frames - 1);
    const int k1 = std::min(k0 + 1, frames.frames - 1);
    const double t = p - k0;
    const auto bilinear = [&](int k) {
        return (1.0 - b) * ((1.0 - a) * frames.at(k, i0, j0) + a * frames.at(k, i1, j0)) +
               b * ((1.0 - a) * frames.at(k, i0, j1) + a * frames.at(k, i1, j1));
    };
    return (1.0 - t) * bilinear(k0) + t * bilinear(k1);
}

} // namespace aurorawall::components::roles
