#pragma once
// The event stepper: decides where an RK4 step ends. It sees a trial step's end and the event
// functions the cell hands it; when one has reached zero it locates the earliest root inside
// the step by re-run RK4 steps from the same start (docs/physics_kernel.md, "Numerics"), so that the
// state at an event carries the RK4 local error only and the global error stays fourth order
// through impacts. The first re-run goes to the root on the step's cubic Hermite interpolant,
// O(dt^4) from the true one. An event at a level of theta (impact, overturning, fracture) is
// then projected onto its level by a second-order Taylor step in time from that state: one
// re-run step per event. Otherwise, or when the projection is not small, the next re-runs
// bracket the root from there (~4 re-run steps instead of ~10 from the whole step). It knows
// the events by name, their functions' signs and levels, nothing of the physics behind them.
#include <algorithm>
#include <cfloat>
#include <cmath>

#include "rocksweep/physics/step.hpp"

namespace rocksweep::kernel {

/// What can end a step. Each has a function of the state that is positive before the event and
/// <= 0 once it has happened.
/// trough: the turning point of s theta the other way (s theta_dot from < 0 to >= 0), located
/// only to decide a step that dips (below).
enum class Event { none, overturn, fracture, impact, turn, trough };

/// theta's turning point inside a step, from the cubic Hermite interpolant of (theta,
/// theta_dot) at the zero of the linear interpolant of theta_dot: error O(dt^4) in the peak.
inline double hermite_peak(double dt, double y0, double v0, double y1, double v1) {
    const double tau = v0 / (v0 - v1);
    double theta, theta_dot;  // theta_dot unused: theta'' at the ends is not needed here
    StepEnds{0.0, y0, v0, 0.0, dt, y1, v1, 0.0}.at(tau * dt, theta, theta_dot);
    return theta;
}

/// The largest s theta inside a step [0, dt] (s = +-1, the side), where s theta_dot turns from
/// > 0 to <= 0: theta_dot as the cubic Hermite interpolant of (theta_dot, theta'') at the ends,
/// theta its integral from y0, a quartic whose turning points err by O(dt^5) like the step's
/// states. Unlike hermite_peak it needs no s theta_dot0 > 0: a block that lifts from rest
/// (theta = theta_dot = 0) and falls back within one step has its peak found too, where the
/// linear root of theta_dot lands on the start (measured: half the peak, issue 22). The turning
/// points are bracketed on 16 sub-intervals and bisected; the result is at least s y0.
inline double quartic_peak(double dt, double s, double y0, double v0, double a0, double v1, double a1) {
    auto vel = [&](double u) {
        const double w = 1.0 - u;
        return s * ((1 + 2 * u) * w * w * v0 + u * w * w * dt * a0 + u * u * (3 - 2 * u) * v1 + u * u * (u - 1) * dt * a1);
    };
    auto pos = [&](double u) {
        const double u2 = u * u, u3 = u2 * u, u4 = u3 * u;
        return s * y0 + s * dt * ((u - u3 + 0.5 * u4) * v0 + (0.5 * u2 - 2.0 * u3 / 3.0 + 0.25 * u4) * dt * a0 +
                                  (u3 - 0.5 * u4) * v1 + (0.25 * u4 - u3 / 3.0) * dt * a1);
    };
    double best = s * y0, u_prev = 0.0, f_prev = vel(0.0);
    for (int k = 1; k <= 16; ++k) {
        const double u = k / 16.0, f = vel(u);
        if (f_prev > 0.0 && f <= 0.0) {
            double lo = u_prev, hi = u;
            for (int i = 0; i < 60 && hi - lo > 1e-15; ++i) {
                const double mid = 0.5 * (lo + hi);
                (vel(mid) > 0.0 ? lo : hi) = mid;
            }
            best = std::max(best, pos(0.5 * (lo + hi)));
        }
        u_prev = u;
        f_prev = f;
    }
    return best;
}

/// theta and theta_dot at d on the cubic Hermite interpolant of (theta, theta_dot) over [0, d1]
/// (theta_dot as the cubic's derivative: the step's accelerations are not needed).
inline void hermite_state(double d1, double y0, double v0, double y1, double v1, double d, double& y, double& v) {
    const double u = d / d1, w = 1.0 - u;
    y = (1 + 2 * u) * w * w * y0 + u * w * w * d1 * v0 + u * u * (3 - 2 * u) * y1 - u * u * w * d1 * v1;
    v = 6 * u * w * (y1 - y0) / d1 + w * (1 - 3 * u) * v0 + u * (3 * u - 2) * v1;
}

/// The Events a stepper is handed (for one step from a fixed start):
///   double g(Event e, double d, double y, double v)      e's function at time d into the step;
///   Event earliest(double d, double y, double v, double& g)  the smallest of the armed ones;
///   double level(Event e)     the theta at which e happens, NaN if e is not a level of theta;
///   double acceleration(double d, double y, double v)  theta'' at time d in that state;
///   bool only(Event e, double d, double y, double v)  no other armed event has happened there;
///   bool grazes(double dt, double y1, double v1)  the step's ends may miss a fracture at an
///       in-step turning point (the fracture function dips to <= 0 and comes back): the turning
///       point (Event::turn's root) is located and the fracture function decided there.
///   optionally bool dips(double dt, double y1, double v1)  the same for an impact: theta can pass 0
///       and come back within one step while both ends stay on the step's side (the equation
///       of the side goes on smoothly past 0); the trough (Event::trough's root) is located and
///       the impact function decided there. Measured (issue 22): a sweep-default step of 0.02 s
///       under Sylmar went through such an impact unseen, and the run ended 81 % off.
class EventStepper {
public:
    /// A search is under way: the cell's next trial step is trial() long, from the same start.
    bool searching() const { return searching_; }
    double trial() const { return trial_; }

    /// The end (y1, v1) of a trial step of length dt from (y0, v0) at time t0. Either calls
    /// accept(dt, y, v, event, interior) with the accepted step's length, the state at its end
    /// and what happened there, or sets up another trial. interior: the step ends at an in-step
    /// turning point, not where the cell's trial step was to end (which may be a time boundary:
    /// the end of the pulse, a zero of the ground, a record's sample).
    template <class Events, class Accept>
    void finish(const Events& ev, double t0, double y0, double v0, double dt, double y1, double v1,
                Accept&& accept) {
        double g;
        if (target_ == Event::none) ev.earliest(dt, y1, v1, g);
        else g = ev.g(target_, dt, y1, v1);
        if (!searching_) {
            if (g > 0.0) {
                if (ev.grazes(dt, y1, v1)) graze_ = Event::fracture;
                else if (dips(ev, dt, y1, v1)) graze_ = Event::impact;
                else return accept(dt, y1, v1, Event::none, false);
                // Locate the turning point (the turn function, positive at the start, <= 0 at
                // the end) on re-run RK4 steps; its height decides the fracture (the impact).
                peak_check_ = true;
                const Event turn = graze_ == Event::impact ? Event::trough : Event::turn;
                start(turn, 0.0, ev.g(turn, 0.0, y0, v0), dt, ev.g(turn, dt, y1, v1), y1, v1);
                guess(ev, y0, v0);
                return;
            }
            // The earliest event lies in (0, dt]: find it by Illinois (regula falsi that halves
            // the value of an end kept twice), each trial a fresh RK4 step from the same start.
            start(Event::none, 0.0, NAN, dt, g, y1, v1);  // the functions may vanish at 0
            guess(ev, y0, v0);
            return;
        }
        if (probes_ == 1 && target_ == Event::none && !peak_check_ && projections_ < 3 &&
            project(ev, y0, dt, y1, v1, accept))
            return;
        ++iterations_;
        const bool probe = probes_ > 0;
        if (g > 0.0) {
            if (last_moved_ == 1) g_hi_ *= 0.5;
            lo_ = dt;
            g_lo_ = g;
            last_moved_ = 1;
        } else {
            if (last_moved_ == -1) g_lo_ *= 0.5;
            hi_ = dt;
            g_hi_ = g;
            hi_y_ = y1;
            hi_v_ = v1;
            last_moved_ = -1;
        }
        if (probe) {
            // A probe near the interpolated root: no Illinois halving; the first one sets the
            // stride (a Newton step along the interpolant, widened), each next one goes the
            // other way until both ends of the bracket come from probes.
            last_moved_ = 0;
            (g > 0.0 ? probed_lo_ : probed_hi_) = true;
            if (probes_ == 1) stride_ = std::max(1.5 * std::abs(g / slope_), 1e-9 * hi_);
        }
        const double tol = std::max(4.0 * DBL_EPSILON * (std::abs(t0) + hi_), 1e-12 * hi_);
        // A trial on which the function is exactly 0 (theta rounds to 0 at an impact) is the
        // root itself: regula falsi could not move off it, and would bisect to the tolerance.
        if (hi_ - lo_ <= tol || g_hi_ == 0.0 || iterations_ >= 100) {
            searching_ = false;
            const Event target = target_;
            target_ = Event::none;  // the next step looks for every event again
            if (peak_check_) {
                peak_check_ = false;
                const double gf = ev.g(graze_, hi_, hi_y_, hi_v_);
                if (gf <= 0.0) {
                    // The peak passes the fracture angle (the trough passes 0): the event lies
                    // in (0, turning point].
                    start(graze_, 0.0, ev.g(graze_, 0.0, y0, v0), hi_, gf, hi_y_, hi_v_);
                    guess(ev, y0, v0);
                    return;
                }
                // The spring holds: the step ends at the turning point (an ordinary step end).
                return accept(hi_, hi_y_, hi_v_, Event::none, true);
            }
            double gh;
            const Event which = target == Event::none ? ev.earliest(hi_, hi_y_, hi_v_, gh) : target;
            return accept(hi_, hi_y_, hi_v_, which, false);
        }
        if (probe && !(probed_lo_ && probed_hi_) && probes_ < 4 && std::isfinite(stride_)) {
            const double x = dt + (g > 0.0 ? stride_ : -stride_);
            stride_ *= 8.0;
            if (x > lo_ && x < hi_) {
                ++probes_;
                trial_ = x;
                return;
            }
        }
        probes_ = 0;  // Illinois from here on
        double x = 0.5 * (lo_ + hi_);
        // Guard: bisect when there is no value at lo yet, or the bracket stopped shrinking.
        if (!std::isnan(g_lo_) && (iterations_ % 4 != 0 || hi_ - lo_ < 0.5 * width_)) {
            const double xs = lo_ + (hi_ - lo_) * g_lo_ / (g_lo_ - g_hi_);
            if (xs > lo_ && xs < hi_) x = xs;
        }
        if (iterations_ % 4 == 0) width_ = hi_ - lo_;
        // Never closer than tol/2 to an end (Dekker's rule): when the root lies that close to
        // it, this trial lands on the other side and closes the bracket.
        trial_ = std::clamp(x, lo_ + 0.5 * tol, hi_ - 0.5 * tol);
    }

private:
    // the root lies in (lo, hi]
    bool searching_ = false;
    /// What the search locates: Event::none = the earliest of all events at the step's end;
    /// Event::turn with peak_check_ = the in-step turning point of a step that grazes.
    Event target_ = Event::none;
    bool peak_check_ = false;
    Event graze_ = Event::fracture;  ///< what a peak check decides: fracture (a peak) or impact (a trough)

    template <class Events>
    static bool dips(const Events& ev, double dt, double y1, double v1) {
        if constexpr (requires { ev.dips(dt, y1, v1); }) return ev.dips(dt, y1, v1);
        else return false;
    }
    double lo_ = 0.0, hi_ = 0.0, g_lo_ = 0.0, g_hi_ = 0.0, trial_ = 0.0, width_ = 0.0;
    int last_moved_ = 0, iterations_ = 0;
    double hi_y_ = 0.0, hi_v_ = 0.0;
    // Probing around the interpolated root: trials made so far (0: none, Illinois), Taylor
    // projections tried, the interpolant's slope there, the next stride, which ends of the
    // bracket probes set.
    int probes_ = 0, projections_ = 0;
    double slope_ = 0.0, stride_ = 0.0;
    bool probed_lo_ = false, probed_hi_ = false;

    /// After a re-run step to x (first the interpolated root), in the state (y, v) there: the
    /// event at a level of theta is taken where the second-order Taylor expansion from that
    /// state reaches the level, t* = x - delta with delta = eps/v + a eps^2/(2 v^3) (eps = y -
    /// level, a = theta''), and theta_dot* = v - a delta. Its error, O(delta^3) in time, is far
    /// below the step's own error when delta is within 1e-3 of the step: then the event is
    /// accepted (true). A larger delta, up to 5 % of the step, is tried again from a re-run step
    /// to t* (true, a new trial), at most twice. False, for the bracketing search, when the
    /// projection is larger, leaves the step, lets another event come first, or lands in the
    /// first 1e-3 of a step from theta = 0 (an uplift or impact), where the trivial root may be
    /// double or triple and the interpolant's root is not the RK4 one's.
    template <class Events, class Accept>
    bool project(const Events& ev, double y0, double x, double y, double v, Accept& accept) {
        ++projections_;
        double g;
        const Event e = ev.earliest(hi_, hi_y_, hi_v_, g);
        const double level = ev.level(e);
        if (!std::isfinite(level) || !(std::abs(v) > 0.0)) return false;
        const double a = ev.acceleration(x, y, v);
        const double eps = y - level;
        const double delta = eps / v + a * eps * eps / (2.0 * v * v * v);
        const double d = x - delta;
        if (!(d > 0.0 && d <= hi_ && std::abs(delta) <= 0.05 * hi_)) return false;
        if (y0 == 0.0 && d < 1e-3 * hi_) return false;
        if (std::abs(delta) > 1e-3 * hi_) {
            if (projections_ >= 3) return false;
            trial_ = d;
            return true;
        }
        const double vd = v - a * delta;
        if (!ev.only(e, d, level, vd)) return false;
        searching_ = false;
        target_ = Event::none;
        probes_ = 0;
        accept(d, level, vd, e, false);
        return true;
    }

    /// The target's function along the cubic Hermite interpolant of the bracket (0, hi_].
    template <class Events>
    double interpolated_g(const Events& ev, double y0, double v0, double d) const {
        double y, v, g;
        hermite_state(hi_, y0, v0, hi_y_, hi_v_, d, y, v);
        if (target_ == Event::none) ev.earliest(d, y, v, g);
        else g = ev.g(target_, d, y, v);
        return g;
    }

    /// Makes the first trial of a search just started on (0, hi_] the root of the target's
    /// function on the interpolant (Illinois on the cubic: no RK4 step), and notes its slope.
    template <class Events>
    void guess(const Events& ev, double y0, double v0) {
        double lo = lo_, hi = hi_, glo = g_lo_, ghi = g_hi_;
        int moved = 0;
        for (int i = 0; i < 40 && hi - lo > 1e-7 * hi_; ++i) {
            double x = 0.5 * (lo + hi);
            if (!std::isnan(glo) && i % 4 != 3) {
                const double xs = lo + (hi - lo) * glo / (glo - ghi);
                if (xs > lo && xs < hi) x = xs;
            }
            const double gx = interpolated_g(ev, y0, v0, x);
            if (!std::isfinite(gx)) return;  // keep the plain search
            if (gx > 0.0) {
                if (moved == 1) ghi *= 0.5;
                lo = x, glo = gx, moved = 1;
            } else {
                if (moved == -1) glo *= 0.5;
                hi = x, ghi = gx, moved = -1;
            }
        }
        const double x = hi, e = 1e-7 * hi_;
        if (!(x > lo_ && x < hi_) || !(x - e > lo_ && x + e < hi_)) return;
        slope_ = (interpolated_g(ev, y0, v0, x + e) - interpolated_g(ev, y0, v0, x - e)) / (2 * e);
        if (!(std::isfinite(slope_) && slope_ != 0.0)) return;
        trial_ = x;
        probes_ = 1;
    }

    /// Starts an Illinois search for a root in (lo, hi]; g_lo may be NaN (no value at lo).
    void start(Event target, double lo, double g_lo, double hi, double g_hi, double y_hi, double v_hi) {
        searching_ = true;
        target_ = target;
        last_moved_ = 0;
        iterations_ = 0;
        lo_ = lo;
        g_lo_ = g_lo;
        hi_ = hi;
        g_hi_ = g_hi;
        hi_y_ = y_hi;
        hi_v_ = v_hi;
        width_ = hi - lo;
        trial_ = 0.5 * (lo + hi);
        probes_ = 0;
        projections_ = 0;
        probed_lo_ = probed_hi_ = false;
    }
};

}  // namespace rocksweep::kernel
