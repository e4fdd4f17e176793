#pragma once
/// The symmetric Ricker wavelet a (1 - 2 u^2) exp(-u^2), u = pi (t - 1.5 T) / T, on [0, 3 T],
/// T = 2 pi / omega: its main lobe at 1.5 T, negative side lobes of 0.446 a at u^2 = 3/2, and
/// below 1e-8 a where the window cuts it (docs/physics.md, "Pulse families").
#include <cmath>

#include "rocksweep/physics/excitation/ground.hpp"

namespace rocksweep {

struct Ricker {
    double ax_g, omega;
    static constexpr bool vectorised = true;  ///< its lane() runs in the vector loop
    static constexpr bool nodal = false;      ///< the kernel evaluates lane() at the nodes

    double centre() const { return 3.0 * M_PI / omega; }
    double end_time() const { return 6.0 * M_PI / omega; }
    /// The scalar questions take the lane's own arithmetic: the same bits as the kernel.
    double ax(double t) const { return lane<false>(lane_coefficients(), t, 1.0).ax; }
    double ay(double) const { return 0.0; }
    double peak_ax() const { return std::abs(ax_g); }
    double peak_ay() const { return 0.0; }
    double time_scale() const { return omega; }
    double next_kink(double) const { return INFINITY; }
    /// Zeros at u^2 = 1/2: t = centre -+ sqrt(2) / omega.
    double next_ax_zero(double t) const {
        if (ax_g == 0.0) return INFINITY;
        for (const double z : {centre() - std::sqrt(2.0) / omega, centre() + std::sqrt(2.0) / omega})
            if (z > t) return z;
        return INFINITY;
    }
    double next_scan(double t) const { return t + 2.0 * M_PI / omega / 512.0; }
    /// |ax| peaks at the side lobes (u^2 = 3/2) and the main lobe (u = 0).
    template <class Visit>
    void peaks(double, double t1, Visit&& visit) const {
        const double d = 2.0 * std::sqrt(1.5) / omega;
        for (const double tp : {centre() - d, centre(), centre() + d})
            if (!(tp < t1) || !visit(tp)) return;
    }
    GroundLane lane_coefficients() const {
        GroundLane g;
        g.ax_g = ax_g;
        g.omega = omega;
        g.t_ref = centre();
        return g;
    }
    /// exp(-q) for q in [0, 23] (the window's range) as (e^(-q/64))^64, e^x by its Taylor
    /// series to x^13 on [-0.36, 0]: plain arithmetic, so it vectorises and every lane gets
    /// the bits it gets alone; relative error ~1e-14 (64 roundings squared in).
    [[gnu::always_inline]] static inline double exp_minus(double q) {
        const double x = -q * (1.0 / 64.0);
        double p = 1.0 / 6227020800.0;  // 1/13!
        constexpr double inv_fact[13] = {1.0, 1.0, 1.0 / 2, 1.0 / 6, 1.0 / 24, 1.0 / 120, 1.0 / 720, 1.0 / 5040,
                                         1.0 / 40320, 1.0 / 362880, 1.0 / 3628800, 1.0 / 39916800, 1.0 / 479001600};
        for (int k = 12; k >= 0; --k) p = p * x + inv_fact[k];
        for (int k = 0; k < 6; ++k) p = p * p;
        return p;
    }
    /// Outside the window `in` = 0 makes u = 0 and the result +0.
    template <bool with_y>
    [[gnu::always_inline]] static inline Ground lane(const GroundLane& c, double t, double in) {
        const double u = (0.5 * c.omega * (t - c.t_ref)) * in;
        const double q = u * u;
        return Ground{(c.ax_g * ((1.0 - 2.0 * q) * exp_minus(q))) * in + 0.0, 0.0};
    }
};

}  // namespace rocksweep
