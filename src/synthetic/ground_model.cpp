#include "rocksweep/synthetic/ground_model.hpp"

#include <cmath>
#include <sstream>

#include "gamma.hpp"
#include "rocksweep/core/errors.hpp"
#include "rocksweep/records/record.hpp"

namespace rocksweep::synthetic {
namespace {

// Shapes k = 2 alpha2 - 1 the envelope may take: below 0.2 the envelope is a spike at t = 0 with
// a tail (D5-95 / t_mid > 85), above 1e4 the envelope is a spike of relative width 3.3 / sqrt(k) = 3 %.
constexpr double k_min = 0.2, k_max = 1e4;

// D5-95 / t_mid of a gamma envelope of shape k: a decreasing function of k alone.
double duration_ratio(double k) {
    using detail::gamma_p_inverse;
    return (gamma_p_inverse(k, 0.95) - gamma_p_inverse(k, 0.05)) / gamma_p_inverse(k, 0.45);
}

}  // namespace

void check(const ModelParameters& p) {
    require_closed("arias", p.arias_m_s, 1e-8, 100.0, "an Arias intensity in [1e-8, 100] m/s");
    require_closed("d595", p.d595_s, 0.1, 1000.0, "a significant duration in [0.1, 1000] s");
    require_closed("tmid", p.tmid_s, 0.05, 1000.0, "a time in [0.05, 1000] s");
    require_closed("f-mid", p.f_mid_hz, filter_frequency_floor_hz, 50.0, "a frequency in [0.1, 50] Hz");
    require_closed("f-slope", p.f_slope_hz_s, -10.0, 10.0, "a drift in [-10, 10] Hz/s");
    require_closed("zeta", p.zeta_f, 0.01, 0.99, "a damping ratio in [0.01, 0.99]");
    require_closed("fc", p.fc_hz, 0.01, 10.0, "a corner frequency in [0.01, 10] Hz");
}

double Modulation::operator()(double t_s) const {
    if (t_s <= 0.0) return 0.0;  // the first sample is zero whatever alpha2 (docs/synthetic.md)
    return std::exp(log_alpha1 + (alpha2 - 1.0) * std::log(t_s) - alpha3 * t_s);
}

double Modulation::arias_fraction(double t_s) const { return detail::gamma_p(2.0 * alpha2 - 1.0, 2.0 * alpha3 * t_s); }

double Modulation::arias_time(double fraction) const {
    return detail::gamma_p_inverse(2.0 * alpha2 - 1.0, fraction) / (2.0 * alpha3);
}

Modulation modulation(const ModelParameters& p) {
    const double target = p.d595_s / p.tmid_s;
    const double r_lo = duration_ratio(k_max), r_hi = duration_ratio(k_min);
    if (!(target > r_lo && target < r_hi)) {
        std::ostringstream allowed;
        allowed << "D5-95 / t_mid = " << format_short(target, 4) << " must lie in (" << format_short(r_lo, 3) << ", "
                << format_short(r_hi, 3) << ") for a gamma envelope";
        throw InputError("d595", format_short(p.d595_s), allowed.str());
    }
    // Bisection on log k: the ratio falls monotonically as the envelope narrows.
    double lo = std::log(k_min), hi = std::log(k_max);
    for (int i = 0; i < 100 && hi - lo > 1e-13; ++i) {
        const double mid = 0.5 * (lo + hi);
        (duration_ratio(std::exp(mid)) > target ? lo : hi) = mid;
    }
    const double k = std::exp(0.5 * (lo + hi));
    Modulation m;
    m.alpha2 = 0.5 * (k + 1.0);
    m.alpha3 = detail::gamma_p_inverse(k, 0.45) / (2.0 * p.tmid_s);
    // I_a = pi / (2 g) alpha1^2 Gamma(k) / (2 alpha3)^k
    const double g = standard_gravity;
    const double log_alpha1 = 0.5 * (std::log(2.0 * g * p.arias_m_s / M_PI) + k * std::log(2.0 * m.alpha3) - std::lgamma(k));
    // Where alpha1 is a normal double, the log of its rounded value: the motions stay bitwise
    // those of the versions that stored alpha1 itself (and files made by them resume).
    const double alpha1 = std::exp(log_alpha1);
    m.log_alpha1 = std::isnormal(alpha1) ? std::log(alpha1) : log_alpha1;
    return m;
}

double default_duration_s(const ModelParameters& p) { return modulation(p).arias_time(0.9999) + 3.0 / p.fc_hz; }

std::string describe(const ModelParameters& p) {
    std::ostringstream s;
    s << "I_a = " << format_short(p.arias_m_s, 4) << " m/s, D5-95 = " << format_short(p.d595_s, 4)
      << " s, t_mid = " << format_short(p.tmid_s, 4) << " s, f_mid = " << format_short(p.f_mid_hz, 4)
      << " Hz, f' = " << format_short(p.f_slope_hz_s, 4) << " Hz/s, zeta_f = " << format_short(p.zeta_f, 4)
      << ", f_c = " << format_short(p.fc_hz, 4) << " Hz";
    return s.str();
}

}  // namespace rocksweep::synthetic
