#pragma once
// The sizes of a cloud's droplets: one radius, or Hansen & Travis's gamma distribution
// (Hansen & Travis 1974, "Light scattering in planetary atmospheres", Space Sci. Rev. 16, 527, eq. 2.56)
//   n(r) ∝ r^((1−3v)/v) e^(−r/(a v)),
// with a the effective radius (the mean radius weighted by the geometric cross-section πr²) and v the
// effective variance (the cross-section-weighted variance of r, divided by a²); as v → 0 it narrows to
// the single radius a.
#include <utility>

namespace aurorawall::components::glory::mie {

class DropSizeDistribution {
public:
    // All drops of radius r > 0 (µm).
    static DropSizeDistribution singleSize(double radiusUm);
    // Effective radius a > 0 (µm), effective variance 0 < v < 0.5 (n(r) is integrable at r = 0 only for
    // v < 0.5).
    static DropSizeDistribution gamma(double effectiveRadiusUm, double effectiveVariance);

    bool isSingleSize() const { return variance_ == 0.0; }
    double effectiveRadiusUm() const { return radius_; }
    double effectiveVariance() const { return variance_; }

    // ln n(r) up to a constant: zero at the mode (gamma only).
    double logDensity(double radiusUm) const;

    // The radii (µm) outside which the drops hold less than 1e-12 of the size average: below the lower one,
    // 1e-12 of ∫ n(r) r² dr (a cross-section ~ r² or less); above the upper one, 1e-12 of ∫ n(r) r⁴ dr
    // (the forward scattering peak ~ r⁴, the heaviest-tailed weight the average meets).
    std::pair<double, double> radiusRangeUm() const;

private:
    DropSizeDistribution(double radius, double variance) : radius_(radius), variance_(variance) {}
    double shape() const { return (1.0 - 3.0 * variance_) / variance_; } // exponent of r
    double scaleUm() const { return radius_ * variance_; }               // e-folding radius a·v
    double radius_;
    double variance_;
};

} // namespace aurorawall::components::glory::mie
