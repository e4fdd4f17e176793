#pragma once
/// The mean annual rate of a damage state at a site: the fragility P(DS | x) integrated over
/// the hazard curve, lambda = integral of P(DS | x) |dH(x)| (Cornell & Krawinkler 2000), in
/// u = ln x, where the integrand P(u) k(u) H(u) is smooth between the hazard curve's points
/// (k the curve's log-log slope). Definitions and rules: docs/risk.md. Pure math: no I/O.
#include <span>

#include "rocksweep/records/fragility.hpp"
#include "rocksweep/risk/hazard_curve.hpp"

namespace rocksweep {

/// lambda [1/yr] and the parts of it that come from beyond the hazard curve's points, where
/// the curve is extrapolated (HazardCurve): `below` its first point, `above` its last.
struct RiskRate {
    double rate = 0.0;
    double below = 0.0;
    double above = 0.0;
};

/// For a lognormal fragility: Gauss-Legendre quadrature in ln x on pieces no wider than
/// beta / 4 between the hazard curve's points, from where the integrand has fallen below
/// 1e-17 of its peak (z = -k_max beta - 9) to z = +9, above which P = 1 to 1e-19 and the rest
/// is H there. Against the power-law closed form: at most 5e-15 relative over k = 1.2-4,
/// beta = 0.1-1.2, medians inside and beyond the curve (measured). beta = 0 (a step at the
/// median): lambda = H(median). A median of +inf gives 0; NaN gives NaN.
RiskRate annual_rate(const HazardCurve& h, const LognormalFragility& f);

/// For empirical fractions at increasing intensity levels: P linear in ln x between levels,
/// 0 below the first level (the suite ran nothing there) and the last fraction held above the
/// last level. NaN fractions (a level with no converged run) are skipped; all NaN gives NaN.
/// Throws std::invalid_argument for sizes that differ or levels not positive and increasing.
RiskRate annual_rate(const HazardCurve& h, std::span<const double> levels, std::span<const double> fractions);

/// The deaggregation: d lambda / d ln x = P(x) k(x) H(x) [1/yr per unit of ln x], the density
/// whose integral over ln x is lambda.
double rate_density(const HazardCurve& h, const LognormalFragility& f, double x);
double rate_density(const HazardCurve& h, std::span<const double> levels, std::span<const double> fractions, double x);

}  // namespace rocksweep
