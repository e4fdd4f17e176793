#pragma once
// One cell's run as a lane of the W-lane kernel, for any anchorage law (anchorage_law.hpp):
// the cell's state machine (Lane), and the loop that keeps a batch of lanes busy (run_lanes).
// integrate_cells (integrator.cpp) runs it with the law of each cell's AnchorageKind (with_law).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>

#include "rocksweep/physics/anchorage_law.hpp"
#include "rocksweep/physics/integrator.hpp"
#include "batch.hpp"
#include "event_stepper.hpp"
#include "observers.hpp"
#include "rocking_events.hpp"

namespace rocksweep::kernel {

/// One cell's life: at rest, rocking, finished. It prepares each trial step of its lane, hands
/// the step's end to the event stepper with its event functions, and applies what happened at
/// an accepted end (impact, fracture, switch, overturning, the energy decision). The physics
/// is the system's and its anchorage law's (system.hpp, Law); the figures of the result are
/// the observers'.
template <AnchorageLaw Law>
class Lane {
public:
    Lane(const CellModel& m, const IntegratorSettings& s, const StepObserver* obs)
        : m_(m), set_(s), law_(m), extremes_(law_.anchored()) {
        if (obs) history_.emplace(m, *obs);
        t_pulse_end_ = m.pulse.end_time();
        ground_ = visit(m.pulse, [](const auto& e) { return e.lane_coefficients(); });
        nodal_ = visit(m.pulse, [](const auto& e) { return std::decay_t<decltype(e)>::nodal; });
        uplift_slope_ = m.uplift_slope();
        never_uplifts_ = m.never_uplifts();  // a record's peak is a scan of the whole table
        h_ = set_.method == Method::paper ? set_.paper_dt_s
                                          : 2.0 * M_PI / (std::max(m.omega_max(), Law::omega(m)) * set_.steps_per_period);
        adaptive_ = set_.method == Method::events && nodal_ && set_.tolerance > 0.0;
        h_max_ = 4.0 * h_;
        err_scale_y_ = 1.0 / (set_.tolerance * m.alpha);
        err_scale_v_ = 1.0 / (set_.tolerance * std::sqrt(m.p2) * m.alpha);
        r_.t_overturn_s = NAN;
        if (m.theta0 != 0.0 || m.theta_dot0 != 0.0) start_moving();
    }

    CellResult result() const {
        CellResult r = r_;
        r.max_rotation = extremes_.max_phi() / m_.alpha;
        r.peak_force_ratio = extremes_.peak_force();
        r.broken = law_.broken_bits();
        r.mu_required = demand_.mu_required();
        r.pivot_uplift = demand_.pivot_uplift() ? 1 : 0;
        return r;
    }

    /// Sets up the next trial step in lane i of the batch; advances a block at rest first.
    /// Returns false when the cell has finished.
    template <int W>
    bool prepare(Batch<W, Law>& b, int i) {
        while (!done_ && side_ == 0) leave_rest();
        if (done_) return false;
        if (r_.steps >= set_.max_steps) {
            finish(Outcome::not_converged);
            return false;
        }
        RhsLane<Law>& c = b.c[i];
        c.p2 = m_.p2;
        c.alpha = m_.alpha;
        c.law = law_.coef(side_);
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
        } else if (stepper_.searching()) {
            c.t_cut = in_pulse() ? INFINITY : -INFINITY;
            b.dt[i] = stepper_.trial();
        } else {
            c.t_cut = in_pulse() ? INFINITY : -INFINITY;
            boundary_ = next_boundary();
            clipped_ = boundary_ - t_ <= h_;
            b.dt[i] = clipped_ ? boundary_ - t_ : h_;
        }
        if (nodal_) c.nodes = nodes(b.dt[i], c.t_cut);
        return true;
    }

    template <int W>
    void finish_step(const Batch<W, Law>& b, int i) {
        ++r_.steps;
        if (set_.method == Method::paper) return paper_step(b.dt[i], b.y1[i], b.v1[i], b.a0[i]);
        if (adaptive_ && !stepper_.searching() && !control(b.dt[i], b.err_y[i], b.err_v[i])) return;
        const double a0 = b.a0[i];
        stepper_.finish(RockingEvents<Law>{law_, side_, th_, thd_, in_pulse(), m_, t_}, t_, th_, thd_, b.dt[i], b.y1[i], b.v1[i],
                        [&](double dt, double y1, double v1, Event e, bool interior) { accept(dt, y1, v1, a0, e, interior); });
    }

private:
    const CellModel& m_;
    const IntegratorSettings& set_;
    double t_ = 0.0, th_ = 0.0, thd_ = 0.0;
    int side_ = 0;  ///< +1: rocking with theta > 0; -1: theta < 0; 0: at rest
    mutable double zero_asked_ = INFINITY, zero_ = -INFINITY;  ///< next_ax_zero's cache: asked at, answer
    bool done_ = false;
    double t_pulse_end_, h_;  ///< h_: the next step's length (fixed, or chosen from the error)
    bool adaptive_ = false;  ///< h_ follows the error estimate (IntegratorSettings::tolerance)
    double h_max_ = INFINITY, err_scale_y_ = 0.0, err_scale_v_ = 0.0;
    GroundLane ground_;  ///< the pulse's coefficients in the lane loop
    bool nodal_ = false;  ///< the pulse's family takes its ground at the nodes from the lane
    double uplift_slope_;  ///< CellModel::uplift_slope, asked at every sample scanned at rest
    bool never_uplifts_;
    double boundary_ = INFINITY;
    bool clipped_ = false;  ///< the prepared step ends on boundary_ (or the paper's t_end)
    std::int64_t scans_ = 0;  ///< ground samples scanned outside RK4 steps (rest, uplift)
    CellResult r_{};
    Law law_;
    EventStepper stepper_;
    // observers
    Extremes extremes_;
    FrictionDemand<Law> demand_;
    std::optional<HistoryRecorder> history_;

    bool in_pulse() const { return t_ < t_pulse_end_; }

    /// Error control of a trial step of length dt (not a search's re-run, which is shorter and
    /// from the same start): its estimated local error, scaled by the tolerance, e = max(|e_theta|
    /// / alpha, |e_theta_dot| / (p alpha)) / tol. e > 1: rejected (false), the step is tried
    /// again from the same start, shorter. Else the next step is dt * 0.9 e^(-1/4), within
    /// [0.2, 4] dt and at most h_max_; a step cut short by a boundary (a sample) does not
    /// shorten the next one. The estimate is O(h^4) (the third-order member's error), so the
    /// error per step stays ~tol and the global error falls like tol. sqrt(sqrt()) is exact
    /// rounding on every machine: lanes and ranks take the same steps to the bit.
    bool control(double dt, double err_y, double err_v) {
        const double e = std::max(std::abs(err_y) * err_scale_y_, std::abs(err_v) * err_scale_v_);
        double f = e > 0.0 ? 0.9 / std::sqrt(std::sqrt(e)) : 4.0;
        f = std::clamp(f, 0.2, 4.0);
        if (e > 1.0 && dt > 1e-9 * h_max_) {
            h_ = dt * f;
            return false;
        }
        h_ = std::min(h_max_, clipped_ ? std::max(h_, dt * f) : dt * f);
        return true;
    }

    double next_boundary() const {
        double b = set_.t_end_s;
        if (in_pulse()) {
            b = std::min(b, t_pulse_end_);
            if (law_.switches_at_ground_zeros()) b = std::min(b, next_ax_zero());
            // Where a record's slope jumps, unless the steps cross its samples on moment nodes.
            if (set_.steps_end_at_samples) b = std::min(b, m_.pulse.next_kink(t_));
        }
        return b;
    }

    /// A nodal family's ground at the nodes of the step [t_, t_ + h]: the moment nodes for the
    /// events method, whose steps lie inside the pulse or after it; for the paper's, the values
    /// at the stage times, cut at t_cut as the other families' are.
    std::array<Ground, 3> nodes(double h, double t_cut) const {
        return visit(m_.pulse, [&](const auto& e) -> std::array<Ground, 3> {
            using F = std::decay_t<decltype(e)>;
            if constexpr (F::nodal) {
                if (set_.method == Method::events && h > 0.0)
                    return t_ < t_cut ? e.moment_nodes(t_, h) : std::array<Ground, 3>{};
                auto at = [&](double t) { return F::template lane<true>(ground_, t, t < t_cut ? 1.0 : 0.0); };
                return {at(t_), at(t_ + 0.5 * h), at(t_ + h)};
            } else {
                return {};
            }
        });
    }

    void finish(Outcome o) {
        r_.outcome = o;
        done_ = true;
    }

    /// The anchorage law's switches at the current state.
    void follow_law() { law_.follow_law(side_, th_, thd_, in_pulse(), [this] { return ax_ahead(); }); }
    /// The sign of ax over the coming interval, up to the next zero of ax, taken at its middle:
    /// robust at the zeros.
    double ax_ahead() const {
        const double tz = std::min({next_ax_zero(), t_pulse_end_, t_ + h_});
        return m_.pulse.ax(0.5 * (t_ + tz));
    }

    /// The ground's next zero after t_ (a law such as the adaptive one switches there), kept
    /// until t_ reaches it: time only moves forward, and the first zero after any t in
    /// [t_asked, zero) is the same one. A record's scan for it was 30 % of a suite's time when
    /// asked twice per step.
    double next_ax_zero() const {
        if (!(t_ >= zero_asked_ && t_ < zero_)) {
            zero_ = m_.pulse.next_ax_zero(t_);
            zero_asked_ = t_;
        }
        return zero_;
    }

    /// `kink`: the state is at a sample where the record turns (note_reactions_inside).
    void note_reactions(bool kink = false) {
        demand_.rocking(m_, t_, in_pulse(), side_, law_, th_, thd_, kink);
    }
    /// Whether a step ending at t ends on a sample where the record turns.
    bool ends_on_turn(double t) const {
        if (!nodal_ || !in_pulse()) return false;
        return visit(m_.pulse, [&](const auto& e) {
            if constexpr (std::decay_t<decltype(e)>::nodal) return e.turns_at(t);
            else return false;
        });
    }
    /// A step that crosses a record's samples (--record-steps cross): the demand also at each
    /// sample inside it where the ground turns, the state there from the step's cubic Hermite
    /// interpolant. f_x follows the ground, whose slope jumps at a sample, so |f_x / f_y| peaks
    /// at such a sample as often as not, where no parabola through the accepted states finds it
    /// (measured without: half the suite's safe cells low by more than 1 %, one in twelve by 10 %).
    void note_reactions_inside(double t0, double y0, double v0, double t1, double y1, double v1) {
        if (!nodal_ || set_.steps_end_at_samples || !in_pulse()) return;
        visit(m_.pulse, [&](const auto& e) {
            if constexpr (std::decay_t<decltype(e)>::nodal)
                e.turning_points(t0, t1, [&](double tk, const Ground& g) {
                    double y, v;
                    hermite_state(t1 - t0, y0, v0, y1, v1, tk - t0, y, v);
                    demand_.rocking(m_, tk, g, side_, law_, y, v, true);
                });
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

    void note_rest_demand(double t0, double t1) {
        demand_.at_rest(m_.pulse, t_pulse_end_, t0, t1, [this] { return charge(); });
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
        law_.at_uplift();
    }

    /// A run from a state other than rest (basins of attraction): already rocking, so the
    /// uplift test of leave_rest never applies. The side is theta0's sign, or theta_dot0's
    /// when theta0 = 0.
    void start_moving() {
        th_ = m_.theta0;
        thd_ = m_.theta_dot0;
        side_ = (th_ != 0.0 ? th_ : thd_) > 0.0 ? 1 : -1;
        law_.at_start(side_, th_, thd_, in_pulse(), [this] { return ax_ahead(); });
    }

    /// First time in [t, t_stop) at which the block uplifts, or +inf.
    double next_uplift(double t, double t_stop) {
        if (m_.uplifts(t, uplift_slope_)) return t;
        if (never_uplifts_) return INFINITY;  // decided without integrating
        return m_.pulse.first_uplift(t, t_stop, [this](const Ground& g) { return lifts(g.ax, g.ay, uplift_slope_); },
                                     [this] { return charge(); });
    }

    /// Takes the state at t + dt as the new state and applies what happened there (the event
    /// stepper's verdict; interior: a step cut at an in-step turning point).
    void accept(double dt, double y1, double v1, double a0, Event e, bool interior) {
        const double t0 = t_, y0 = th_, v0 = thd_;
        const double t1 = (e == Event::none && clipped_ && !interior) ? boundary_ : t_ + dt;
        // A turning point inside the step (one that reaches the fracture angle was located).
        if (side_ * v0 >= 0.0 && side_ * v1 < 0.0) note_extremes(peak_inside(dt, y0, v0, a0, t1, y1, v1));
        note_extremes(std::min(side_ * y1, M_PI / 2));
        if (history_) history_->step(t0, y0, v0, a0, t1, y1, v1, side_, law_, r_.impacts);
        note_reactions_inside(t0, y0, v0, t1, y1, v1);
        t_ = t1;
        th_ = y1;
        thd_ = v1;
        note_reactions(ends_on_turn(t1));  // just before the event: an impact's approach speed is the larger
        switch (e) {
            case Event::overturn: return overturn();
            case Event::fracture: return law_.fracture(side_);
            case Event::impact: return impact();
            case Event::turn: return law_.at_turn(side_, th_);
            case Event::trough:  // only located to decide an impact, never accepted as an event
            case Event::none: break;
        }
        if (t_ >= set_.t_end_s) return finish(Outcome::safe);
        follow_law();  // at a zero of ax or the end of the pulse
    }

    void note_extremes(double phi) { extremes_.add(phi, law_, side_); }

    /// The in-step peak of side * theta of a step that turns (from s theta_dot >= 0 at its
    /// start, which includes an uplift from rest, to < 0 at its end), on theta's quartic from
    /// theta'' at both ends. An intact spring's peak stays at its fracture angle: the located
    /// turning point (the grazing check) decided that the spring held.
    double peak_inside(double dt, double y0, double v0, double a0, double t1, double y1, double v1) const {
        const Ground g = in_pulse() ? Ground{m_.pulse.ax(t1), m_.pulse.ay(t1)} : Ground{};
        const double a1 = rocking::theta_ddot<Law>(rocking::coef(m_.p2, m_.alpha, side_, m_.equations == Equations::linearised),
                                                   law_.coef(side_), g, y1, v1);
        const double peak = quartic_peak(dt, side_, y0, v0, a0, v1, a1);
        return law_.intact(side_) ? std::min(peak, law_.break_angle()) : peak;
    }

    void overturn() {
        r_.t_overturn_s = t_;
        extremes_.overturned();
        finish(r_.impacts_total > 0 ? Outcome::overturned_impact : Outcome::overturned_no_impact);
    }

    void impact() {
        const double approach = std::abs(thd_);
        ++r_.impacts_total;
        th_ = 0.0;
        demand_.reset();
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
        follow_law();
        note_reactions();
        if (!in_pulse() && set_.energy_stop) {
            const FreeFate f = law_.free_fate(side_, std::abs(thd_));
            if (f.decided) {
                extremes_.add_decided(f.max_phi, f.peak_force, law_.anchored());
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
        note_extremes(std::min(side_ * y1, M_PI / 2));
        if (history_) history_->step(t0, y0, v0, a0, t1, y1, v1, side_, law_, r_.impacts);
        t_ = t1;
        th_ = y1;
        thd_ = v1;
        note_reactions();
        if (side_ * y1 >= M_PI / 2) return overturn();
        if (law_.intact(side_) && side_ * y1 >= law_.break_angle()) law_.fracture(side_);
        if (side_ * y1 < 0.0) {
            impact();
            if (done_ || side_ == 0) return;
        }
        law_.follow_law_lagged(side_, th_, y0, in_pulse(), [&] { return m_.pulse.ax(t_); });
        if (t_ >= set_.t_end_s) finish(Outcome::safe);
    }

    /// A block at rest until time t, for histories.
    void observe_rest(double t1) {
        if (history_ && t1 > t_) history_->step(t_, 0.0, 0.0, 0.0, t1, 0.0, 0.0, side_, law_, r_.impacts);
    }
};

/// Runs each cell to its outcome under the anchorage law Law, W cells at a time, a lane refilled
/// as soon as its cell finishes; calls *obs after every accepted step when given.
template <int W, AnchorageLaw Law>
void run_lanes(std::span<const CellModel> cells, std::span<CellResult> results,
               const IntegratorSettings& settings, const StepObserver* obs, BatchStats* stats = nullptr) {
    Batch<W, Law> b;
    std::array<std::optional<Lane<Law>>, W> lane;
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

}  // namespace rocksweep::kernel
