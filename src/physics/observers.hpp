#pragma once
// Observers of one cell's run: each is handed the accepted states (and the block's rest
// intervals) and keeps its own figure of the result: the extremes (max rotation, peak
// anchorage force), the friction demand and pivot uplift, and for histories the works. None
// of them decides anything about the motion; none knows the stepper.
#include <algorithm>
#include <cmath>
#include <optional>

#include "rocksweep/physics/anchorage_law.hpp"
#include "rocksweep/physics/integrator.hpp"
#include "rocksweep/physics/model.hpp"
#include "rocksweep/physics/system.hpp"

namespace rocksweep::kernel {

/// The extreme of a smooth quantity between accepted states, from the parabola through the
/// last three of one rocking phase: checks made only at step ends miss an extreme inside a
/// step by O(dt^2); the vertex of the parabola misses it by O(dt^3).
class ThreePointExtreme {
public:
    void reset() { n_ = 0; }
    /// Adds (t, f); returns the parabola's vertex value if the middle point is a local extreme
    /// of the kind `sign` (+1 max, -1 min) and the vertex lies between the outer points, else f.
    double add(double t, double f, double sign) {
        if (n_ == 3) { t_[0] = t_[1]; f_[0] = f_[1]; t_[1] = t_[2]; f_[1] = f_[2]; n_ = 2; }
        t_[n_] = t; f_[n_] = f; ++n_;
        if (n_ < 3) return f;
        // f - f1 = a u^2 + b u through (u0, f0 - f1), (0, 0), (u2, f2 - f1), u = t - t1.
        const double u0 = t_[0] - t_[1], u2 = t_[2] - t_[1], g0 = f_[0] - f_[1], g2 = f_[2] - f_[1];
        if (!(u0 < 0.0 && u2 > 0.0) || !(sign * g0 < 0.0 && sign * g2 <= 0.0)) return f;
        const double det = u0 * u2 * (u0 - u2);
        const double a = (g0 * u2 - g2 * u0) / det, b = (u0 * u0 * g2 - u2 * u2 * g0) / det;
        if (!(sign * a < 0.0)) return f;
        const double u = -b / (2.0 * a);
        if (!(u > u0 && u < u2)) return f;
        const double v = f_[1] - b * b / (4.0 * a);
        return sign * v > sign * f ? v : f;
    }

private:
    double t_[3] = {0, 0, 0}, f_[3] = {0, 0, 0};
    int n_ = 0;
};

/// Max |theta| and the peak force of an intact working anchorage / F_u. Turning points inside a
/// step come from the step's interpolant (the stepper locates those that reach the fracture
/// angle), so an intact spring never reports more than F_u.
class Extremes {
public:
    explicit Extremes(bool anchored) : peak_force_(anchored ? 0.0 : NAN) {}
    template <AnchorageLaw Law>
    void add(double phi, const Law& law, int side) {
        max_phi_ = std::max(max_phi_, phi);
        if (law.intact(side)) peak_force_ = std::max(peak_force_, law.force_ratio(phi));
    }
    /// What the energy decision found for the rest of the motion.
    void add_decided(double max_phi, double peak_force, bool anchored) {
        max_phi_ = std::max(max_phi_, max_phi);
        if (anchored) peak_force_ = std::max(peak_force_, peak_force);
    }
    void overturned() { max_phi_ = M_PI / 2; }
    double max_phi() const { return max_phi_; }
    double peak_force() const { return peak_force_; }

private:
    double max_phi_ = 0.0;
    double peak_force_;
};

/// The friction the base must supply for pure rocking, max |f_x / f_y| (mu_required), and
/// whether the pivot's vertical reaction went negative (pivot_uplift), physics.md §6.
template <AnchorageLaw Law>
class FrictionDemand {
public:
    /// A rocking state on side s (Eq. 16-18, the law's reactions): checked at every accepted state
    /// and just after each impact. In free rocking the demand peaks as the block settles
    /// (phi, phi' -> 0), at (sin a cos a / i) / (1 - sin^2 a / i) with i = I0/(mR^2) >= 1,
    /// below the tan(alpha) that uplift itself needs: the energy decision leaves nothing out.
    void rocking(const CellModel& m, double t, bool acting, int side, const Law& law, double theta, double theta_dot,
                 bool kink = false) {
        rocking(m, t, acting ? Ground{m.pulse.ax(t), m.pulse.ay(t)} : Ground{}, side, law, theta, theta_dot, kink);
    }
    /// The same with the ground at t given. `kink`: t is a sample where the record turns, a kink
    /// of the demand: its value counts as it is, and no parabola is fitted across it (one
    /// through a kink overshoots the peak there).
    void rocking(const CellModel& m, double t, const Ground& ground, int side, const Law& law, double theta, double theta_dot,
                 bool kink = false) {
        const double phi = side * theta;
        // Past alpha the block is beyond its static stability limit: a fall to the ground needs
        // ever more friction (f_y -> 0 as theta_dot grows) and says nothing about survival. A
        // located event at alpha (a spring breaking at theta_f = alpha) lands a rounding past
        // it: that state is still at alpha, and its demand counts.
        if (phi > m.alpha * (1.0 + 1e-9)) return reset();
        // An anchorage that breaks or switches makes f_y jump: no parabola across the jump.
        const typename Law::Coef k = law.coef(side);
        if (!(coef_ && *coef_ == k)) reset();
        coef_ = k;
        const BaseReactions f = law.reactions(side, ground.ax, ground.ay, theta, theta_dot);
        if (kink) reset();
        const double fx = f.fx, fy = f.fy;
        if (fy <= 0.0) pivot_up_ = true;
        else mu_ = std::max(mu_, demand_.add(t, std::abs(fx) / fy, 1.0));
        if (lift_.add(t, fy, -1.0) <= 0.0) pivot_up_ = true;
    }
    /// A new rocking phase (impact, rest, past alpha): no parabola across it.
    void reset() {
        demand_.reset();
        lift_.reset();
    }
    /// At rest on the moving ground the base carries m (g + ay) and m ax: the friction needed is
    /// max |ax| / (1 + ay) over [t0, t1] of the pulse (ending at t_pulse_end), taken at its
    /// ends and where the pulse says |ax| may peak (and on its scan with a vertical component).
    /// charge() is called per point visited and may end the scan (returns false).
    template <class Charge>
    void at_rest(const Pulse& pulse, double t_pulse_end, double t0, double t1, Charge&& charge) {
        t1 = std::min(t1, t_pulse_end);
        if (!(t1 >= t0)) return;
        auto demand = [](const Ground& g) { return std::abs(g.ax) / (1.0 + g.ay); };
        auto at = [&](double t) { return demand(Ground{pulse.ax(t), pulse.ay(t)}); };
        mu_ = std::max({mu_, at(t0), at(t1 < t_pulse_end ? t1 : std::nextafter(t1, t0))});
        pulse.demand_points(t0, t1, [&](double t, const Ground& g) {
            if (!charge()) return false;
            if (t > t0) mu_ = std::max(mu_, demand(g));
            return true;
        });
    }
    double mu_required() const { return mu_; }
    bool pivot_uplift() const { return pivot_up_; }

private:
    double mu_ = 0.0;
    bool pivot_up_ = false;
    ThreePointExtreme demand_, lift_;  ///< in-step extremes of |f_x / f_y| and f_y
    std::optional<typename Law::Coef> coef_;  ///< the anchorage of the points they hold
};

/// For histories: each accepted step as a StepRecord with the running works (Eq. 23-24) and
/// the energy the adaptive switches injected, handed to the caller's StepObserver.
class HistoryRecorder {
public:
    HistoryRecorder(const CellModel& m, const StepObserver& obs) : m_(m), obs_(obs), t_pulse_end_(m.pulse.end_time()) {}
    /// The step from (t0, y0, v0, theta''(t0) = a0) to (t1, y1, v1) on side s with the anchorage
    /// as it acted over it; impacts so far.
    template <AnchorageLaw Law>
    void step(double t0, double y0, double v0, double a0, double t1, double y1, double v1, int side, const Law& law,
              int impacts) {
        StepRecord s{};
        s.t0 = t0; s.theta0 = y0; s.theta_dot0 = v0; s.acc0 = a0;
        s.t1 = t1; s.theta1 = y1; s.theta_dot1 = v1;
        const double ax1 = t1 < t_pulse_end_ || (t1 == t_pulse_end_ && t0 < t1) ? m_.pulse.ax(t1) : 0.0;
        const double ay1 = t1 <= t_pulse_end_ ? m_.pulse.ay(t1) : 0.0;
        const bool linear = m_.equations == Equations::linearised;
        s.acc1 = side == 0 ? 0.0
                           : rocking::theta_ddot<Law>(rocking::coef(m_.p2, m_.alpha, side, linear), law.coef(side),
                                                      Ground{ax1, ay1}, y1, v1);
        const double k = law.stiffness_n_m(side);
        s.k_left = side > 0 ? k : 0.0;
        s.k_right = side < 0 ? k : 0.0;
        const Works w = law.works(side, s, t1);
        w_exc_ += w.excitation_j;
        w_anch_ += w.anchorage_j;
        s.work_excitation = w_exc_;
        s.work_anchorage = w_anch_;
        s.switch_energy = law.switch_energy();
        s.impacts = impacts;
        obs_(s);
    }

private:
    const CellModel& m_;
    const StepObserver& obs_;
    double t_pulse_end_;
    double w_exc_ = 0.0, w_anch_ = 0.0;
};

}  // namespace rocksweep::kernel
