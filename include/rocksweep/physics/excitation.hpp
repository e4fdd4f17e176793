#pragma once
/// Ground motions (physics.md §3, §8): accelerations in units of g, time in s, no motion
/// outside the window [0, end_time()). `Pulse` is the plain description a cell carries; each
/// family is its own type (excitation/*.hpp) answering what the integrator asks of it — the
/// ground at t, the window's end, the times where it stops being smooth (next_kink) and its
/// zeros (the adaptive law switches there), its peak, its time scale, where to look for the
/// first uplift from rest (next_scan, peaks) — and its ground in the W-lane kernel (lane).
/// The scalar questions are answered through visit(); the kernel instantiates its lane loop
/// per family. A new family is one header and its registration here: a PulseKind, a case in
/// visit(), and its name in pulse_library.hpp.
#include <cfloat>
#include <cmath>
#include <memory>
#include <vector>

#include "rocksweep/physics/excitation/ground.hpp"
#include "rocksweep/physics/excitation/harmonic.hpp"
#include "rocksweep/physics/excitation/recorded.hpp"
#include "rocksweep/physics/excitation/rectangle.hpp"
#include "rocksweep/physics/excitation/ricker.hpp"

namespace rocksweep {

enum class PulseKind { sine, constant, record, ricker };

/// One ground motion. sine: a_p0 sin(omega t + psi) on [0, periods 2 pi / omega] with an
/// optional vertical a_v0 sin(omega t + psi_v) over the same window (Harmonic); constant:
/// Housner's a_p0 held for `duration_s` (Rectangle); record: horizontal and optional vertical
/// samples in g at a fixed interval, linear between samples, times record_scale (Recorded); the
/// samples are shared, not copied, by the cells that scale one record; ricker: the Ricker wavelet of peak a_p0 and omega (Ricker).
struct Pulse {
    PulseKind kind = PulseKind::sine;
    double ax_g = 0.0;          ///< horizontal amplitude a_p0 / g
    double omega = 1.0;         ///< omega_p [rad/s] (sine)
    double phase = 0.0;         ///< psi [rad] (sine)
    double ay_g = 0.0;          ///< vertical amplitude a_v0 / g (sine)
    double phase_y = 0.0;       ///< psi_v [rad] (sine)
    double periods = 1.0;       ///< sine: window length in periods 2 pi / omega
    double duration_s = 0.0;    ///< constant pulse length [s]
    std::shared_ptr<const std::vector<double>> record;    ///< record: horizontal samples / g
    std::shared_ptr<const std::vector<double>> record_y;  ///< record: vertical samples / g, same times (null: none)
    double record_dt_s = 0.0;   ///< record: sampling interval [s]
    double record_scale = 1.0;  ///< record: factor on both components, applied after interpolation

    double end_time() const;
    /// Horizontal, vertical ground acceleration / g at time t inside the window.
    double ax(double t) const;
    double ay(double t) const;
    /// Largest |ax|, |ay| over the window, for deciding without integrating.
    double peak_ax() const;
    double peak_ay() const;
    /// The pulse's own angular frequency for the step size [rad/s] (0: none).
    double time_scale() const;
    /// First time after t (strictly) where the ground stops being smooth inside the window
    /// (a record's sample times), or +inf.
    double next_kink(double t) const;
    /// A record's name for next_kink: the first sample time after t.
    double next_sample(double t) const { return next_kink(t); }
    /// First zero of ax after t (strictly), or +inf if none: the adaptive law switches there.
    double next_ax_zero(double t) const;
    /// First time in [t, t_stop) at which `lifts(g)` holds for the ground g there, to machine
    /// precision, or +inf; `charge()` is called per scanned sample and may end the search
    /// (returns false).
    template <class Lifts, class Charge>
    double first_uplift(double t, double t_stop, Lifts&& lifts, Charge&& charge) const;
    /// Visits in order the times in (t0, t1) where |ax| may peak, plus (with a vertical
    /// component) a scan of the window, with the ground there; `visit(t, g)` returns false to
    /// stop. Times at or below t0 may come first: callers skip them.
    template <class Visit>
    void demand_points(double t0, double t1, Visit&& visit) const;
};

/// Calls f with the family of p.
template <class F>
decltype(auto) visit(const Pulse& p, F&& f) {
    switch (p.kind) {
        case PulseKind::sine: return f(Harmonic{p.ax_g, p.omega, p.phase, p.ay_g, p.phase_y, p.periods});
        case PulseKind::constant: return f(Rectangle{p.ax_g, p.duration_s});
        case PulseKind::record: return f(Recorded{p.record.get(), p.record_y.get(), p.record_dt_s, p.record_scale});
        case PulseKind::ricker: return f(Ricker{p.ax_g, p.omega});
    }
    return f(Rectangle{0.0, 0.0});  // not reached: every kind has its case
}

inline double Pulse::end_time() const { return visit(*this, [](const auto& e) { return e.end_time(); }); }
inline double Pulse::ax(double t) const { return visit(*this, [t](const auto& e) { return e.ax(t); }); }
inline double Pulse::ay(double t) const { return visit(*this, [t](const auto& e) { return e.ay(t); }); }
inline double Pulse::peak_ax() const { return visit(*this, [](const auto& e) { return e.peak_ax(); }); }
inline double Pulse::peak_ay() const { return visit(*this, [](const auto& e) { return e.peak_ay(); }); }
inline double Pulse::time_scale() const { return visit(*this, [](const auto& e) { return e.time_scale(); }); }
inline double Pulse::next_kink(double t) const { return visit(*this, [t](const auto& e) { return e.next_kink(t); }); }
inline double Pulse::next_ax_zero(double t) const {
    return visit(*this, [t](const auto& e) { return e.next_ax_zero(t); });
}

template <class Lifts, class Charge>
double Pulse::first_uplift(double t, double t_stop, Lifts&& lifts, Charge&& charge) const {
    return visit(*this, [&](const auto& e) {
        using F = std::decay_t<decltype(e)>;
        auto lifts_at = [&](double x) { return lifts(Ground{e.ax(x), e.ay(x)}); };
        // The uplift instant in (lo, hi], hi lifting and lo not, to machine precision.
        auto bisect = [&](double lo, double hi) {
            for (int i = 0; i < 200 && hi - lo > 4 * DBL_EPSILON * hi; ++i) {
                const double mid = 0.5 * (lo + hi);
                (lifts_at(mid) ? hi : lo) = mid;
            }
            return hi;
        };
        if constexpr (F::nodal) {
            double lo;  // a scan of its table
            const double hi = e.first_lifting_sample(t, t_stop, lifts, charge, lo);
            return std::isfinite(hi) ? bisect(lo, hi) : hi;
        }
        if (!std::isfinite(e.next_scan(t))) return double{INFINITY};  // the ground does not change
        for (double prev = t; prev < t_stop;) {
            if (!charge()) return double{INFINITY};
            double next = std::min(e.next_scan(prev), t_stop);
            // A peak of |ax| in (prev, next) catches a pulse barely above the threshold.
            e.peaks(prev, next, [&](double tp) {
                if (!(tp > prev && lifts_at(tp))) return true;
                next = tp;
                return false;
            });
            if (next < t_stop && lifts_at(next)) return bisect(prev, next);
            prev = next;
        }
        return double{INFINITY};
    });
}

template <class Visit>
void Pulse::demand_points(double t0, double t1, Visit&& visit_point) const {
    visit(*this, [&](const auto& e) {
        using F = std::decay_t<decltype(e)>;
        if constexpr (F::nodal) {
            e.sample_points(t0, t1, visit_point);  // every sample: the vertical's too
        } else {
            auto at = [&](double t) { return visit_point(t, Ground{e.ax(t), e.ay(t)}); };
            bool go = true;
            e.peaks(t0, t1, [&](double tp) { return go = at(tp); });
            if (go && e.peak_ay() != 0.0)
                for (double t = t0; t < t1 && at(t); t = e.next_scan(t)) {}
        }
    });
}

}  // namespace rocksweep
