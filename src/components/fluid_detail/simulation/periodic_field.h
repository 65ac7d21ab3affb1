#pragma once
// A scalar field on a doubly periodic nx × ny grid (powers of two) and its interpolation.
// See docs/fluid.md, "Discretization".
#include <algorithm>
#include <cstddef>
#include <vector>

namespace aurorawall::components::fluid_detail::simulation {

bool isPowerOfTwo(int n);

// Values at the nodes (i, j), i in [0, nx), j in [0, ny), spaced hx × hy (km). Indices wrap:
// node (i + nx, j − ny) is node (i, j). Where a node sits in space (cell centre or face) is the
// owner's business; interpolation works in grid coordinates, node (i, j) at (i, j).
struct PeriodicField {
    int nx = 0;
    int ny = 0;
    double hx = 0.0;
    double hy = 0.0;
    std::vector<double> values; // values[j * nx + i]

    PeriodicField() = default;
    // All zero. nx and ny must be powers of two (std::invalid_argument otherwise).
    PeriodicField(int nx, int ny, double hx, double hy);

    int wrapX(int i) const { return i & (nx - 1); }
    int wrapY(int j) const { return j & (ny - 1); }
    double& operator()(int i, int j) { return values[std::size_t(wrapY(j)) * nx + wrapX(i)]; }
    double operator()(int i, int j) const { return values[std::size_t(wrapY(j)) * nx + wrapX(i)]; }

    // (1/N) Σ q and sqrt((1/N) Σ q²) over the N = nx·ny nodes.
    double mean() const;
    double rms() const;
    void subtractMean();
};

// ⌊g⌋ by truncation and a correction (std::floor is a library call on baseline x86-64).
inline int floorToInt(double g)
{
    const int i = int(g);
    return i - int(g < double(i));
}

// Catmull–Rom weights of the nodes −1, 0, 1, 2 at t in [0, 1):
//   w₋₁ = (−t³ + 2t² − t)/2, w₀ = (3t³ − 5t² + 2)/2, w₁ = (−3t³ + 4t² + t)/2, w₂ = (t³ − t²)/2.
inline void catmullRomWeights(double t, double w[4])
{
    const double t2 = t * t;
    const double t3 = t2 * t;
    w[0] = 0.5 * (-t3 + 2.0 * t2 - t);
    w[1] = 0.5 * (3.0 * t3 - 5.0 * t2 + 2.0);
    w[2] = 0.5 * (-3.0 * t3 + 4.0 * t2 + t);
    w[3] = 0.5 * (t3 - t2);
}

// Bilinear interpolation at grid coordinates (gx, gy) with i = ⌊gx⌋, a = gx − i (same for y):
//   q = (1−a)(1−b) q(i,j) + a(1−b) q(i+1,j) + (1−a) b q(i,j+1) + a b q(i+1,j+1).
inline double sampleBilinear(const PeriodicField& f, double gx, double gy)
{
    const int i = floorToInt(gx);
    const int j = floorToInt(gy);
    const double a = gx - i;
    const double b = gy - j;
    return (1.0 - b) * ((1.0 - a) * f(i, j) + a * f(i + 1, j)) + b * ((1.0 - a) * f(i, j + 1) + a * f(i + 1, j + 1));
}

// Bicubic Catmull–Rom interpolation on the 4 × 4 nodes around (gx, gy), clamped to the min/max
// of the 2 × 2 nodes of the cell (Fedkiw, Stam & Jensen 2001, "Visual simulation of smoke",
// sec. 3.3): third order in smooth regions, never a new extremum.
inline double sampleCubicClamped(const PeriodicField& f, double gx, double gy)
{
    const int i = floorToInt(gx);
    const int j = floorToInt(gy);
    double wx[4];
    double wy[4];
    catmullRomWeights(gx - i, wx);
    catmullRomWeights(gy - j, wy);
    double q = 0.0;
    for (int m = 0; m < 4; ++m) {
        const double* row = &f.values[std::size_t(f.wrapY(j - 1 + m)) * f.nx];
        double r = 0.0;
        for (int l = 0; l < 4; ++l)
            r += wx[l] * row[f.wrapX(i - 1 + l)];
        q += wy[m] * r;
    }
    const double q00 = f(i, j);
    const double q10 = f(i + 1, j);
    const double q01 = f(i, j + 1);
    const double q11 = f(i + 1, j + 1);
    const double lo = std::min(std::min(q00, q10), std::min(q01, q11));
    const double hi = std::max(std::max(q00, q10), std::max(q01, q11));
    return std::clamp(q, lo, hi);
}

} // namespace aurorawall::components::fluid_detail::simulation
