#include "rocksweep/physics/integrator.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cfloat>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <stdexcept>

#include "rocksweep/physics/energy.hpp"
#include "batch.hpp"

namespace rocksweep {

std::string to_string(Method m) { return m == Method::events ? "events" : "paper"; }

std::string to_string(Outcome o) {
    switch (o) {
        case Outcome::safe: return "safe";
        case Outcome::overturned_impact: return "overturned_with_impact";
        case Outcome::overturned_no_impact: return "overturned_without_impact";
        case Outcome::not_converged: return "not_converged";
    }
    return "?";
}

namespace {

constexpr double kHalfPi = M_PI / 2;

using kernel::Batch;
using kernel::RhsLane;

enum class Event { none, overturn, fracture, impact, turn };

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

/// The state machine of one cell: what its next trial step is, and what the step's end means.
class Lane {
public:
    Lane(const CellModel& m, const IntegratorSettings& s, const StepObserver* obs)
        : m_(m), set_(s), obs_(obs) {
        t_pulse_end_ = m.pulse.end_time();
        ground_ = visit(m.pulse, [](const auto& e) { return e.lane_coefficients(); });
        h_ = set_.method == Method::paper ? set_.paper_dt_s
                                          : 2.0 * M_PI / (m.omega_max() * set_.steps_per_period);
        r_.t_overturn_s = NAN;
        r_.peak_force_ratio = m.anchorage == AnchorageKind::free ? NAN : 0.0;
        if (m.theta0 != 0.0 || m.theta_dot0 != 0.0) start_moving();
    }

    bool finished() const { return done_; }
    CellResult result() const {
        CellResult r = r_;
        r.max_rotation = max_phi_ / m_.alpha;
        r.broken = static_cast<std::uint8_t>((broken_[0] ? broken_left : 0) | (broken_[1] ? broken_right : 0));
        r.mu_required = mu_;
        r.pivot_uplift = pivot_up_ ? 1 : 0;
        return r;
    }

    /// Sets up the next trial step in lane i of the batch; advances a block at rest first.
    /// Returns false when the cell has finished.
    template <int W>
    bool prepare(Batch<W>& b, int i) {
        while (!done_ && side_ == 0) leave_rest();
        if (done_) return false;
        if (r_.steps >= set_.max_steps) {
            finish(Outcome::not_converged);
            return false;
        }
        RhsLane& c = b.c[i];
        c.p2 = m_.p2;
        c.alpha = m_.alpha;
        c.kappa = kappa();
        c.pulse = &m_.pulse;
        c.ground = ground_;
        c.linear = m_.equations == Equations::linearised;
        c.side = side_;
        b.t0[i] = t_;
        b.y0[i] = th_;
        b.v0[i] = thd_;
        if (set_.method == Method::paper) {
            c.t_cut = t_pulse_end_;  // the ground stops mid-step, as in a fixed-step code
            // Only the end of a record cuts a step short.
            clipped_ = set_.t_end_s - t_ <= h_;
            b.dt[i] = clipped_ ? set_.t_end_s - t_ : h_;
        } else if (searching_) {
            c.t_cut = in_pulse() ? INFINITY : -INFINITY;
            b.dt[i] = trial_;
        } else {
            c.t_cut = in_pulse() ? INFINITY : -INFINITY;
            boundary_ = next_boundary();
            clipped_ = boundary_ - t_ <= h_;
            b.dt[i] = clipped_ ? boundary_ - t_ : h_;
        }
        return true;
    }

    template <int W>
    void finish_step(const Batch<W>& b, int i) {
        ++r_.steps;
        if (set_.method == Method::paper)
            paper_step(b.dt[i], b.y1[i], b.v1[i], b.a0[i]);
        else
            event_step(b.dt[i], b.y1[i], b.v1[i], b.a0[i]);
    }

private:
    const CellModel& m_;
    const IntegratorSettings& set_;
    const StepObserver* obs_;
    double t_ = 0.0, th_ = 0.0, thd_ = 0.0;
    int side_ = 0;  ///< +1: rocking with theta > 0; -1: theta < 0; 0: at rest
    bool broken_[2] = {false, false};  ///< [0] left spring (theta > 0), [1] right
    bool k_max_ = true;                ///< adaptive: K = K_max now
    bool done_ = false;
    double t_pulse_end_, h_;
    GroundLane ground_;  ///< the pulse's coefficients in the lane loop
    double boundary_ = INFINITY;
    bool clipped_ = false;
    // event search on the current step: the root lies in (lo, hi]
    bool searching_ = false;
    /// What the search locates: Event::none = the earliest of all events at the step's end;
    /// Event::turn with peak_check_ = the in-step turning point of a step whose interpolated
    /// peak reaches the fracture angle (a grazing fracture that the step's ends do not see).
    Event target_ = Event::none;
    bool peak_check_ = false;
    double lo_ = 0.0, hi_ = 0.0, g_lo_ = 0.0, g_hi_ = 0.0, trial_ = 0.0, width_ = 0.0;
    int last_moved_ = 0, iterations_ = 0;
    double hi_y_ = 0.0, hi_v_ = 0.0;
    double max_phi_ = 0.0;
    double mu_ = 0.0;           ///< max |f_x / f_y| so far
    bool pivot_up_ = false;     ///< f_y < 0 seen
    ThreePointExtreme demand_, lift_;  ///< in-step extremes of |f_x / f_y| and f_y
    double react_kappa_ = -1.0;        ///< the spring of the points they hold
    double w_exc_ = 0.0, w_anch_ = 0.0;
    double e_switch_ = 0.0;  ///< energy the K_min -> K_max switches put into the spring [J]
    std::int64_t scans_ = 0;  ///< ground samples scanned outside RK4 steps (rest, uplift)
    CellResult r_{};

    bool in_pulse() const { return t_ < t_pulse_end_; }
    bool anchored() const { return m_.anchorage != AnchorageKind::free; }
    bool intact(int side) const { return anchored() && !broken_[side > 0 ? 0 : 1]; }
    double kappa() const {
        if (side_ == 0 || !intact(side_)) return 0.0;
        return k_max_ ? m_.kappa_max : m_.kappa_min;
    }
    double break_angle() const { return k_max_ ? m_.break_max : m_.break_min; }
    double force_coef() const { return k_max_ ? m_.force_max : m_.force_min; }
    double ax_at(double t) const { return t < t_pulse_end_ ? m_.pulse.ax(t) : 0.0; }

    double next_boundary() const {
        double b = set_.t_end_s;
        if (in_pulse()) {
            b = std::min(b, t_pulse_end_);
            if (m_.anchorage == AnchorageKind::adaptive) b = std::min(b, m_.pulse.next_ax_zero(t_));
            // Where the ground stops being smooth (a record's samples) steps end, so the error
            // stays that of a smooth right-hand side.
            b = std::min(b, m_.pulse.next_kink(t_));
        }
        return b;
    }

    void finish(Outcome o) {
        r_.outcome = o;
        done_ = true;
    }

    /// The adaptive law in continuous time (physics.md §4). On the switching surface itself
    /// the previous K stays.
    void update_stiffness() {
        if (m_.anchorage != AnchorageKind::adaptive || side_ == 0) return;
        // The side stands for theta's sign: theta is 0 just after an impact.
        if (in_pulse()) {
            // Sign of ax over the coming interval, taken at its middle: robust at the zeros.
            const double tz = std::min({m_.pulse.next_ax_zero(t_), t_pulse_end_, t_ + h_});
            set_kmax(adaptive_uses_kmax(true, m_.pulse.ax(0.5 * (t_ + tz)), side_, 0.0, k_max_));
        } else {
            set_kmax(adaptive_uses_kmax(false, 0.0, side_, thd_, k_max_));
        }
    }

    /// Switches the adaptive spring. A K_min -> K_max switch at nonzero elongation raises the
    /// spring's potential (that of Eq. 8, physics.md §4) by I0 [V(K_max) - V(K_min)]: the
    /// paper's law puts that energy into the block, and the histories report it. The passive
    /// law never does: the switch waits for theta = 0 (the next impact), where the law is asked
    /// again.
    void set_kmax(bool kmax) {
        if (kmax && !k_max_ && th_ != 0.0 && intact(side_)) {
            if (m_.adaptive_law == AdaptiveLaw::passive) return;
            const double phi = std::abs(th_);
            e_switch_ += m_.inertia * (spring_potential(m_, m_.kappa_max, phi) - spring_potential(m_, m_.kappa_min, phi));
        }
        k_max_ = kmax;
    }

    void note_extremes(double phi) {
        max_phi_ = std::max(max_phi_, phi);
        if (intact(side_)) r_.peak_force_ratio = std::max(r_.peak_force_ratio, force_coef() * std::tan(0.5 * phi));
    }

    /// Base reactions while rocking (physics.md §6, Eq. 16-18), per unit m g, from the motion of
    /// the centre of mass about the pivot at x = s b: x = s b - s R sin(alpha - phi),
    /// y = R cos(alpha - phi), phi = s theta. The working spring pulls the lifted corner down,
    /// which presses the pivot: f_y gains F_s / (m g). Checked at every accepted state and just
    /// after each impact. In free rocking the demand peaks as the block settles (phi, phi' -> 0),
    /// at (sin a cos a / i) / (1 - sin^2 a / i) with i = I0/(mR^2) >= 1, below the tan(alpha)
    /// that uplift itself needs: the energy decision leaves nothing out. Only |theta| <= alpha
    /// is checked.
    void note_reactions() {
        const double phi = side_ * th_;
        // Past alpha the block is beyond its static stability limit: a fall to the ground needs
        // ever more friction (f_y -> 0 as theta_dot grows) and says nothing about survival.
        if (phi > m_.alpha) return reset_reactions();
        // A spring that breaks or switches makes f_y jump: no parabola across the jump.
        if (kappa() != react_kappa_) reset_reactions();
        react_kappa_ = kappa();
        const bool acting = in_pulse();
        const double ax = acting ? m_.pulse.ax(t_) : 0.0, ay = acting ? m_.pulse.ay(t_) : 0.0;
        const double k = intact(side_) ? (k_max_ ? m_.k_max_n_m : m_.k_min_n_m) : 0.0;
        const BaseReactions f = base_reactions(m_, side_, kappa(), k, ax, ay, th_, thd_);
        const double fx = f.fx, fy = f.fy;
        if (fy <= 0.0) pivot_up_ = true;
        else mu_ = std::max(mu_, demand_.add(t_, std::abs(fx) / fy, 1.0));
        if (lift_.add(t_, fy, -1.0) <= 0.0) pivot_up_ = true;
    }
    /// A new rocking phase (impact, rest, past alpha): no parabola across it.
    void reset_reactions() {
        demand_.reset();
        lift_.reset();
    }

    /// At rest on the moving ground the base carries m (g + ay) and m ax: the friction needed is
    /// max |ax| / (1 + ay) over [t0, t1] of the pulse, taken at its ends and where the pulse
    /// says |ax| may peak (and on its scan with a vertical component).
    void note_rest_demand(double t0, double t1) {
        t1 = std::min(t1, t_pulse_end_);
        if (!(t1 >= t0)) return;
        auto demand = [&](double t) { return std::abs(m_.pulse.ax(t)) / (1.0 + m_.pulse.ay(t)); };
        mu_ = std::max({mu_, demand(t0), demand(t1 < t_pulse_end_ ? t1 : std::nextafter(t1, t0))});
        m_.pulse.demand_points(t0, t1, [&](double t) {
            if (!charge()) return false;
            if (t > t0) mu_ = std::max(mu_, demand(t));
            return true;
        });
    }

    /// One ground sample scanned outside the RK4 steps (uplift search, friction demand at rest),
    /// counted against the step cap with the steps: a scan that cannot progress (omega_p so
    /// large that t + T/512 == t, or NaN) ends as not_converged within the cap like any runaway
    /// cell. A stop request is honoured here too, as between batch steps. False: out of budget.
    bool charge() {
        ++scans_;
        if ((scans_ & 4095) == 0 && set_.stop_requested && set_.stop_requested()) throw Interrupted();
        if (r_.steps + scans_ < set_.max_steps) return true;
        finish(Outcome::not_converged);
        return false;
    }

    /// From rest: wait for the ground to lift a corner (Eq. 1), or finish safe.
    void leave_rest() {
        const double tu = in_pulse() ? next_uplift(t_, std::min(t_pulse_end_, set_.t_end_s)) : INFINITY;
        if (done_) return;
        if (!std::isfinite(tu)) {
            const double t_stop = std::min(std::max(t_, t_pulse_end_), set_.t_end_s);
            note_rest_demand(t_, t_stop);
            if (done_) return;
            observe_rest(t_stop);
            t_ = t_stop;
            finish(Outcome::safe);
            return;
        }
        note_rest_demand(t_, tu);
        if (done_) return;
        observe_rest(tu);
        t_ = tu;
        th_ = thd_ = 0.0;
        side_ = m_.pulse.ax(tu) > 0.0 ? -1 : 1;  // positive ground acceleration tips to theta < 0
        k_max_ = true;  // at uplift ax theta < 0: the adaptive law's K_max
    }

    /// A run from a state other than rest (basins of attraction): already rocking, so the
    /// uplift test of leave_rest never applies. The side is theta0's sign, or theta_dot0's
    /// when theta0 = 0. The adaptive law picks K from the state (Eq. 21-22); at theta_dot0 = 0
    /// it takes K_min, as at the turning point of an outward swing.
    void start_moving() {
        th_ = m_.theta0;
        thd_ = m_.theta_dot0;
        side_ = (th_ != 0.0 ? th_ : thd_) > 0.0 ? 1 : -1;
        k_max_ = false;
        update_stiffness();
        if (intact(side_) && side_ * th_ >= break_angle()) broken_[side_ > 0 ? 0 : 1] = true;
    }

    /// First time in [t, t_stop) at which the block uplifts, or +inf.
    double next_uplift(double t, double t_stop) {
        if (m_.uplifts(t)) return t;
        if (m_.never_uplifts()) return INFINITY;  // decided without integrating
        return m_.pulse.first_uplift(t, t_stop, [this](double x) { return m_.uplifts(x); }, [this] { return charge(); });
    }

    // ---- event functions: positive before the event, <= 0 once it has happened ----
    bool turn_armed() const {
        return m_.anchorage == AnchorageKind::adaptive && !in_pulse() && intact(side_) && side_ * thd_ > 0.0;
    }
    double g_event(Event e, double d, double y, double v) const {
        const double s = side_;
        switch (e) {
            case Event::overturn: return kHalfPi - s * y;
            case Event::fracture: return break_angle() - s * y;
            case Event::impact:
                // theta starts at 0 after an impact or uplift: divide out the trivial root.
                if (th_ != 0.0) return s * y;
                return s * thd_ > 0.0 ? s * y / d : s * y / (d * d);
            case Event::turn: return s * v;
            case Event::none: break;
        }
        return 1.0;
    }
    Event first_event(double d, double y, double v, double& g) const {
        Event which = Event::none;
        g = INFINITY;
        auto consider = [&](Event e) {
            const double ge = g_event(e, d, y, v);
            if (ge < g) { g = ge; which = e; }
        };
        consider(Event::overturn);
        if (intact(side_)) consider(Event::fracture);
        consider(Event::impact);
        if (turn_armed()) consider(Event::turn);
        return which;
    }

    /// The value the current search drives to zero.
    double g_search(double d, double y, double v) const {
        double g;
        if (target_ == Event::none) first_event(d, y, v, g);
        else g = g_event(target_, d, y, v);
        return g;
    }

    /// Starts an Illinois search for a root in (lo, hi]; g_lo may be NaN (no value at lo).
    void start_search(Event target, double lo, double g_lo, double hi, double g_hi, double y_hi, double v_hi) {
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
    }

    /// A step with no event at its end whose |theta| turns inside it: true if the cubic Hermite
    /// peak comes within a margin of the fracture angle. The margin covers the interpolant's
    /// O(dt^4) error (a tenth of the peak's rise above the ends, which is O(dt^2)) and the RK4
    /// states' own; the located turning point then decides.
    bool peak_may_break(double dt, double y1, double v1) const {
        if (!intact(side_)) return false;
        const double s = side_, v0 = thd_, y0 = th_;
        if (!(s * v0 > 0.0 && s * v1 < 0.0)) return false;
        const double peak = s * hermite_peak(dt, y0, v0, y1, v1);
        const double ends = std::max(s * y0, s * y1);
        return peak >= break_angle() - (1e-4 * break_angle() + 0.1 * (peak - ends));
    }

    void event_step(double dt, double y1, double v1, double a0) {
        const double g = g_search(dt, y1, v1);
        if (!searching_) {
            if (g > 0.0) {
                if (!peak_may_break(dt, y1, v1)) {
                    accept(dt, y1, v1, a0, Event::none);
                    return;
                }
                // Locate the turning point (side * theta_dot = 0, positive at the start, <= 0 at
                // the end) on re-run RK4 steps; its height decides the fracture.
                peak_check_ = true;
                start_search(Event::turn, 0.0, side_ * thd_, dt, side_ * v1, y1, v1);
                return;
            }
            // The earliest event lies in (0, dt]: find it by Illinois (regula falsi that halves
            // the value of an end kept twice), each trial a fresh RK4 step from the same start,
            // so that the state at the event carries the RK4 local error only.
            start_search(Event::none, 0.0, NAN, dt, g, y1, v1);  // the functions may vanish at 0
            return;
        }
        ++iterations_;
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
        const double tol = std::max(4.0 * DBL_EPSILON * (std::abs(t_) + hi_), 1e-12 * hi_);
        if (hi_ - lo_ <= tol || iterations_ >= 100) {
            searching_ = false;
            const Event target = target_;
            target_ = Event::none;  // the next step looks for every event again
            if (peak_check_) {
                peak_check_ = false;
                const double gf = g_event(Event::fracture, hi_, hi_y_, hi_v_);
                if (gf <= 0.0) {
                    // The peak passes the fracture angle: the fracture lies in (0, peak].
                    start_search(Event::fracture, 0.0, g_event(Event::fracture, 0.0, th_, thd_), hi_, gf, hi_y_, hi_v_);
                    return;
                }
                // The spring holds: the step ends at the turning point (an ordinary step end).
                clipped_ = false;
                accept(hi_, hi_y_, hi_v_, a0, Event::none);
                return;
            }
            double gh;
            const Event which = target == Event::none ? first_event(hi_, hi_y_, hi_v_, gh) : target;
            accept(hi_, hi_y_, hi_v_, a0, which);
            return;
        }
        double x = 0.5 * (lo_ + hi_);
        // Guard: bisect when there is no value at lo yet, or the bracket stopped shrinking.
        if (!std::isnan(g_lo_) && (iterations_ % 4 != 0 || hi_ - lo_ < 0.5 * width_)) {
            const double xs = lo_ + (hi_ - lo_) * g_lo_ / (g_lo_ - g_hi_);
            if (xs > lo_ && xs < hi_) x = xs;
        }
        if (iterations_ % 4 == 0) width_ = hi_ - lo_;
        trial_ = x;
    }

    /// |theta|'s turning point inside a step from the cubic Hermite interpolant of (theta,
    /// theta_dot), at the zero of the linear interpolant of theta_dot: error O(dt^4) in the peak.
    static double hermite_peak(double dt, double y0, double v0, double y1, double v1) {
        const double tau = v0 / (v0 - v1);
        double theta, theta_dot;  // theta_dot unused: theta'' at the ends is not needed here
        StepEnds{0.0, y0, v0, 0.0, dt, y1, v1, 0.0}.at(tau * dt, theta, theta_dot);
        return theta;
    }

    /// Takes the state at t + dt as the new state and applies what happened there.
    void accept(double dt, double y1, double v1, double a0, Event e) {
        const double t0 = t_, y0 = th_, v0 = thd_;
        const double t1 = (e == Event::none && clipped_) ? boundary_ : t_ + dt;
        // A turning point inside the step (one that reaches the fracture angle was located).
        if (side_ * v0 > 0.0 && side_ * v1 < 0.0) note_extremes(side_ * hermite_peak(dt, y0, v0, y1, v1));
        note_extremes(std::min(side_ * y1, kHalfPi));
        if (obs_) observe(t0, y0, v0, a0, t1, y1, v1);
        t_ = t1;
        th_ = y1;
        thd_ = v1;
        note_reactions();  // just before the event: an impact's approach speed is the larger
        switch (e) {
            case Event::overturn: return overturn();
            case Event::fracture:
                broken_[side_ > 0 ? 0 : 1] = true;
                return;
            case Event::impact: return impact();
            case Event::turn:
                set_kmax(false);
                return;
            case Event::none: break;
        }
        if (t_ >= set_.t_end_s) return finish(Outcome::safe);
        update_stiffness();  // at a zero of ax or the end of the pulse
    }

    void overturn() {
        r_.t_overturn_s = t_;
        max_phi_ = kHalfPi;
        finish(r_.impacts_total > 0 ? Outcome::overturned_impact : Outcome::overturned_no_impact);
    }

    void impact() {
        const double approach = std::abs(thd_);
        ++r_.impacts_total;
        th_ = 0.0;
        reset_reactions();
        if (approach < m_.v_threshold) {
            // The block is settling: the remaining impacts pile up in a time of order
            // 2 v / (p^2 alpha (1 - e)). Take it as at rest (physics.md §5).
            thd_ = 0.0;
            side_ = 0;
            return;
        }
        ++r_.impacts;
        thd_ *= m_.e;
        side_ = -side_;
        update_stiffness();
        note_reactions();
        if (!in_pulse() && set_.energy_stop) {
            const FreeFate f = free_fate(m_, side_, std::abs(thd_), !broken_[0], !broken_[1]);
            if (f.decided) {
                max_phi_ = std::max(max_phi_, f.max_phi);
                if (anchored()) r_.peak_force_ratio = std::max(r_.peak_force_ratio, f.peak_force);
                r_.impacts += f.impacts;
                r_.impacts_total += f.impacts_total;
                finish(Outcome::safe);
            }
        }
    }

    /// The paper's scheme (Section 3.2): fixed dt, checks at the end of the step only, the
    /// adaptive law one step behind.
    void paper_step(double dt, double y1, double v1, double a0) {
        const double t0 = t_, y0 = th_, v0 = thd_;
        const double t1 = clipped_ ? set_.t_end_s : t_ + dt;
        note_extremes(std::min(side_ * y1, kHalfPi));
        if (obs_) observe(t0, y0, v0, a0, t1, y1, v1);
        t_ = t1;
        th_ = y1;
        thd_ = v1;
        note_reactions();
        if (side_ * y1 >= kHalfPi) return overturn();
        if (intact(side_) && side_ * y1 >= break_angle()) broken_[side_ > 0 ? 0 : 1] = true;
        if (side_ * y1 < 0.0) {
            impact();
            if (done_ || side_ == 0) return;
        }
        if (m_.anchorage == AnchorageKind::adaptive) {
            // One step behind, as the paper's K(t+1) from the state at t; Eq. 22 on |theta|'s
            // change over the step.
            if (in_pulse()) set_kmax(adaptive_uses_kmax(true, m_.pulse.ax(t_), side_, 0.0, k_max_));
            else if (th_ != 0.0) set_kmax(adaptive_uses_kmax(false, 0.0, 1.0, std::abs(th_) - std::abs(y0), k_max_));
        }
        if (t_ >= set_.t_end_s) finish(Outcome::safe);
    }

    /// A block at rest until time t, for histories.
    void observe_rest(double t1) {
        if (obs_ && t1 > t_) observe(t_, 0.0, 0.0, 0.0, t1, 0.0, 0.0);
    }

    void observe(double t0, double y0, double v0, double a0, double t1, double y1, double v1) {
        StepRecord s{};
        s.t0 = t0; s.theta0 = y0; s.theta_dot0 = v0; s.acc0 = a0;
        s.t1 = t1; s.theta1 = y1; s.theta_dot1 = v1;
        const double ax1 = t1 < t_pulse_end_ || (t1 == t_pulse_end_ && t0 < t1) ? m_.pulse.ax(t1) : 0.0;
        const double ay1 = t1 <= t_pulse_end_ ? m_.pulse.ay(t1) : 0.0;
        s.acc1 = side_ == 0 ? 0.0 : rocking_acceleration(m_, side_, kappa(), ax1, ay1, y1);
        const double k = side_ == 0 || !intact(side_) ? 0.0 : (k_max_ ? m_.k_max_n_m : m_.k_min_n_m);
        s.k_left = side_ > 0 ? k : 0.0;
        s.k_right = side_ < 0 ? k : 0.0;
        const Works w = step_works(m_, k, s, t1);
        w_exc_ += w.excitation_j;
        w_anch_ += w.anchorage_j;
        s.work_excitation = w_exc_;
        s.work_anchorage = w_anch_;
        s.switch_energy = e_switch_;
        s.impacts = r_.impacts;
        (*obs_)(s);
    }
};

template <int W>
void run_lanes(std::span<const CellModel> cells, std::span<CellResult> results,
               const IntegratorSettings& settings, const StepObserver* obs, BatchStats* stats = nullptr) {
    Batch<W> b;
    std::array<std::optional<Lane>, W> lane;
    std::array<std::size_t, W> index{};
    std::size_t next = 0;
    int live = 0;
    auto refill = [&](int i) {
        // A finished lane takes the next cell at once, so that lanes stay busy.
        while (next < cells.size()) {
            lane[i].emplace(cells[next], settings, obs);
            index[i] = next++;
            if (lane[i]->prepare(b, i)) return true;
            results[index[i]] = lane[i]->result();
        }
        lane[i].reset();
        return false;
    };
    for (int i = 0; i < W; ++i) live += refill(i) ? 1 : 0;
    // A stop request is honoured within ~256 batch steps, even inside one slow cell.
    std::uint32_t until_poll = 256;
    while (live > 0) {
        if (settings.stop_requested && --until_poll == 0) {
            until_poll = 256;
            if (settings.stop_requested()) throw Interrupted();
        }
        for (int i = 0; i < W; ++i)
            if (!lane[i]) b.dt[i] = 0.0;  // idle lane: a harmless zero step
        b.step();
        if (stats) {
            ++stats->batch_steps;
            stats->busy_lane_steps += live;
        }
        for (int i = 0; i < W; ++i) {
            if (!lane[i]) continue;
            lane[i]->finish_step(b, i);
            if (lane[i]->prepare(b, i)) continue;
            results[index[i]] = lane[i]->result();
            if (!refill(i)) --live;
        }
    }
}

}  // namespace

void integrate_cells(std::span<const CellModel> cells, std::span<CellResult> results,
                     const IntegratorSettings& settings, int lanes, BatchStats* stats) {
    if (results.size() != cells.size()) throw std::invalid_argument("integrate_cells: size mismatch");
    if (stats) stats->lanes = lanes;
    switch (lanes) {
        case 1: return run_lanes<1>(cells, results, settings, nullptr, stats);
        case 4: return run_lanes<4>(cells, results, settings, nullptr, stats);
        case 8: return run_lanes<8>(cells, results, settings, nullptr, stats);
        case 16: return run_lanes<16>(cells, results, settings, nullptr, stats);
        default: throw std::invalid_argument("integrate_cells: lanes must be 1, 4, 8 or 16");
    }
}

CellResult integrate_cell(const CellModel& cell, const IntegratorSettings& settings, const StepObserver& observer) {
    CellResult r;
    run_lanes<1>(std::span<const CellModel>(&cell, 1), std::span<CellResult>(&r, 1), settings,
                 observer ? &observer : nullptr);
    return r;
}

}  // namespace rocksweep
