#include "rocksweep/records/fragility.hpp"

#include "fit_detail.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace rocksweep {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kZ95 = 1.959963984540054;  // Phi^-1(0.975)
constexpr double kLnSqrt2Pi = 0.91893853320467274;

using fit_detail::intervals;
using fit_detail::log_cdf;
using fit_detail::mills;

/// A concave function of two parameters near a point: value, gradient and Hessian.
struct Local {
    double f = 0.0, g0 = 0.0, g1 = 0.0, h00 = 0.0, h01 = 0.0, h11 = 0.0;
    void add(double fk, double d1, double d2, double v) {  // a term of (x0 + v x1) with f', f''
        f += fk;
        g0 += d1;
        g1 += v * d1;
        h00 += d2;
        h01 += v * d2;
        h11 += v * v * d2;
    }
};

/// Maximises a concave function by Newton's method with step halving (Armijo). `eval(x0, x1,
/// out)` returns false outside the domain. With `fix1`, x1 stays put. Returns the iterations.
template <class Eval>
int maximise(Eval&& eval, double& x0, double& x1, bool fix1, Local& at) {
    if (!eval(x0, x1, at)) throw std::logic_error("fragility fit: starting point outside the domain");
    for (int it = 1; it <= 200; ++it) {
        double d0, d1 = 0.0;
        const double det = at.h00 * at.h11 - at.h01 * at.h01;
        if (fix1) {
            d0 = at.h00 < 0.0 ? -at.g0 / at.h00 : at.g0;
        } else if (at.h00 < 0.0 && det > 0.0) {  // negative definite: the Newton step
            d0 = -(at.h11 * at.g0 - at.h01 * at.g1) / det;
            d1 = -(at.h00 * at.g1 - at.h01 * at.g0) / det;
        } else {  // rounding made the Hessian indefinite: go uphill along the gradient
            d0 = at.g0;
            d1 = at.g1;
        }
        const double slope = at.g0 * d0 + at.g1 * d1;  // >= 0
        if (!(slope > 1e-14 * (1.0 + std::abs(at.f)))) return it;
        Local trial;
        double t = 1.0;
        bool uphill = false;
        for (int k = 0; k < 80 && !uphill; ++k) {
            uphill = eval(x0 + t * d0, x1 + t * d1, trial) && trial.f >= at.f + 1e-4 * t * slope;
            if (!uphill) t *= 0.5;
        }
        if (!uphill) return it;  // no progress left at this precision: the maximum
        x0 += t * d0;
        x1 += t * d1;
        at = trial;
    }
    throw std::runtime_error("fragility fit: Newton's method did not converge in 200 iterations");
}

void check_intensity(double x, const char* what) {
    if (!(x > 0.0) || !std::isfinite(x))
        throw std::invalid_argument(std::string(what) + ": an intensity must be positive and finite");
}

/// A fit with only its status and point estimates; every uncertainty NaN.
FragilityFit limit_fit(FitStatus s, double median, double beta) {
    FragilityFit f;
    f.status = s;
    f.curve = {median, beta};
    f.se_ln_median = f.se_beta = f.cov_ln_median_beta = f.median_lo = f.median_hi = f.beta_lo = f.beta_hi = f.log_likelihood = kNaN;
    return f;
}

/// Covariance of two smooth functions of (x0, x1) with gradients j and k, from the inverse of
/// the negative Hessian (the observed information): j^T (-H)^-1 k.
double delta_covariance(const Local& at, double j0, double j1, double k0, double k1, bool fix1) {
    if (fix1) return j0 * k0 / -at.h00;
    const double det = at.h00 * at.h11 - at.h01 * at.h01;
    // (-H)^-1 = [[-h11, h01], [h01, -h00]] / det
    return (-at.h11 * j0 * k0 + at.h01 * (j0 * k1 + j1 * k0) - at.h00 * j1 * k1) / det;
}

double delta_variance(const Local& at, double j0, double j1, bool fix1) {
    return delta_covariance(at, j0, j1, j0, j1, fix1);
}

}  // namespace

namespace fit_detail {

void intervals(FragilityFit& f) {
    const double m = f.curve.median, b = f.curve.beta;
    f.median_lo = m * std::exp(-kZ95 * f.se_ln_median);
    f.median_hi = m * std::exp(kZ95 * f.se_ln_median);
    f.beta_lo = b * std::exp(-kZ95 * f.se_beta / b);
    f.beta_hi = b * std::exp(kZ95 * f.se_beta / b);
}

/// ln Phi(z), accurate in both tails: erfc where Phi is representable, the asymptotic series
/// Phi(z) ~ phi(z) / |z| (1 - 1/z^2 + 3/z^4 - 15/z^6) below z = -35 (relative error < 1e-10).
double log_cdf(double z) {
    if (z > 0.0) return std::log1p(-0.5 * std::erfc(z / M_SQRT2));
    if (z >= -35.0) return std::log(0.5 * std::erfc(-z / M_SQRT2));
    const double r = 1.0 / (z * z);
    return -0.5 * z * z - kLnSqrt2Pi - std::log(-z) + std::log1p(-r + 3 * r * r - 15 * r * r * r);
}

/// The inverse Mills ratio phi(z) / Phi(z): d ln Phi / dz.
double mills(double z) { return std::exp(-0.5 * z * z - kLnSqrt2Pi - log_cdf(z)); }

ProbitTerm probit_term(double z, double reached, double missed) {
    ProbitTerm t;
    if (reached > 0) {
        const double l = mills(z);
        t.f += reached * log_cdf(z);
        t.d1 += reached * l;
        t.d2 -= reached * l * (l + z);
    }
    if (missed > 0) {
        const double l = mills(-z);
        t.f += missed * log_cdf(-z);
        t.d1 -= missed * l;
        t.d2 -= missed * l * (l - z);
    }
    return t;
}

}  // namespace fit_detail

double normal_cdf(double z) { return 0.5 * std::erfc(-z / M_SQRT2); }

double LognormalFragility::probability(double x) const {
    if (beta == 0.0) return x >= median ? 1.0 : 0.0;
    return normal_cdf(std::log(x / median) / beta);
}

std::string to_string(FitStatus s) {
    switch (s) {
        case FitStatus::ok: return "ok";
        case FitStatus::none_reached: return "none_reached";
        case FitStatus::all_reached: return "all_reached";
        case FitStatus::zero_dispersion: return "zero_dispersion";
        case FitStatus::not_identifiable: return "not_identifiable";
        case FitStatus::decreasing: return "decreasing";
    }
    return "?";
}

FragilityFit fit_capacities(std::span<const Capacity> capacities) {
    if (capacities.empty()) throw std::invalid_argument("fit_capacities: no capacities");
    std::vector<double> y, yc;  // ln of the uncensored and of the censored capacities
    for (const Capacity& c : capacities) {
        check_intensity(c.intensity, "fit_capacities");
        (c.censored ? yc : y).push_back(std::log(c.intensity));
    }
    if (y.empty()) return limit_fit(FitStatus::none_reached, INFINITY, kNaN);
    const double n = static_cast<double>(y.size());
    double mean = 0.0, ss = 0.0;
    for (double v : y) mean += v / n;
    for (double v : y) ss += (v - mean) * (v - mean);
    const double y_max = *std::max_element(y.begin(), y.end());
    const bool any_above = std::any_of(yc.begin(), yc.end(), [&](double v) { return v > y_max; });
    if (ss == 0.0 && !any_above) return limit_fit(FitStatus::zero_dispersion, std::exp(mean), 0.0);

    FragilityFit f;
    if (yc.empty()) {  // closed form: the normal MLE of ln c
        const double beta = std::sqrt(ss / n);
        f.curve = {std::exp(mean), beta};
        f.se_ln_median = beta / std::sqrt(n);
        f.se_beta = beta / std::sqrt(2.0 * n);
        f.log_likelihood = -n * (std::log(beta) + kLnSqrt2Pi + 0.5);
        intervals(f);
        return f;
    }
    // Censored: Olsen's parameters delta = mu / beta, gamma = 1 / beta on ln c centred at the
    // uncensored mean, where the log-likelihood is concave.
    auto eval = [&](double delta, double gamma, Local& at) {
        if (!(gamma > 0.0)) return false;
        at = Local{};
        for (double v : y) {  // ln gamma - r^2 / 2 - ln sqrt(2 pi), r = gamma y - delta
            const double r = gamma * (v - mean) - delta;
            at.f += std::log(gamma) - 0.5 * r * r - kLnSqrt2Pi;
            at.g0 += r;
            at.g1 += 1.0 / gamma - r * (v - mean);
            at.h00 += -1.0;
            at.h01 += v - mean;
            at.h11 += -1.0 / (gamma * gamma) - (v - mean) * (v - mean);
        }
        for (double v : yc) {  // ln P(capacity > c) = ln Phi(w), w = delta - gamma y
            const double w = delta - gamma * (v - mean), l = mills(w), d2 = -l * (l + w);
            at.add(log_cdf(w), l, d2, -(v - mean));
        }
        return std::isfinite(at.f);
    };
    double delta = 0.0, gamma = ss > 0.0 ? 1.0 / std::sqrt(ss / n) : 1.0;
    if (ss == 0.0)  // one distinct uncensored value: scale by the censored ones above it
        for (double v : yc) gamma = std::min(gamma, 1.0 / std::max(v - mean, 1e-3));
    Local at;
    f.iterations = maximise(eval, delta, gamma, false, at);
    f.curve = {std::exp(mean + delta / gamma), 1.0 / gamma};
    f.log_likelihood = at.f;
    // ln median = mean + delta / gamma, beta = 1 / gamma
    const double j0 = 1.0 / gamma, j1 = -delta / (gamma * gamma), k1 = -1.0 / (gamma * gamma);
    f.se_ln_median = std::sqrt(delta_variance(at, j0, j1, false));
    f.se_beta = std::sqrt(delta_variance(at, 0.0, k1, false));
    f.cov_ln_median_beta = delta_covariance(at, j0, j1, 0.0, k1, false);
    intervals(f);
    return f;
}

void wilson_interval(const Stripe& s, double& lo, double& hi) {
    const double n = s.total, p = s.fraction(), z2 = kZ95 * kZ95;
    const double centre = (p + z2 / (2 * n)) / (1 + z2 / n);
    const double half = kZ95 * std::sqrt(p * (1 - p) / n + z2 / (4 * n * n)) / (1 + z2 / n);
    lo = std::max(0.0, centre - half);
    hi = std::min(1.0, centre + half);
}

FragilityFit fit_stripes(std::span<const Stripe> stripes, double fixed_beta) {
    if (stripes.empty()) throw std::invalid_argument("fit_stripes: no stripes");
    if (!(fixed_beta >= 0.0) || !std::isfinite(fixed_beta))
        throw std::invalid_argument("fit_stripes: fixed_beta must be finite and >= 0 (0: beta is fitted)");
    const bool fix = fixed_beta > 0.0;
    double u_bar = 0.0, weight = 0.0;
    double safe_max = -INFINITY, reached_min = INFINITY;  // highest x with n < N, lowest with n > 0
    double x_lo = INFINITY, x_hi = -INFINITY;
    for (const Stripe& s : stripes) {
        check_intensity(s.intensity, "fit_stripes");
        if (s.total < 1 || s.exceed < 0 || s.exceed > s.total)
            throw std::invalid_argument("fit_stripes: counts must satisfy 0 <= n <= N, N >= 1");
        u_bar += s.total * std::log(s.intensity);
        weight += s.total;
        if (s.exceed < s.total) safe_max = std::max(safe_max, s.intensity);
        if (s.exceed > 0) reached_min = std::min(reached_min, s.intensity);
        x_lo = std::min(x_lo, s.intensity);
        x_hi = std::max(x_hi, s.intensity);
    }
    u_bar /= weight;
    const double beta_out = fix ? fixed_beta : kNaN;
    if (reached_min == INFINITY) return limit_fit(FitStatus::none_reached, INFINITY, beta_out);
    if (safe_max == -INFINITY) return limit_fit(FitStatus::all_reached, 0.0, beta_out);
    if (!fix && x_lo == x_hi) return limit_fit(FitStatus::not_identifiable, kNaN, kNaN);
    if (!fix && reached_min > safe_max)
        return limit_fit(FitStatus::zero_dispersion, std::sqrt(reached_min * safe_max), 0.0);
    if (!fix && reached_min == safe_max) return limit_fit(FitStatus::zero_dispersion, reached_min, 0.0);

    // P = Phi(a + b v), v = ln x - u_bar: the probit likelihood, concave in (a, b).
    auto eval = [&](double a, double b, Local& at) {
        at = Local{};
        for (const Stripe& s : stripes) {
            const double v = std::log(s.intensity) - u_bar, z = a + b * v;
            const fit_detail::ProbitTerm t = fit_detail::probit_term(z, s.exceed, s.total - s.exceed);
            at.add(t.f, t.d1, t.d2, v);
        }
        return std::isfinite(at.f);
    };
    double spread = 0.0;
    for (const Stripe& s : stripes) spread = std::max(spread, std::abs(std::log(s.intensity) - u_bar));
    double a = 0.0, b = fix ? 1.0 / fixed_beta : 1.0 / std::max(spread, 0.1);
    Local at;
    FragilityFit f;
    f.iterations = maximise(eval, a, b, fix, at);
    if (!(b > 0.0)) return limit_fit(FitStatus::decreasing, kNaN, kNaN);
    f.curve = {std::exp(u_bar - a / b), 1.0 / b};
    f.log_likelihood = at.f;
    // ln median = u_bar - a / b, beta = 1 / b
    f.se_ln_median = std::sqrt(delta_variance(at, -1.0 / b, a / (b * b), fix));
    f.se_beta = fix ? 0.0 : std::sqrt(delta_variance(at, 0.0, -1.0 / (b * b), false));
    f.cov_ln_median_beta = fix ? 0.0 : delta_covariance(at, -1.0 / b, a / (b * b), 0.0, -1.0 / (b * b), false);
    intervals(f);
    return f;
}

std::string DamageState::name() const {
    if (overturning) return "overturning";
    char buf[64];
    std::snprintf(buf, sizeof buf, "rotation>=%g", rotation_ratio);
    return buf;
}

std::vector<DamageState> default_damage_states() {
    return {{0.1, false}, {0.3, false}, {0.5, false}, {0.0, true}};
}

bool reaches(const IdaPoint& run, const DamageState& state) {
    return run.overturned || (!state.overturning && run.max_rotation >= state.rotation_ratio);
}

std::vector<Stripe> stripes_from_runs(std::span<const IdaPoint> runs, const DamageState& state) {
    std::vector<IdaPoint> sorted(runs.begin(), runs.end());
    for (const IdaPoint& p : sorted) check_intensity(p.intensity, "stripes_from_runs");
    std::sort(sorted.begin(), sorted.end(), [](const IdaPoint& a, const IdaPoint& b) { return a.intensity < b.intensity; });
    std::vector<Stripe> stripes;
    for (const IdaPoint& p : sorted) {
        if (stripes.empty() || stripes.back().intensity != p.intensity) stripes.push_back({p.intensity, 0, 0});
        ++stripes.back().total;
        stripes.back().exceed += reaches(p, state) ? 1 : 0;
    }
    return stripes;
}

IdaCapacity ida_capacity(std::span<const IdaPoint> curve, const DamageState& state) {
    if (curve.empty()) throw std::invalid_argument("ida_capacity: empty curve");
    for (std::size_t k = 0; k < curve.size(); ++k) {
        check_intensity(curve[k].intensity, "ida_capacity");
        if (k > 0 && !(curve[k].intensity > curve[k - 1].intensity))
            throw std::invalid_argument("ida_capacity: intensities must increase strictly");
    }
    IdaCapacity c;
    const auto first = std::find_if(curve.begin(), curve.end(), [&](const IdaPoint& p) { return reaches(p, state); });
    if (first == curve.end()) {
        c.first_level = c.below = kNaN;
        c.capacity = {curve.back().intensity, true};
        return c;
    }
    const std::size_t k = static_cast<std::size_t>(first - curve.begin());
    c.reached = true;
    c.first_level = curve[k].intensity;
    c.below = k > 0 ? curve[k - 1].intensity : kNaN;
    c.capacity = {c.first_level, false};
    if (k > 0 && !state.overturning && !curve[k].overturned) {
        // theta_max / alpha is continuous in the scale until overturning: interpolate its crossing.
        const IdaPoint &p0 = curve[k - 1], &p1 = curve[k];
        const double u = (state.rotation_ratio - p0.max_rotation) / (p1.max_rotation - p0.max_rotation);
        c.capacity.intensity = p0.intensity + u * (p1.intensity - p0.intensity);
    }
    c.safe_above = std::any_of(first + 1, curve.end(), [&](const IdaPoint& p) { return !reaches(p, state); });
    return c;
}

}  // namespace rocksweep
