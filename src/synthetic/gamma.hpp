#pragma once
// Regularised lower incomplete gamma function and its inverse: the cumulative Arias intensity
// of the gamma-shaped envelope. Private to the synthetic layer.

namespace rocksweep::synthetic::detail {

/// P(a, x) = gamma(a, x) / Gamma(a), a > 0, x >= 0.
double gamma_p(double a, double x);
/// The x >= 0 with P(a, x) = p, p in (0, 1).
double gamma_p_inverse(double a, double p);

}  // namespace rocksweep::synthetic::detail
