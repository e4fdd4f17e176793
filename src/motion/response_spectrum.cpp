#include "rocksweep/motion/response_spectrum.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rocksweep::motion {

namespace {

// The oscillator's response inside one step from (u0, v0) under a(tau) = a0 + slope tau, in
// closed form (Nigam & Jennings 1969): a decaying oscillation about the particular solution
// A + B tau of the linear input.
class StepResponse {
public:
    StepResponse(const Oscillator& o, OscillatorState x0, double a0, double slope) : a0_(a0), slope_(slope) {
        const double w = o.omega();
        k_ = w * w;
        zw_ = o.damping * w;
        wd_ = w * std::sqrt(1.0 - o.damping * o.damping);
        b_ = -slope / k_;
        a_ = (-a0 - 2.0 * zw_ * b_) / k_;
        c1_ = x0.u - a_;
        c2_ = (x0.v - b_ + zw_ * c1_) / wd_;
    }
    OscillatorState at(double tau) const {
        const double e = std::exp(-zw_ * tau), c = std::cos(wd_ * tau), s = std::sin(wd_ * tau);
        return {e * (c1_ * c + c2_ * s) + a_ + b_ * tau, e * ((wd_ * c2_ - zw_ * c1_) * c - (wd_ * c1_ + zw_ * c2_) * s) + b_};
    }
    /// A bound on |u| over [0, h], from the closed form (|exp(-zeta w tau)| <= 1), widened well
    /// beyond the rounding of at(): where it does not exceed a peak, no |u| inside can.
    double bound(double h) const {
        return (std::sqrt(c1_ * c1_ + c2_ * c2_) + std::abs(a_) + std::abs(b_) * h) * (1.0 + 1e-9);
    }
    /// u'' = -a - 2 zeta w v - w^2 u
    double acceleration(double tau, const OscillatorState& x) const {
        return -(a0_ + slope_ * tau) - 2.0 * zw_ * x.v - k_ * x.u;
    }

private:
    double a0_, slope_, k_, zw_, wd_, a_, b_, c1_, c2_;
};

// |u| where v, of sign v_lo at lo and the other sign at hi, is zero: Newton's steps on the
// closed form (v' = u''), kept inside the bracket, which each step narrows; a bisection when a
// step would leave it. A few steps reach the last bits of tau.
double interior_peak(const StepResponse& r, double lo, double hi, double v_lo, double v_hi) {
    double tau = lo + (hi - lo) * v_lo / (v_lo - v_hi);
    for (int k = 0; k < 60; ++k) {
        const OscillatorState x = r.at(tau);
        if (x.v == 0.0) return std::abs(x.u);
        ((x.v > 0.0) == (v_lo > 0.0) ? lo : hi) = tau;
        const double slope = r.acceleration(tau, x);
        double next = slope != 0.0 ? tau - x.v / slope : 0.5 * (lo + hi);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        if (std::abs(next - tau) <= 4e-16 * hi || hi - lo <= 4e-16 * hi) return std::abs(r.at(next).u);
        tau = next;
    }
    return std::abs(r.at(tau).u);
}

}  // namespace

double spectral_acceleration(std::span<const double> a, double dt_s, const Oscillator& o) {
    if (a.size() < 2) throw std::invalid_argument("spectral_acceleration: at least two samples");
    const ExactStep step(o, dt_s);
    // Pieces of at most T/8 in a step: v has at most one zero in each (its zeros are ~T/2 apart).
    // Their states come from the exact map of a piece (no transcendental function per piece);
    // the closed form is evaluated only where v changes sign.
    const int pieces = std::max(1, static_cast<int>(std::ceil(8.0 * dt_s / o.period_s)));
    const ExactStep piece(o, dt_s / pieces);
    OscillatorState x;
    double peak = 0.0;
    for (std::size_t i = 1; i < a.size(); ++i) {
        const double a0 = a[i - 1], a1 = a[i], slope = (a1 - a0) / dt_s;
        const OscillatorState next = step.advance(x, a0, a1);
        peak = std::max(peak, std::abs(next.u));
        OscillatorState s0 = x;
        for (int p = 1; p <= pieces; ++p) {
            const double t0 = dt_s * (p - 1) / pieces, t1 = dt_s * p / pieces;
            const OscillatorState s1 = p == pieces ? next : piece.advance(s0, a0 + slope * t0, a0 + slope * t1);
            peak = std::max(peak, std::abs(s1.u));
            // The root search (a few exp, cos, sin) only where its |u| could raise the peak:
            // the bound leaves the peak as the search everywhere would find it, bit for bit,
            // and skips most searches once the strong motion has set the peak.
            if ((s1.v > 0.0) != (s0.v > 0.0) && s0.v != 0.0) {
                const StepResponse r(o, s0, a0 + slope * t0, slope);
                if (r.bound(t1 - t0) > peak) peak = std::max(peak, interior_peak(r, 0.0, t1 - t0, s0.v, s1.v));
            }
            s0 = s1;
        }
        x = next;
    }
    return o.omega() * o.omega() * peak;
}

std::vector<double> response_spectrum(std::span<const double> a, double dt_s, std::span<const double> periods_s, double zeta) {
    std::vector<double> sa;
    sa.reserve(periods_s.size());
    for (double t : periods_s) sa.push_back(spectral_acceleration(a, dt_s, Oscillator{t, zeta}));
    return sa;
}

std::vector<double> floor_spectrum_periods() {
    constexpr int n = 60;
    constexpr double lo = 0.02, hi = 5.0;
    std::vector<double> t(n);
    for (int i = 0; i < n; ++i) t[i] = lo * std::pow(hi / lo, static_cast<double>(i) / (n - 1));
    return t;
}

}  // namespace rocksweep::motion
