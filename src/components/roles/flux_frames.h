#pragma once
// The data of the role "curtain detail" (roles/curtain_detail.h): flux frames on a strip along a
// curtain, as a provider computes them (a fluid simulation, a plasma's electron strip) and as the
// curtains' profile samples them.
#include <cstddef>
#include <string>
#include <vector>

namespace aurorawall::components::roles {

// Flux frames: F (1/km) at the cell centres, frame-major then row-major: flux[(k·ny + iy)·nx + ix].
// Texel (ix, iy) is centred at s = (ix + ½)·texelKmX along the curtain and u = (iy + ½)·texelKmY − Ly/2
// across it (u = 0 on the curtain's centre line). Normalized so that ∫F du = 1 for every column of
// frame 0.
struct FluxFrames {
    int nx = 0;
    int ny = 0;
    int frames = 0;
    float texelKmX = 0.0f;
    float texelKmY = 0.0f;
    std::vector<float> flux;

    float at(int frame, int ix, int iy) const { return flux[(std::size_t(frame) * ny + iy) * nx + ix]; }
};

// The CPU reference for the shader lookup: F at (sKm along, uKm across from the centre line),
// bilinear between texel centres with periodic wrap in both directions, and linear between
// frames ⌊p⌋ and ⌊p⌋ + 1 at p = clamp(phase, 0, 1)·(frames − 1). In double.
double sampleFlux(const FluxFrames& frames, double sKm, double uKm, double phase);

// For each frame: beyond this lateral distance from the strip's centre line (strip km) the frame
// holds no more than 1e-3 of the peak flux of all frames: the largest |u| + one texel of any such cell.
std::vector<double> frameReachesKm(const FluxFrames& frames, double stripWidthKm);

// Flux frames as the bytes of a cache file: nx, ny, frames (int32), texelKmX, texelKmY (float32),
// then the flux (float32), native byte order; and back, checked against the expected counts (an
// error naming `what` when they differ): the providers' on-disk table caches.
std::vector<char> fluxFramesBytes(const FluxFrames& frames);
FluxFrames fluxFramesFromBytes(const std::vector<char>& bytes, int nx, int ny, int frames, const std::string& what);

} // namespace aurorawall::components::roles
