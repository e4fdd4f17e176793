#pragma once
/// A recorded ground motion: horizontal and (optionally) vertical samples / g at a fixed interval
/// from t = 0, linear between samples, times a scale factor applied after interpolation. Its
/// sample times are where it stops being smooth: each ends a step. The samples are shared (one
/// table per record, whatever the scale), so the lanes of a batch that hold one record at
/// different scales read one table in the vector loop (docs/physics.md, "Recorded ground motions").
#include <algorithm>
#include <cmath>
#include <vector>

#include "rocksweep/physics/excitation/ground.hpp"

namespace rocksweep {

struct Recorded {
    const std::vector<double>* samples;    ///< horizontal / g
    const std::vector<double>* samples_y;  ///< vertical / g, same times and length; nullptr: none
    double dt_s;
    double scale = 1.0;                     ///< applied to both components after interpolation
    static constexpr bool vectorised = true;  ///< its lane() runs in the vector loop (one shared table)

    double end_time() const { return static_cast<double>(samples->size() - 1) * dt_s; }
    /// The scalar questions take the lane's own arithmetic: the same bits as the kernel.
    double ax(double t) const { return lane<false>(lane_coefficients(), t, 1.0).ax; }
    double ay(double t) const { return lane<true>(lane_coefficients(), t, 1.0).ay; }
    double peak_ax() const { return peak(*samples) * std::abs(scale); }
    double peak_ay() const { return samples_y ? peak(*samples_y) * std::abs(scale) : 0.0; }
    double time_scale() const { return 0.0; }  // its samples end steps instead
    /// The first sample time after t (strictly), where the ground's slope changes.
    double next_kink(double t) const {
        double k = std::floor(t / dt_s) + 1.0;
        if (!(k * dt_s > t)) k += 1.0;
        return k * dt_s;
    }
    /// Piecewise linear: the first segment after t whose ends differ in sign (or that ends on 0).
    double next_ax_zero(double t) const {
        const GroundLane c = lane_coefficients();
        const double t_end = end_time();
        auto ax_at = [&c](double tt) { return lane<false>(c, tt, 1.0).ax; };
        // From the sample at or before t, so that every t of a segment finds the same zero (the
        // integrator keeps it until t reaches it); each segment's start is the last one's end.
        double s0 = std::floor(t / dt_s) * dt_s;
        if (s0 > t) s0 -= dt_s;
        double a0 = ax_at(s0);
        for (double t0 = s0, t1 = next_kink(s0); t0 < t_end; t0 = t1, t1 = next_kink(t1)) {
            const double a1 = ax_at(std::min(t1, t_end));
            if (a0 != 0.0 && (a1 == 0.0 || (a0 > 0.0) != (a1 > 0.0))) {
                const double tz = t0 + (t1 - t0) * a0 / (a0 - a1);
                if (tz > t) return tz;  // a zero that rounds onto t itself is the one just passed
            }
            a0 = a1;
        }
        return INFINITY;
    }
    /// |ax| - (1 + ay) tan(alpha) is convex on a segment (|linear| - linear), so it is largest at
    /// a segment's ends: scanning the samples brackets every uplift, with or without a vertical.
    double next_scan(double t) const { return next_kink(t); }
    template <class Visit>
    void peaks(double t0, double t1, Visit&& visit) const {
        for (double t = next_kink(t0); t < t1; t = next_kink(t))
            if (!visit(t)) return;
    }
    /// Scale in ax_g (and ay_g with a vertical; 0 without, reading the horizontal table).
    GroundLane lane_coefficients() const {
        GroundLane g;
        g.ax_g = scale;
        g.ay_g = samples_y ? scale : 0.0;
        g.samples = samples->data();
        g.samples_y = samples_y ? samples_y->data() : samples->data();
        g.sample_dt_s = dt_s;
        g.last_segment = static_cast<int>(samples->size() - 2);
        return g;
    }
    /// The ground at t in the lane loop, branch-free: segment i = floor(t / dt) clamped to the
    /// table, a gather of its ends, then the scale. Outside the window `in` = 0 makes x = 0 (so
    /// the index stays in int range whatever t is) and the result +0. Inside, 0 <= x <= samples
    /// - 1 up to rounding: truncation is floor, and the clamp in int (a clamp of doubles would
    /// be a comparison that may trap, which GCC does not if-convert) keeps i + 1 in the table.
    template <bool with_y>
    [[gnu::always_inline]] static inline Ground lane(const GroundLane& c, double t, double in) {
        const double x = (t / c.sample_dt_s) * in;
        const int i = std::min(std::max(static_cast<int>(x), 0), c.last_segment);
        const double u = x - static_cast<double>(i);
        Ground g;
        g.ax = (c.ax_g * (c.samples[i] + u * (c.samples[i + 1] - c.samples[i]))) * in + 0.0;
        if constexpr (with_y) g.ay = (c.ay_g * (c.samples_y[i] + u * (c.samples_y[i + 1] - c.samples_y[i]))) * in + 0.0;
        return g;
    }

private:
    static double peak(const std::vector<double>& a) {
        double m = 0.0;
        for (double v : a) m = std::max(m, std::abs(v));
        return m;
    }
};

}  // namespace rocksweep
