#include "rocksweep/physics/history.hpp"

#include <cmath>

#include "rocksweep/physics/energy.hpp"
#include "rocksweep/core/errors.hpp"

namespace rocksweep {

History sample_history(const CellModel& cell, IntegratorSettings settings, double output_dt_s, double t_end_s) {
    require_open("output-dt", output_dt_s, 0.0, INFINITY, "an interval > 0 s");
    require_open("t-end", t_end_s, 0.0, INFINITY, "a time > 0 s");
    settings.t_end_s = t_end_s;
    settings.energy_stop = false;  // a history shows the whole motion, not only its verdict
    History h;
    std::size_t k = 0;
    auto sample_time = [&](std::size_t i) { return static_cast<double>(i) * output_dt_s; };
    StepRecord last{};
    bool any = false;
    auto push = [&](double t, double th, double thd, const StepRecord& s, const Works& since_t1) {
        h.t.push_back(t);
        h.theta.push_back(th);
        h.theta_dot.push_back(thd);
        h.k_left.push_back(s.k_left);
        h.k_right.push_back(s.k_right);
        const double ax = t < cell.pulse.end_time() ? cell.pulse.ax(t) : 0.0;
        h.ground_acc.push_back(ax * cell.gravity);
        h.w_excitation.push_back(s.work_excitation - since_t1.excitation_j);
        h.w_anchorage.push_back(s.work_anchorage - since_t1.anchorage_j);
        h.e_switch.push_back(s.switch_energy);
    };
    const StepObserver obs = [&](const StepRecord& s) {
        // The step's works from each sample time t to its end, taken off the cumulative value at
        // t1; the works up to t are added up sample by sample, so that a long step (a block at
        // rest through a whole record) costs its samples once, not once per output sample.
        const double k_n_m = s.k_left + s.k_right;
        Works all{}, to_t{};
        bool have_all = false;
        double t_prev = s.t0;
        while (sample_time(k) <= s.t1 && sample_time(k) <= t_end_s) {
            const double t = sample_time(k);
            if (t < s.t0) { ++k; continue; }
            double th, thd;
            s.at(t, th, thd);
            if (!have_all) all = step_works(cell, k_n_m, s, s.t1), have_all = true;
            const Works piece = step_works(cell, k_n_m, s, t_prev, t);
            to_t.excitation_j += piece.excitation_j;
            to_t.anchorage_j += piece.anchorage_j;
            t_prev = t;
            push(t, th, thd, s, Works{all.excitation_j - to_t.excitation_j, all.anchorage_j - to_t.anchorage_j});
            ++k;
        }
        last = s;
        any = true;
    };
    h.result = integrate_cell(cell, settings, obs);
    // No switch follows the last step with the spring stretched: the run ends there (t_end,
    // overturning) or the block is at rest.
    h.switch_energy_j = any ? last.switch_energy : 0.0;
    // A block at rest, or lying on its side, keeps its last state to the end of the record.
    if (any && std::isnan(h.result.t_overturn_s)) {
        StepRecord rest = last;
        rest.k_left = rest.k_right = 0.0;
        while (sample_time(k) <= t_end_s * (1 + 1e-12)) {
            push(sample_time(k), last.theta1, last.theta_dot1, rest, Works{});
            ++k;
        }
    }
    return h;
}

}  // namespace rocksweep
