#include "rocksweep/history.hpp"

#include <cmath>

#include "rocksweep/errors.hpp"

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
    auto push = [&](double t, double th, double thd, const StepRecord& s) {
        h.t.push_back(t);
        h.theta.push_back(th);
        h.theta_dot.push_back(thd);
        h.k_left.push_back(s.k_left);
        h.k_right.push_back(s.k_right);
        const double ax = t < cell.pulse.end_time() ? cell.pulse.ax(t) : 0.0;
        h.ground_acc.push_back(ax * cell.gravity);
        // Works are kept per step; between step ends they follow linearly.
        h.w_excitation.push_back(s.work_excitation);
        h.w_anchorage.push_back(s.work_anchorage);
    };
    const StepObserver obs = [&](const StepRecord& s) {
        const double dt = s.t1 - s.t0;
        while (sample_time(k) <= s.t1 && sample_time(k) <= t_end_s) {
            const double t = sample_time(k);
            if (t < s.t0) { ++k; continue; }
            // Cubic Hermite on (theta, theta_dot) and on (theta_dot, theta'').
            const double u = dt > 0.0 ? (t - s.t0) / dt : 1.0;
            const double h00 = (1 + 2 * u) * (1 - u) * (1 - u), h10 = u * (1 - u) * (1 - u);
            const double h01 = u * u * (3 - 2 * u), h11 = u * u * (u - 1);
            const double th = h00 * s.theta0 + h10 * dt * s.theta_dot0 + h01 * s.theta1 + h11 * dt * s.theta_dot1;
            const double thd = h00 * s.theta_dot0 + h10 * dt * s.acc0 + h01 * s.theta_dot1 + h11 * dt * s.acc1;
            push(t, th, thd, s);
            ++k;
        }
        last = s;
        any = true;
    };
    h.result = integrate_cell(cell, settings, obs);
    // A block at rest, or lying on its side, keeps its last state to the end of the record.
    if (any && std::isnan(h.result.t_overturn_s)) {
        StepRecord rest = last;
        rest.k_left = rest.k_right = 0.0;
        while (sample_time(k) <= t_end_s * (1 + 1e-12)) {
            push(sample_time(k), last.theta1, last.theta_dot1, rest);
            ++k;
        }
    }
    return h;
}

}  // namespace rocksweep
