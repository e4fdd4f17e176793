#include "rocksweep/records/stripe_clusters.hpp"

#include <cmath>
#include <stdexcept>

#include "fit_detail.hpp"

namespace rocksweep {

// P = Phi(z), z = a + b ln x with b = 1 / beta, a = -ln(median) / beta: the parameters the
// likelihood is smooth in. The variance of a smooth function of them is the same whatever
// parameters it is computed in (the delta method is invariant), so fit_stripes' centring is
// not needed here.
StripeClusters::StripeClusters(const FragilityFit& fit, std::vector<double> intensities) : fit_(fit) {
    for (double x : intensities)
        if (!(x > 0.0) || !std::isfinite(x)) throw std::invalid_argument("StripeClusters: an intensity must be positive and finite");
    active_ = fit.status == FitStatus::ok && fit.curve.beta > 0.0 && std::isfinite(fit.curve.beta) &&
              std::isfinite(fit.se_beta) && fit.se_beta > 0.0;
    const double b = 1.0 / fit.curve.beta, a = -std::log(fit.curve.median) * b;
    for (double x : intensities) {
        const double u = std::log(x), z = a + b * u;
        ln_x_.push_back(u);
        score_reached_.push_back(active_ ? fit_detail::probit_term(z, 1, 0).d1 : 0.0);
        score_missed_.push_back(active_ ? fit_detail::probit_term(z, 0, 1).d1 : 0.0);
    }
}

void StripeClusters::add(std::span<const std::int8_t> outcome) {
    if (outcome.size() != ln_x_.size()) throw std::invalid_argument("StripeClusters::add: one outcome per level");
    double g0 = 0.0, g1 = 0.0;
    for (std::size_t l = 0; l < outcome.size(); ++l) {
        if (outcome[l] < 0) continue;
        const double s = outcome[l] > 0 ? score_reached_[l] : score_missed_[l];
        g0 += s;
        g1 += s * ln_x_[l];
    }
    m00_ += g0 * g0;
    m01_ += g0 * g1;
    m11_ += g1 * g1;
    ++records_;
}

FragilityFit StripeClusters::corrected(std::span<const Stripe> stripes) const {
    if (!active_ || records_ < 2) return fit_;
    // The Hessian of the pooled log-likelihood at the fit.
    const double b = 1.0 / fit_.curve.beta, a = -std::log(fit_.curve.median) * b;
    double h00 = 0.0, h01 = 0.0, h11 = 0.0;
    for (const Stripe& s : stripes) {
        const double u = std::log(s.intensity), z = a + b * u;
        const double d2 = fit_detail::probit_term(z, s.exceed, s.total - s.exceed).d2;
        h00 += d2;
        h01 += d2 * u;
        h11 += d2 * u * u;
    }
    const double det = h00 * h11 - h01 * h01;
    if (!(h00 < 0.0 && det > 0.0)) return fit_;
    // H^-1 = [[h11, -h01], [-h01, h00]] / det; V = H^-1 M H^-1 (G / (G - 1)).
    const double i00 = h11 / det, i01 = -h01 / det, i11 = h00 / det;
    const double k = static_cast<double>(records_) / static_cast<double>(records_ - 1);
    // Of two functions with gradients j and q in (a, b): (H^-1 j)^T M (H^-1 q).
    auto covariance = [&](double j0, double j1, double q0, double q1) {
        const double w0 = i00 * j0 + i01 * j1, w1 = i01 * j0 + i11 * j1;
        const double v0 = i00 * q0 + i01 * q1, v1 = i01 * q0 + i11 * q1;
        return k * (w0 * v0 * m00_ + (w0 * v1 + w1 * v0) * m01_ + w1 * v1 * m11_);
    };
    const double m0 = -1.0 / b, m1 = a / (b * b), b1 = -1.0 / (b * b);  // ln median = -a / b, beta = 1 / b
    FragilityFit f = fit_;
    f.se_ln_median = std::sqrt(covariance(m0, m1, m0, m1));
    f.se_beta = std::sqrt(covariance(0.0, b1, 0.0, b1));
    f.cov_ln_median_beta = covariance(m0, m1, 0.0, b1);
    fit_detail::intervals(f);
    return f;
}

}  // namespace rocksweep
