#pragma once
/// A recorded horizontal ground motion: samples / g at a fixed interval from t = 0, linear
/// between samples. Its sample times are where it stops being smooth: each ends a step.
#include <algorithm>
#include <cmath>
#include <vector>

#include "rocksweep/physics/excitation/ground.hpp"

namespace rocksweep {

struct Recorded {
    const std::vector<double>* samples;
    double dt_s;
    static constexpr bool vectorised = false;  ///< read per lane from its table, outside the vector loop

    double end_time() const { return static_cast<double>(samples->size() - 1) * dt_s; }
    double ax(double t) const {
        const std::vector<double>& a = *samples;
        const double x = t / dt_s;
        const auto i = static_cast<std::size_t>(std::max(0.0, std::min(std::floor(x), static_cast<double>(a.size() - 2))));
        const double u = x - static_cast<double>(i);
        return a[i] + u * (a[i + 1] - a[i]);
    }
    double ay(double) const { return 0.0; }
    double peak_ax() const {
        double m = 0.0;
        for (double a : *samples) m = std::max(m, std::abs(a));
        return m;
    }
    double peak_ay() const { return 0.0; }
    double time_scale() const { return 0.0; }  // its samples end steps instead
    /// The first sample time after t (strictly), where the ground's slope changes.
    double next_kink(double t) const {
        double k = std::floor(t / dt_s) + 1.0;
        if (!(k * dt_s > t)) k += 1.0;
        return k * dt_s;
    }
    /// Piecewise linear: the first segment after t whose ends differ in sign (or that ends on 0).
    double next_ax_zero(double t) const {
        for (double t0 = t, t1 = next_kink(t); t0 < end_time(); t0 = t1, t1 = next_kink(t1)) {
            const double a0 = ax(t0), a1 = ax(std::min(t1, end_time()));
            if (a0 != 0.0 && (a1 == 0.0 || (a0 > 0.0) != (a1 > 0.0))) {
                const double tz = t0 + (t1 - t0) * a0 / (a0 - a1);
                if (tz > t) return tz;  // a zero that rounds onto t itself is the one just passed
            }
        }
        return INFINITY;
    }
    /// |ax| is largest at a segment's ends: scanning the samples brackets every uplift.
    double next_scan(double t) const { return next_kink(t); }
    template <class Visit>
    void peaks(double t0, double t1, Visit&& visit) const {
        for (double t = next_kink(t0); t < t1; t = next_kink(t))
            if (!visit(t)) return;
    }
    GroundLane lane_coefficients() const {
        GroundLane g;
        g.samples = samples;
        g.sample_dt_s = dt_s;
        return g;
    }
    /// Read from the table, not vectorised; lanes of other families in the batch keep theirs.
    template <bool with_y>
    static Ground lane(const GroundLane& c, double t, double in) {
        return Ground{in != 0.0 ? Recorded{c.samples, c.sample_dt_s}.ax(t) : 0.0, 0.0};
    }
};

}  // namespace rocksweep
