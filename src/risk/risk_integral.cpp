#include "rocksweep/risk/risk_integral.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <vector>

namespace rocksweep {

namespace {

// 10-point Gauss-Legendre on [-1, 1]: exact for polynomials of degree 19.
constexpr double gl_node[5] = {0.1488743389816312, 0.4333953941292472, 0.6794095682990244, 0.8650633666889845,
                               0.9739065285171717};
constexpr double gl_weight[5] = {0.2955242247147529, 0.2692667193099963, 0.2190863625159820, 0.1494513491505806,
                                 0.0666713443086881};

/// Where a piece [a, b] of ln x lies against the hazard curve's points ln x_1, ln x_n.
void add_piece(RiskRate& r, double value, double a, double b, double u_first, double u_last) {
    r.rate += value;
    if (b <= u_first) r.below += value;
    else if (a >= u_last) r.above += value;
}

/// integral of P(u) k(u) H(u) du over [u_lo, u_hi], on pieces no wider than `width` between
/// `breaks` (which must hold every hazard point inside, where k jumps), plus a tail above u_hi
/// where P is the constant `p_tail`: p_tail H(u_hi).
RiskRate integrate(const HazardCurve& h, const std::function<double(double)>& p, double u_lo, double u_hi,
                   std::vector<double> breaks, double width, double p_tail) {
    const double u_first = std::log(h.intensity().front()), u_last = std::log(h.intensity().back());
    for (const double x : h.intensity()) breaks.push_back(std::log(x));
    breaks.push_back(u_lo);
    breaks.push_back(u_hi);
    std::sort(breaks.begin(), breaks.end());
    RiskRate r;
    for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
        const double a = std::max(breaks[i], u_lo), b = std::min(breaks[i + 1], u_hi);
        if (!(b > a)) continue;
        const int n = std::max(1, static_cast<int>(std::ceil((b - a) / width)));
        const double step = (b - a) / n;
        // One slope per piece: evaluate it at the middle, away from the break that ends it.
        const double k = h.slope_at(std::exp(a + 0.5 * (b - a)));
        double piece = 0.0;
        for (int j = 0; j < n; ++j) {
            const double c = a + (j + 0.5) * step, half = 0.5 * step;
            double sum = 0.0;
            for (int q = 0; q < 5; ++q)
                for (const double s : {-1.0, 1.0}) {
                    const double u = c + s * half * gl_node[q];
                    sum += gl_weight[q] * p(u) * h.rate_at(std::exp(u));
                }
            piece += k * half * sum;
        }
        // Classified by the interval between breaks, whose ends are the curve's points exactly.
        add_piece(r, piece, a, b, u_first, u_last);
    }
    if (p_tail > 0) {
        // p_tail (H(u_hi) - H(max(u_hi, u_last))) inside the curve, the rest beyond it.
        const double h_hi = h.rate_at(std::exp(u_hi)), h_end = h.rate_at(std::exp(std::max(u_hi, u_last)));
        r.rate += p_tail * h_hi;
        r.above += p_tail * h_end;
        if (u_hi < u_first) r.below += p_tail * (h_hi - h.rate_at(std::exp(u_first)));
    }
    return r;
}

/// The usable (level, fraction) pairs: NaN fractions dropped.
void usable(std::span<const double> levels, std::span<const double> fractions, std::vector<double>& u,
            std::vector<double>& p) {
    if (levels.size() != fractions.size()) throw std::invalid_argument("annual_rate: as many fractions as levels");
    for (std::size_t i = 0; i < levels.size(); ++i) {
        if (!(levels[i] > 0 && std::isfinite(levels[i])) || (i > 0 && !(levels[i] > levels[i - 1])))
            throw std::invalid_argument("annual_rate: levels positive, finite and increasing");
        if (std::isnan(fractions[i])) continue;
        u.push_back(std::log(levels[i]));
        p.push_back(fractions[i]);
    }
}

/// P linear in u between the levels, 0 below the first, the last one held above.
double piecewise(const std::vector<double>& u, const std::vector<double>& p, double x) {
    if (x < u.front()) return 0.0;
    if (x >= u.back()) return p.back();
    const std::size_t i = static_cast<std::size_t>(std::upper_bound(u.begin(), u.end(), x) - u.begin()) - 1;
    const double t = (x - u[i]) / (u[i + 1] - u[i]);
    return p[i] + t * (p[i + 1] - p[i]);
}

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

}  // namespace

RiskRate annual_rate(const HazardCurve& h, const LognormalFragility& f) {
    if (f.median == std::numeric_limits<double>::infinity()) return {};  // never reached: no rate
    if (std::isnan(f.median) || std::isnan(f.beta)) return {nan, nan, nan};
    const double x_first = h.intensity().front(), x_last = h.intensity().back();
    if (f.beta == 0) {
        // A step at the median: every exceedance of it counts, lambda = H(median).
        const double total = h.rate_at(f.median);
        return {total, f.median < x_first ? total - h.rate_at(x_first) : 0.0, h.rate_at(std::max(f.median, x_last))};
    }
    const double m = std::log(f.median), beta = f.beta;
    // Below z = -k beta - 9 the integrand Phi(z) e^{-k beta z} is under e^{-40} of its peak.
    const double u_lo = m + beta * (-h.max_slope() * beta - 9.0), u_hi = m + 9.0 * beta;
    const auto p = [&](double u) { return normal_cdf((u - m) / beta); };
    return integrate(h, p, u_lo, u_hi, {}, std::min(0.25, beta / 4), 1.0);
}

RiskRate annual_rate(const HazardCurve& h, std::span<const double> levels, std::span<const double> fractions) {
    std::vector<double> u, p;
    usable(levels, fractions, u, p);
    if (u.empty()) return {nan, nan, nan};
    if (u.size() == 1) return integrate(h, [](double) { return 0.0; }, u[0], u[0], {}, 0.25, p[0]);
    const auto pu = [&](double x) { return piecewise(u, p, x); };
    return integrate(h, pu, u.front(), u.back(), u, 0.25, p.back());
}

double rate_density(const HazardCurve& h, const LognormalFragility& f, double x) {
    return f.probability(x) * h.slope_at(x) * h.rate_at(x);
}

double rate_density(const HazardCurve& h, std::span<const double> levels, std::span<const double> fractions, double x) {
    std::vector<double> u, p;
    usable(levels, fractions, u, p);
    if (u.empty()) return nan;
    return piecewise(u, p, std::log(x)) * h.slope_at(x) * h.rate_at(x);
}

}  // namespace rocksweep
