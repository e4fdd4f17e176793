#pragma once
/// Ground pulses (physics.md §3): accelerations in units of g, time in s.
#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

namespace rocksweep {

enum class PulseKind { sine, constant, record };

/// One-sine pulse a_p0 sin(omega t + psi) on [0, 2 pi / omega], with an optional vertical
/// component a_v0 sin(omega t + psi_v) over the same window; Housner's constant
/// acceleration a_p0 held for `duration_s`; or a recorded horizontal ground motion, samples
/// in g at a fixed interval, linear between samples. No motion outside the window.
struct Pulse {
    PulseKind kind = PulseKind::sine;
    double ax_g = 0.0;          ///< horizontal amplitude a_p0 / g
    double omega = 1.0;         ///< omega_p [rad/s] (sine)
    double phase = 0.0;         ///< psi [rad] (sine)
    double ay_g = 0.0;          ///< vertical amplitude a_v0 / g (sine)
    double phase_y = 0.0;       ///< psi_v [rad] (sine)
    double duration_s = 0.0;    ///< constant pulse length [s]
    std::shared_ptr<const std::vector<double>> record;  ///< record: samples / g
    double record_dt_s = 0.0;   ///< record: sampling interval [s]

    double end_time() const {
        switch (kind) {
            case PulseKind::sine: return 2.0 * M_PI / omega;
            case PulseKind::constant: return duration_s;
            case PulseKind::record: return static_cast<double>(record->size() - 1) * record_dt_s;
        }
        return 0.0;
    }
    /// Horizontal ground acceleration / g at time t inside the window.
    double ax(double t) const {
        switch (kind) {
            case PulseKind::sine: return ax_g * std::sin(omega * t + phase);
            case PulseKind::constant: return ax_g;
            case PulseKind::record: {
                const std::vector<double>& a = *record;
                const double x = t / record_dt_s;
                const auto i = static_cast<std::size_t>(std::max(0.0, std::min(std::floor(x), static_cast<double>(a.size() - 2))));
                const double u = x - static_cast<double>(i);
                return a[i] + u * (a[i + 1] - a[i]);
            }
        }
        return 0.0;
    }
    /// Record: the first sample time after t (strictly), where the ground's slope changes.
    double next_sample(double t) const {
        double k = std::floor(t / record_dt_s) + 1.0;
        if (!(k * record_dt_s > t)) k += 1.0;
        return k * record_dt_s;
    }
    /// Largest |ax| over the window, for deciding without integrating.
    double peak_ax() const {
        if (kind != PulseKind::record) return std::abs(ax_g);
        double m = 0.0;
        for (double a : *record) m = std::max(m, std::abs(a));
        return m;
    }
    /// Vertical ground acceleration / g at time t inside the window.
    double ay(double t) const {
        return kind == PulseKind::sine ? ay_g * std::sin(omega * t + phase_y) : 0.0;
    }
    /// First zero of ax after t (strictly), or +inf if none: the adaptive law switches there.
    double next_ax_zero(double t) const;
};

inline double Pulse::next_ax_zero(double t) const {
    if (kind == PulseKind::record) {
        // Piecewise linear: the first segment after t whose ends differ in sign (or that ends on 0).
        for (double t0 = t, t1 = next_sample(t); t0 < end_time(); t0 = t1, t1 = next_sample(t1)) {
            const double a0 = ax(t0), a1 = ax(std::min(t1, end_time()));
            if (a0 != 0.0 && (a1 == 0.0 || (a0 > 0.0) != (a1 > 0.0))) {
                const double tz = t0 + (t1 - t0) * a0 / (a0 - a1);
                if (tz > t) return tz;  // a zero that rounds onto t itself is the one just passed
            }
        }
        return INFINITY;
    }
    if (kind != PulseKind::sine || ax_g == 0.0) return INFINITY;
    // zeros at omega t + psi = k pi
    double k = std::floor((omega * t + phase) / M_PI) + 1.0;
    double tz = (k * M_PI - phase) / omega;
    if (!(tz > t * (1.0 + 1e-14) + 1e-300)) tz = ((k + 1.0) * M_PI - phase) / omega;
    return tz;
}

}  // namespace rocksweep
