#include "gamma.hpp"

#include <cmath>
#include <limits>

namespace rocksweep::synthetic::detail {
namespace {

// x^a e^-x / Gamma(a), the factor both expansions share.
double prefactor(double a, double x) { return std::exp(a * std::log(x) - x - std::lgamma(a)); }

// Series, converges fast for x < a + 1.
double p_series(double a, double x) {
    double term = 1.0 / a, sum = term;
    for (int n = 1; n < 10000; ++n) {
        term *= x / (a + n);
        sum += term;
        if (std::abs(term) < std::abs(sum) * 1e-16) break;
    }
    return sum * prefactor(a, x);
}

// Continued fraction for Q = 1 - P (modified Lentz), for x >= a + 1.
double q_fraction(double a, double x) {
    constexpr double tiny = 1e-300;
    double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
    for (int i = 1; i < 10000; ++i) {
        const double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        if (std::abs(d) < tiny) d = tiny;
        c = b + an / c;
        if (std::abs(c) < tiny) c = tiny;
        d = 1.0 / d;
        const double delta = d * c;
        h *= delta;
        if (std::abs(delta - 1.0) < 1e-16) break;
    }
    return prefactor(a, x) * h;
}

}  // namespace

double gamma_p(double a, double x) {
    if (x <= 0.0) return 0.0;
    return x < a + 1.0 ? p_series(a, x) : 1.0 - q_fraction(a, x);
}

double gamma_p_inverse(double a, double p) {
    // Bracket, then bisect: a few hundred evaluations at most, and only when a model is set up.
    double lo = 0.0, hi = a + 1.0;
    while (gamma_p(a, hi) < p) {
        lo = hi;
        hi *= 2.0;
    }
    for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i) {
        const double mid = 0.5 * (lo + hi);
        (gamma_p(a, mid) < p ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

}  // namespace rocksweep::synthetic::detail
