#pragma once
/// A recorded ground motion: horizontal and (optionally) vertical samples / g at a fixed interval
/// from t = 0, linear between samples, times a scale factor applied after interpolation. Its
/// sample times are where it stops being smooth, and by default each ends a step. The kernel
/// takes the ground at a step's nodes as moment_nodes (the values at the nodes on one linear
/// piece), with which RK4 integrates the ground exactly where it enters linearly even when a
/// step crosses samples (--record-steps cross; measured third order there, docs/physics_kernel.md,
/// "Steps across a record's samples"). The samples are shared (one table per record, whatever
/// the scale).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

#include "rocksweep/physics/excitation/ground.hpp"

namespace rocksweep {

struct Recorded {
    const std::vector<double>* samples;    ///< horizontal / g
    const std::vector<double>* samples_y;  ///< vertical / g, same times and length; nullptr: none
    double dt_s;
    double scale = 1.0;                     ///< applied to both components after interpolation
    static constexpr bool vectorised = true;  ///< the lane loop vectorises over its nodes
    static constexpr bool nodal = true;       ///< the lane hands the kernel its ground at the nodes

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
    /// Pulse::first_uplift's scan on the table: the first sample time in (t, t_stop) where
    /// lifts(ground) holds, or +inf; `before` is the sample (or t) before it. The two bracket the
    /// uplift (Eq. 1's left side minus its right is convex on a segment: next_scan).
    template <class Lifts, class Charge>
    double first_lifting_sample(double t, double t_stop, Lifts&& lifts, Charge&& charge, double& before) const {
        before = t;
        for (std::size_t k = first_sample_after(t), n = samples->size(); k < n; ++k) {
            if (!charge()) return INFINITY;
            const double tk = static_cast<double>(k) * dt_s;
            if (!(tk < t_stop)) break;
            if (lifts(sample(k))) return tk;
            before = tk;
        }
        return INFINITY;
    }
    /// Pulse::demand_points on the table: every sample time in (t0, t1) with its ground.
    template <class Visit>
    void sample_points(double t0, double t1, Visit&& visit) const {
        each_sample(t0, t1, [&](std::size_t k, double tk) { return visit(tk, sample(k)); });
    }
    /// The sample times in (t0, t1) where a component turns (its slope changes sign, or is 0 on
    /// a side), with the ground there: where |f_x / f_y| of a rocking block can peak at a kink
    /// (Lane::note_reactions_inside). Elsewhere its kink is a change of slope of one sign, near
    /// which a peak is a smooth one, between points.
    template <class Visit>
    void turning_points(double t0, double t1, Visit&& visit) const {
        each_sample(t0, t1, [&](std::size_t k, double tk) {
            if (turns(k)) visit(tk, sample(k));
            return true;
        });
    }
    /// Whether t is exactly a sample time (as steps that end at samples end) where the record turns.
    bool turns_at(double t) const {
        const double k = std::round(t / dt_s);
        return k >= 0.0 && k * dt_s == t && turns(static_cast<std::size_t>(k));
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

    /// The ground at RK4's nodes t0, t0 + h/2, t0 + h (h > 0, the step inside the record) as the
    /// three values for which Simpson's rule, the quadrature inside RK4, gives the exact integrals
    /// of u, u s and u s^2 over the step (s = (t - t0) / h) of the piecewise-linear record. The
    /// ground enters the equation of motion linearly, so every term of the step's local error
    /// linear in it is then that of a smooth ground, whatever samples the step crosses. Equal to
    /// the values at the nodes (up to rounding) when the step lies within one sample interval.
    std::array<Ground, 3> moment_nodes(double t0, double h) const {
        std::array<Ground, 3> g{};
        const std::array<double, 3> x = nodes_of(*samples, t0, h);
        const std::array<double, 3> y = samples_y ? nodes_of(*samples_y, t0, h) : std::array<double, 3>{};
        for (int j = 0; j < 3; ++j) {
            g[j].ax = scale * x[j];
            g[j].ay = scale * y[j];
        }
        return g;
    }

private:
    /// The index of next_kink(t).
    std::size_t first_sample_after(double t) const {
        double k = std::max(std::floor(t / dt_s) + 1.0, 0.0);
        if (!(k * dt_s > t)) k += 1.0;
        return static_cast<std::size_t>(k);
    }
    /// f(k, t_k) for each sample k with t_k in (t0, t1), in order, while it returns true.
    template <class F>
    void each_sample(double t0, double t1, F&& f) const {
        for (std::size_t k = first_sample_after(t0), n = samples->size(); k < n; ++k) {
            const double tk = static_cast<double>(k) * dt_s;
            if (!(tk < t1) || !f(k, tk)) return;
        }
    }
    /// Whether a component's slope changes sign at sample k (or is 0 on a side of it).
    bool turns(std::size_t k) const {
        auto in = [k](const std::vector<double>& a) {
            return k > 0 && k + 1 < a.size() && (a[k] - a[k - 1]) * (a[k + 1] - a[k]) <= 0.0;
        };
        return in(*samples) || (samples_y && in(*samples_y));
    }
    /// The ground at sample k, as ax() and ay() there up to rounding.
    Ground sample(std::size_t k) const {
        return Ground{scale * (*samples)[k], samples_y ? scale * (*samples_y)[k] : 0.0};
    }

    /// moment_nodes of one table, before the scale.
    std::array<double, 3> nodes_of(const std::vector<double>& a, double t0, double h) const {
        const int last = static_cast<int>(a.size()) - 2;
        const double t1 = t0 + h, inv_h = 1.0 / h, inv_dt = 1.0 / dt_s;
        int i = std::clamp(static_cast<int>(t0 * inv_dt), 0, last);
        auto at = [&](int seg, double t) {
            const double u = t * inv_dt - static_cast<double>(seg);
            return a[seg] + u * (a[seg + 1] - a[seg]);
        };
        double m0 = 0.0, m1 = 0.0, m2 = 0.0;
        double ta = t0, ua = at(i, t0);
        // Simpson on each linear piece is exact for u s^n, n <= 2.
        for (; i <= last && ta < t1; ++i) {
            const double end = static_cast<double>(i + 1) * dt_s;
            const double tb = std::min(t1, end);
            if (!(tb > ta)) continue;  // t0 rounded onto the segment's end
            const double ub = tb == end ? a[i + 1] : at(i, tb);
            const double sa = (ta - t0) * inv_h, sb = (tb - t0) * inv_h, sm = 0.5 * (sa + sb), w = (sb - sa) / 6.0;
            const double um = 0.5 * (ua + ub);
            m0 += w * (ua + 4.0 * um + ub);
            m1 += w * (sa * ua + 4.0 * sm * um + sb * ub);
            m2 += w * (sa * sa * ua + 4.0 * sm * sm * um + sb * sb * ub);
            ta = tb;
            ua = ub;
        }
        // Simpson's (u0 + 4 um + u1) / 6 with weights 1, s, s^2 at s = 0, 1/2, 1 equal to m0, m1, m2.
        return {6.0 * (m0 - 3.0 * m1 + 2.0 * m2), 6.0 * (m1 - m2), 6.0 * (2.0 * m2 - m1)};
    }

    static double peak(const std::vector<double>& a) {
        double m = 0.0;
        for (double v : a) m = std::max(m, std::abs(v));
        return m;
    }
};

}  // namespace rocksweep
