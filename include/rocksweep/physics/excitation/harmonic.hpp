#pragma once
/// Harmonic ground motion a sin(omega t + psi) on [0, periods T], T = 2 pi / omega, with an
/// optional vertical a_v sin(omega t + psi_v) over the same window: the one-sine pulse
/// (periods = 1), n full cycles (periods = n), and the Makris-Roussos cycloidal pulses, which
/// are this family at a given phase and window (docs/physics.md, "Pulse families").
#include <cmath>

#include "rocksweep/physics/excitation/ground.hpp"
#include "rocksweep/physics/fastmath.hpp"

namespace rocksweep {

struct Harmonic {
    double ax_g, omega, phase, ay_g, phase_y, periods;
    static constexpr bool vectorised = true;  ///< its lane() runs in the vector loop
    static constexpr bool nodal = false;      ///< the kernel evaluates lane() at the nodes

    double end_time() const { return periods * (2.0 * M_PI / omega); }
    double ax(double t) const { return ax_g * std::sin(omega * t + phase); }
    double ay(double t) const { return ay_g * std::sin(omega * t + phase_y); }
    double peak_ax() const { return std::abs(ax_g); }  // every window holds a peak: periods >= 1
    double peak_ay() const { return std::abs(ay_g); }
    double time_scale() const { return omega; }
    double next_kink(double) const { return INFINITY; }
    /// Zeros at omega t + psi = k pi.
    double next_ax_zero(double t) const {
        if (ax_g == 0.0) return INFINITY;
        const double k = std::floor((omega * t + phase) / M_PI) + 1.0;
        double tz = (k * M_PI - phase) / omega;
        if (!(tz > t * (1.0 + 1e-14) + 1e-300)) tz = ((k + 1.0) * M_PI - phase) / omega;
        return tz;
    }
    /// Scanning for uplift: T/512, with the peaks added (below).
    double next_scan(double t) const { return t + 2.0 * M_PI / omega / 512.0; }
    /// Visits, in order, the candidate peaks of |ax| (omega t + psi = pi/2 + k pi) from the one
    /// nearest t0 on, while they are below t1 and `visit` returns true. The first may round onto
    /// or below t0: callers skip those.
    template <class Visit>
    void peaks(double t0, double t1, Visit&& visit) const {
        for (double k = std::ceil(((omega * t0 + phase) - M_PI / 2) / M_PI);; k += 1.0) {
            const double tp = ((M_PI / 2 + k * M_PI) - phase) / omega;
            if (!(tp < t1) || !visit(tp)) return;  // NaN (omega overflowed) ends it too
        }
    }
    GroundLane lane_coefficients() const {
        GroundLane g;
        g.ax_g = ax_g; g.ay_g = ay_g; g.omega = omega; g.phase = phase; g.phase_y = phase_y;
        return g;
    }
    /// The ground at t in the lane loop, branch-free; `in` is 1 inside the window, 0 outside,
    /// where the argument is 0 whatever t is (the sine stays in its range) and the result +0.
    template <bool with_y>
    [[gnu::always_inline]] static inline Ground lane(const GroundLane& c, double t, double in) {
        Ground g;
        g.ax = (c.ax_g * fastmath::sin((c.omega * t + c.phase) * in)) * in + 0.0;
        if constexpr (with_y) g.ay = (c.ay_g * fastmath::sin((c.omega * t + c.phase_y) * in)) * in + 0.0;
        return g;
    }
};

}  // namespace rocksweep
