#include "components/fluid_detail/simulation/multigrid.h"

#include <cmath>
#include <cstddef>
#include <stdexcept>

namespace aurorawall::components::fluid_detail::simulation {

namespace {

// r = f − L p.
void residual(const PeriodicField& p, const PeriodicField& f, PeriodicField& r)
{
    const double ax = 1.0 / (p.hx * p.hx);
    const double ay = 1.0 / (p.hy * p.hy);
    for (int j = 0; j < p.ny; ++j)
        for (int i = 0; i < p.nx; ++i)
            r(i, j) = f(i, j) - ax * (p(i + 1, j) - 2.0 * p(i, j) + p(i - 1, j)) - ay * (p(i, j + 1) - 2.0 * p(i, j) + p(i, j - 1));
}

// Red-black Gauss–Seidel (Briggs et al. ch. 2 and 4): first the nodes with i + j even, then the
// odd ones, each solving its own equation of L p = f with the neighbours' latest values:
//   pᵢⱼ ← ((pᵢ₊₁ⱼ + pᵢ₋₁ⱼ)/hx² + (pᵢⱼ₊₁ + pᵢⱼ₋₁)/hy² − fᵢⱼ) / (2/hx² + 2/hy²).
// Unlike plain Jacobi, it damps the checkerboard mode (nx, ny even keep the colouring periodic).
void smoothRedBlack(PeriodicField& p, const PeriodicField& f, int sweeps)
{
    const double ax = 1.0 / (p.hx * p.hx);
    const double ay = 1.0 / (p.hy * p.hy);
    const double inverseDiagonal = 1.0 / (2.0 * ax + 2.0 * ay);
    for (int s = 0; s < sweeps; ++s)
        for (int colour = 0; colour < 2; ++colour)
            for (int j = 0; j < p.ny; ++j)
                for (int i = (j + colour) & 1; i < p.nx; i += 2)
                    p(i, j) = (ax * (p(i + 1, j) + p(i - 1, j)) + ay * (p(i, j + 1) + p(i, j - 1)) - f(i, j)) * inverseDiagonal;
}

// Full weighting (Briggs et al. ch. 3), coarse node (I, J) at fine node (2I, 2J):
//   c_IJ = (1/16) [4 f₂ᵢ,₂ⱼ + 2 (f₂ᵢ±₁,₂ⱼ + f₂ᵢ,₂ⱼ±₁) + f₂ᵢ±₁,₂ⱼ±₁].
void restrictFullWeighting(const PeriodicField& fine, PeriodicField& coarse)
{
    for (int J = 0; J < coarse.ny; ++J)
        for (int I = 0; I < coarse.nx; ++I) {
            const int i = 2 * I;
            const int j = 2 * J;
            coarse(I, J) = (4.0 * fine(i, j) + 2.0 * (fine(i + 1, j) + fine(i - 1, j) + fine(i, j + 1) + fine(i, j - 1)) +
                            fine(i + 1, j + 1) + fine(i - 1, j + 1) + fine(i + 1, j - 1) + fine(i - 1, j - 1)) /
                           16.0;
        }
}

// Bilinear prolongation (Briggs et al. ch. 3), added to the fine field:
//   f₂ᵢ,₂ⱼ += c_IJ, f₂ᵢ₊₁,₂ⱼ += (c_IJ + c_I+1,J)/2, f₂ᵢ,₂ⱼ₊₁ += (c_IJ + c_I,J+1)/2,
//   f₂ᵢ₊₁,₂ⱼ₊₁ += (c_IJ + c_I+1,J + c_I,J+1 + c_I+1,J+1)/4.
void prolongBilinearAdd(const PeriodicField& coarse, PeriodicField& fine)
{
    for (int J = 0; J < coarse.ny; ++J)
        for (int I = 0; I < coarse.nx; ++I) {
            const double c00 = coarse(I, J);
            const double c10 = coarse(I + 1, J);
            const double c01 = coarse(I, J + 1);
            const double c11 = coarse(I + 1, J + 1);
            fine(2 * I, 2 * J) += c00;
            fine(2 * I + 1, 2 * J) += 0.5 * (c00 + c10);
            fine(2 * I, 2 * J + 1) += 0.5 * (c00 + c01);
            fine(2 * I + 1, 2 * J + 1) += 0.25 * (c00 + c10 + c01 + c11);
        }
}

// Direct solve on the coarsest grid (N nodes): A = −L + s·(1/N)·11ᵀ with s = 2/hx² + 2/hy² is
// symmetric positive definite (the shift lifts the constant null vector of −L), and for a
// zero-mean f the solution of A p = −f is the zero-mean solution of L p = f. A = R Rᵀ by
// Cholesky (Golub & Van Loan, "Matrix Computations", alg. 4.2.1), then two triangular solves.
class CoarsestSolver {
public:
    explicit CoarsestSolver(const PeriodicField& grid)
        : n_(std::size_t(grid.nx) * std::size_t(grid.ny)), r_(n_ * n_, 0.0)
    {
        const double ax = 1.0 / (grid.hx * grid.hx);
        const double ay = 1.0 / (grid.hy * grid.hy);
        const double shift = (2.0 * ax + 2.0 * ay) / double(n_);
        for (std::size_t k = 0; k < n_; ++k)
            for (std::size_t l = 0; l < n_; ++l)
                r_[k * n_ + l] = shift;
        const auto index = [&](int i, int j) { return std::size_t(grid.wrapY(j)) * grid.nx + grid.wrapX(i); };
        for (int j = 0; j < grid.ny; ++j)
            for (int i = 0; i < grid.nx; ++i) {
                const std::size_t k = index(i, j);
                r_[k * n_ + k] += 2.0 * ax + 2.0 * ay;
                r_[k * n_ + index(i + 1, j)] -= ax;
                r_[k * n_ + index(i - 1, j)] -= ax;
                r_[k * n_ + index(i, j + 1)] -= ay;
                r_[k * n_ + index(i, j - 1)] -= ay;
            }
        for (std::size_t k = 0; k < n_; ++k) {
            for (std::size_t m = 0; m < k; ++m)
                r_[k * n_ + k] -= r_[k * n_ + m] * r_[k * n_ + m];
            r_[k * n_ + k] = std::sqrt(r_[k * n_ + k]);
            for (std::size_t l = k + 1; l < n_; ++l) {
                for (std::size_t m = 0; m < k; ++m)
                    r_[l * n_ + k] -= r_[l * n_ + m] * r_[k * n_ + m];
                r_[l * n_ + k] /= r_[k * n_ + k];
            }
        }
    }

    void solve(PeriodicField& p, const PeriodicField& f) const
    {
        std::vector<double> y(n_);
        for (std::size_t k = 0; k < n_; ++k) {
            double s = -f.values[k];
            for (std::size_t m = 0; m < k; ++m)
                s -= r_[k * n_ + m] * y[m];
            y[k] = s / r_[k * n_ + k];
        }
        for (std::size_t k = n_; k-- > 0;) {
            double s = y[k];
            for (std::size_t m = k + 1; m < n_; ++m)
                s -= r_[m * n_ + k] * p.values[m];
            p.values[k] = s / r_[k * n_ + k];
        }
    }

private:
    std::size_t n_;
    std::vector<double> r_; // lower triangle of R, row-major
};

// Level k + 1 of the hierarchy: the error and the restricted residual on the grid 2^(k+1) h.
struct CoarseLevel {
    PeriodicField error;
    PeriodicField rhs;
};

struct Hierarchy {
    std::vector<PeriodicField> residuals; // one per level above the coarsest
    std::vector<CoarseLevel> coarse;
};

// One V(ν₁,ν₂)-cycle on level `depth` (Briggs et al. ch. 3): smooth ν₁ times, restrict the
// residual, solve the coarse error equation L e = r recursively from e = 0, add the prolonged
// error, smooth ν₂ times. The coarsest level is solved directly.
void vCycle(PeriodicField& p, const PeriodicField& f, Hierarchy& h, const CoarsestSolver& coarsest, std::size_t depth,
            const MultigridSettings& settings)
{
    if (depth == h.coarse.size()) {
        coarsest.solve(p, f);
        return;
    }
    smoothRedBlack(p, f, settings.preSmoothing);
    residual(p, f, h.residuals[depth]);
    CoarseLevel& next = h.coarse[depth];
    restrictFullWeighting(h.residuals[depth], next.rhs);
    next.error.values.assign(next.error.values.size(), 0.0);
    vCycle(next.error, next.rhs, h, coarsest, depth + 1, settings);
    prolongBilinearAdd(next.error, p);
    smoothRedBlack(p, f, settings.postSmoothing);
}

} // namespace

MultigridReport solvePoisson(PeriodicField& p, const PeriodicField& f, const MultigridSettings& settings)
{
    if (p.nx != f.nx || p.ny != f.ny || p.hx != f.hx || p.hy != f.hy)
        throw std::invalid_argument("solvePoisson: p and f must share one grid");
    if (p.nx < 2 || p.ny < 2 || p.hx > 2.0 * p.hy || p.hy > 2.0 * p.hx)
        throw std::invalid_argument("solvePoisson: needs nx, ny >= 2 and cells with hx/hy in [1/2, 2]");

    PeriodicField rhs = f;
    rhs.subtractMean();

    Hierarchy h;
    PeriodicField grid(p.nx, p.ny, p.hx, p.hy);
    while (grid.nx >= 4 && grid.ny >= 4) {
        h.residuals.push_back(grid);
        grid = PeriodicField(grid.nx / 2, grid.ny / 2, 2.0 * grid.hx, 2.0 * grid.hy);
        h.coarse.push_back({grid, grid});
    }
    const CoarsestSolver coarsest(grid);

    MultigridReport report;
    report.rhsRms = rhs.rms();
    p.subtractMean();
    PeriodicField r(p.nx, p.ny, p.hx, p.hy);
    residual(p, rhs, r);
    report.residualRms.push_back(r.rms());
    while (report.residualRms.back() > settings.tolerance * report.rhsRms && report.cycles() < settings.maxCycles) {
        vCycle(p, rhs, h, coarsest, 0, settings);
        p.subtractMean();
        residual(p, rhs, r);
        report.residualRms.push_back(r.rms());
    }
    report.converged = report.residualRms.back() <= settings.tolerance * report.rhsRms;
    return report;
}

} // namespace aurorawall::components::fluid_detail::simulation
