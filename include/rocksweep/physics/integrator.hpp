#pragma once
/// RK4 with located events, run over batches of cells (lanes).
#include <cstddef>
#include <functional>
#include <span>
#include <stdexcept>
#include <string>

#include "rocksweep/physics/model.hpp"
#include "rocksweep/physics/outcome.hpp"
#include "rocksweep/physics/step.hpp"

namespace rocksweep {

enum class Method {
    events,  ///< every discontinuity located inside the step and the step restarted there
    paper,   ///< fixed dt, impact taken at the step boundary (Section 3.2); comparison only
};
std::string to_string(Method m);

struct IntegratorSettings {
    Method method = Method::events;
    /// Accuracy knob: steps per period of the cell's fastest time scale (events method).
    double steps_per_period = 48.0;
    /// Under a record (events method): > 0, each step's local error, estimated by RK4's
    /// embedded third-order pair, is kept within this (absolute on theta / alpha and
    /// theta_dot / p) and the step chosen from it; steps_per_period then gives only the first
    /// step and the longest (x4). 0: the fixed step of steps_per_period (pulses always).
    /// docs/physics_kernel.md, "Error-controlled steps under records".
    double tolerance = 0.0;
    double paper_dt_s = 0.0025;       ///< fixed step of the paper's method
    std::int64_t max_steps = 2'000'000;  ///< a cell that needs more is reported not converged
    bool energy_stop = true;  ///< after the pulse, decide a safe block by energy
    double t_end_s = INFINITY;  ///< stop here even if undecided (histories); INFINITY: until decided
    /// A record's samples end steps (events method): each step then sees a linear ground. Off,
    /// steps of the knob's length cross samples on the record's moment nodes (--record-steps
    /// cross): ~1.4x faster at 48 steps per period, with 8x the theta error, third order, and on
    /// the shared suite 14 of 8640 outcomes off a tight reference instead of 2
    /// (physics_kernel.md, "Steps across a record's samples"). On until crossing costs no outcome.
    bool steps_end_at_samples = true;
    /// Polled every few hundred batch steps (well under a millisecond of work); when it returns
    /// true the integration throws Interrupted. Does not shape results.
    std::function<bool()> stop_requested;
};

/// Thrown by integrate_cells / integrate_cell when IntegratorSettings::stop_requested asks it
/// to stop: the cells of that call have no results.
class Interrupted : public std::runtime_error {
public:
    Interrupted() : std::runtime_error("integration interrupted by a stop request") {}
};

/// One accepted step or event, for histories.
struct StepRecord : StepEnds {
    double k_left, k_right;               ///< working stiffness over the step [N/m], 0 if idle
    double work_excitation, work_anchorage;  ///< cumulative at t1 (Eq. 23-24) [J], see step_works
    /// Cumulative energy the adaptive law's K_min -> K_max switches put into the spring before
    /// this step (at t0 and earlier) [J]; physics.md §4.
    double switch_energy;
    int impacts;
};
using StepObserver = std::function<void(const StepRecord&)>;

/// How full the batches stayed: lane-steps that advanced a cell / lane-steps in all.
struct BatchStats {
    std::int64_t batch_steps = 0;  ///< RK4 steps of the whole batch
    std::int64_t busy_lane_steps = 0;
    int lanes = 0;
    double utilisation() const {
        return batch_steps ? static_cast<double>(busy_lane_steps) / (static_cast<double>(batch_steps) * lanes) : 0.0;
    }
};

/// Runs each cell of `cells` to its outcome, `lanes` cells at a time (1, 4, 8 or 16), a lane
/// refilled as soon as its cell finishes. results[i] depends only on cells[i]. Adds to
/// `stats` when given.
void integrate_cells(std::span<const CellModel> cells, std::span<CellResult> results,
                     const IntegratorSettings& settings, int lanes = 8, BatchStats* stats = nullptr);

/// Same as one lane of integrate_cells, calling `observer` after every accepted step.
CellResult integrate_cell(const CellModel& cell, const IntegratorSettings& settings,
                          const StepObserver& observer = {});

}  // namespace rocksweep
