#pragma once
/// Housner's rectangular pulse: constant acceleration a held for a duration (physics.md §7).
#include <cmath>

#include "rocksweep/physics/excitation/ground.hpp"

namespace rocksweep {

struct Rectangle {
    double ax_g, duration_s;
    static constexpr bool vectorised = true;  ///< its lane() runs in the vector loop
    static constexpr bool nodal = false;      ///< the kernel evaluates lane() at the nodes

    double end_time() const { return duration_s; }
    double ax(double) const { return ax_g; }
    double ay(double) const { return 0.0; }
    double peak_ax() const { return std::abs(ax_g); }
    double peak_ay() const { return 0.0; }
    double time_scale() const { return 0.0; }
    double next_kink(double) const { return INFINITY; }
    double next_ax_zero(double) const { return INFINITY; }
    /// Constant ground: a block it does not lift at once it never lifts.
    double next_scan(double) const { return INFINITY; }
    template <class Visit>
    void peaks(double, double, Visit&&) const {}
    GroundLane lane_coefficients() const {
        GroundLane g;
        g.ax_g = ax_g;
        return g;
    }
    template <bool with_y>
    [[gnu::always_inline]] static inline Ground lane(const GroundLane& c, double, double in) {
        return Ground{c.ax_g * in + 0.0, 0.0};
    }
};

}  // namespace rocksweep
