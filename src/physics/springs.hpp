#pragma once
// Eq. 8's anchorage of one cell as the kernel runs it (physics.md §4), an AnchorageLaw
// (anchorage_law.hpp): two elastic-brittle springs, one per base corner, each with its own
// broken flag, and for the adaptive anchorage which of K_max / K_min acts. Free, constant and
// adaptive anchorages all run it (a free block's kappa is 0).
#include <cstdint>

#include "rocksweep/physics/anchorage_law.hpp"
#include "rocksweep/physics/energy.hpp"
#include "rocksweep/physics/model.hpp"
#include "rocksweep/physics/outcome.hpp"
#include "rocksweep/physics/spring_law.hpp"

namespace rocksweep::kernel {

class Springs : public rocking::SpringLaw {
public:
    explicit Springs(const CellModel& m) : m_(m) {}

    /// The spring's small-angle frequency sqrt(p^2 + kappa / 2) with K (K_max).
    static double omega(const CellModel& m) { return std::sqrt(m.p2 + 0.5 * m.kappa_max); }
    /// The lane's coefficients on `side`.
    Coef coef(int side) const { return SpringLaw::coef(kappa(side)); }

    bool anchored() const { return m_.anchorage != AnchorageKind::free; }
    bool adaptive() const { return m_.anchorage == AnchorageKind::adaptive; }
    /// The spring that works on `side` (+1: theta > 0, the left one) still holds.
    bool intact(int side) const { return anchored() && !broken_[side > 0 ? 0 : 1]; }
    /// kappa = 8 b^2 K / I0 of the working spring; 0 at rest, broken or free.
    double kappa(int side) const {
        if (side == 0 || !intact(side)) return 0.0;
        return k_max_ ? m_.kappa_max : m_.kappa_min;
    }
    /// K of the working spring [N/m]; 0 at rest, broken or free.
    double stiffness_n_m(int side) const {
        if (side == 0 || !intact(side)) return 0.0;
        return k_max_ ? m_.k_max_n_m : m_.k_min_n_m;
    }
    /// |theta| at which the acting stiffness breaks (the scenario's break rule).
    double break_angle() const { return k_max_ ? m_.break_max : m_.break_min; }
    /// F / F_u of the acting stiffness at |theta| = phi.
    double force_ratio(double phi) const { return SpringLaw::force_ratio(k_max_ ? m_.force_max : m_.force_min, phi); }
    void fracture(int side) { broken_[side > 0 ? 0 : 1] = true; }
    bool broken(int side) const { return broken_[side > 0 ? 0 : 1]; }
    std::uint8_t broken_bits() const {
        return static_cast<std::uint8_t>((broken_[0] ? broken_left : 0) | (broken_[1] ? broken_right : 0));
    }
    /// Energy the K_min -> K_max switches put into the spring so far [J].
    double switch_energy() const { return e_switch_; }
    /// The adaptive law switches where the ground's acceleration changes sign (Eq. 21).
    bool switches_at_ground_zeros() const { return adaptive(); }

    BaseReactions reactions(int side, double ax, double ay, double theta, double theta_dot) const {
        return base_reactions(m_, side, kappa(side), stiffness_n_m(side), ax, ay, theta, theta_dot);
    }
    Works works(int side, const StepEnds& step, double t) const { return step_works(m_, stiffness_n_m(side), step, t); }
    /// The energy decision of Eq. 8's potential (energy.hpp), with the springs still intact.
    FreeFate free_fate(int side, double v) const { return rocksweep::free_fate(m_, side, v, !broken(1), !broken(-1)); }

    /// Uplift from rest: ax theta < 0 there, the adaptive law's K_max, and the spring is slack.
    void at_uplift() { k_max_ = true; }
    /// A run from a state other than rest (basins): K from the state, K_min at a turning point as
    /// after an outward swing; a spring whose angle lies below |theta0| broke getting there.
    template <class AxAhead>
    void at_start(int side, double theta, double theta_dot, bool acting, AxAhead&& ax_ahead) {
        k_max_ = false;
        follow_law(side, theta, theta_dot, acting, ax_ahead);
        if (intact(side) && side * theta >= break_angle()) fracture(side);
    }

    /// The adaptive law in continuous time (Eq. 21-22): while the ground acts, the sign of
    /// ax theta over the coming interval (ax_ahead(): ax at its middle, asked only here, since
    /// finding the interval costs); in free oscillation, theta theta_dot. The side stands for
    /// theta's sign, which is 0 just after an impact. On the switching surface K stays.
    template <class AxAhead>
    void follow_law(int side, double theta, double theta_dot, bool acting, AxAhead&& ax_ahead) {
        if (!adaptive() || side == 0) return;
        if (acting) switch_to(adaptive_uses_kmax(true, ax_ahead(), side, 0.0, k_max_), side, theta);
        else switch_to(adaptive_uses_kmax(false, 0.0, side, theta_dot, k_max_), side, theta);
    }
    /// The paper's scheme (Section 3.2): the law one step behind, K(t+1) from the state at t,
    /// Eq. 22 on |theta|'s change over the step.
    template <class AxNow>
    void follow_law_lagged(int side, double theta, double theta_prev, bool acting, AxNow&& ax_now) {
        if (!adaptive()) return;
        if (acting) switch_to(adaptive_uses_kmax(true, ax_now(), side, 0.0, k_max_), side, theta);
        else if (theta != 0.0) switch_to(adaptive_uses_kmax(false, 0.0, 1.0, std::abs(theta) - std::abs(theta_prev), k_max_), side, theta);
    }
    /// Eq. 22 at the outward turning point (an event the stepper located).
    void at_turn(int side, double theta) { switch_to(false, side, theta); }
    /// The turning point is an event only in free oscillation, for an intact adaptive spring
    /// moving outward.
    bool turn_armed(int side, double theta_dot, bool acting) const {
        return adaptive() && !acting && intact(side) && side * theta_dot > 0.0;
    }

private:
    const CellModel& m_;
    bool broken_[2] = {false, false};  ///< [0] left spring (theta > 0), [1] right
    bool k_max_ = true;                ///< adaptive: K = K_max now
    double e_switch_ = 0.0;

    /// A K_min -> K_max switch at nonzero elongation raises the spring's potential (that of
    /// Eq. 8, physics.md §4) by I0 [V(K_max) - V(K_min)]: the paper's law puts that energy into
    /// the block, and the histories report it. The passive law never does: the switch waits for
    /// theta = 0 (the next impact), where the law is asked again.
    void switch_to(bool kmax, int side, double theta) {
        if (kmax && !k_max_ && theta != 0.0 && intact(side)) {
            if (m_.adaptive_law == AdaptiveLaw::passive) return;
            const double phi = std::abs(theta);
            e_switch_ += m_.inertia * (spring_potential(m_, m_.kappa_max, phi) - spring_potential(m_, m_.kappa_min, phi));
        }
        k_max_ = kmax;
    }
};

static_assert(AnchorageLaw<Springs>);

}  // namespace rocksweep::kernel
