#include "components/roles/flux_frames.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>

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

std::vector<double> frameReachesKm(const FluxFrames& f, double stripWidthKm)
{
    float peak = 0.0f;
    for (float v : f.flux)
        peak = std::max(peak, v);
    std::vector<double> reach(size_t(f.frames), 0.0);
    for (int k = 0; k < f.frames; ++k)
        for (int iy = 0; iy < f.ny; ++iy)
            for (int ix = 0; ix < f.nx; ++ix)
                if (f.at(k, ix, iy) > 1e-3f * peak)
                    reach[k] = std::max(reach[k], std::abs((iy + 0.5) * f.texelKmY - 0.5 * stripWidthKm) + f.texelKmY);
    return reach;
}

std::vector<char> fluxFramesBytes(const FluxFrames& f)
{
    const std::int32_t counts[3] = {f.nx, f.ny, f.frames};
    const float texels[2] = {f.texelKmX, f.texelKmY};
    std::vector<char> bytes(sizeof counts + sizeof texels + f.flux.size() * sizeof(float));
    std::memcpy(bytes.data(), counts, sizeof counts);
    std::memcpy(bytes.data() + sizeof counts, texels, sizeof texels);
    std::memcpy(bytes.data() + sizeof counts + sizeof texels, f.flux.data(), f.flux.size() * sizeof(float));
    return bytes;
}

FluxFrames fluxFramesFromBytes(const std::vector<char>& bytes, int nx, int ny, int frames, const std::string& what)
{
    std::int32_t counts[3];
    float texels[2];
    const std::size_t header = sizeof counts + sizeof texels;
    const std::size_t cells = std::size_t(nx) * std::size_t(ny) * std::size_t(frames);
    if (bytes.size() != header + cells * sizeof(float))
        throw std::runtime_error(what + " cache: the frames do not have the spec's size");
    std::memcpy(counts, bytes.data(), sizeof counts);
    std::memcpy(texels, bytes.data() + sizeof counts, sizeof texels);
    if (counts[0] != nx || counts[1] != ny || counts[2] != frames)
        throw std::runtime_error(what + " cache: the frames do not have the spec's size");
    FluxFrames f;
    f.nx = counts[0];
    f.ny = counts[1];
    f.frames = counts[2];
    f.texelKmX = texels[0];
    f.texelKmY = texels[1];
    f.flux.resize(cells);
    std::memcpy(f.flux.data(), bytes.data() + header, cells * sizeof(float));
    return f;
}

} // namespace aurorawall::components::roles
