#pragma once
/// Ground pulses (physics.md §3): accelerations in units of g, time in s.
#include <cmath>

namespace rocksweep {

enum class PulseKind { sine, constant };

/// One-sine pulse a_p0 sin(omega t + psi) on [0, 2 pi / omega], with an optional vertical
/// component a_v0 sin(omega t + psi_v) over the same window; or Housner's constant
/// acceleration a_p0 held for `duration_s`. No motion outside the window.
struct Pulse {
    PulseKind kind = PulseKind::sine;
    double ax_g = 0.0;          ///< horizontal amplitude a_p0 / g
    double omega = 1.0;         ///< omega_p [rad/s] (sine)
    double phase = 0.0;         ///< psi [rad] (sine)
    double ay_g = 0.0;          ///< vertical amplitude a_v0 / g (sine)
    double phase_y = 0.0;       ///< psi_v [rad] (sine)
    double duration_s = 0.0;    ///< constant pulse length [s]

    double end_time() const {
        return kind == PulseKind::sine ? 2.0 * M_PI / omega : duration_s;
    }
    /// Horizontal ground acceleration / g at time t inside the window.
    double ax(double t) const {
        return kind == PulseKind::sine ? ax_g * std::sin(omega * t + phase) : ax_g;
    }
    /// Vertical ground acceleration / g at time t inside the window.
    double ay(double t) const {
        return kind == PulseKind::sine ? ay_g * std::sin(omega * t + phase_y) : 0.0;
    }
    /// First zero of ax after t (strictly), or +inf if none: the adaptive law switches there.
    double next_ax_zero(double t) const;
};

inline double Pulse::next_ax_zero(double t) const {
    if (kind != PulseKind::sine || ax_g == 0.0) return INFINITY;
    // zeros at omega t + psi = k pi
    double k = std::floor((omega * t + phase) / M_PI) + 1.0;
    double tz = (k * M_PI - phase) / omega;
    if (!(tz > t * (1.0 + 1e-14) + 1e-300)) tz = ((k + 1.0) * M_PI - phase) / omega;
    return tz;
}

}  // namespace rocksweep
