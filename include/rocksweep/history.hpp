#pragma once
/// One time history sampled at a fixed output interval.
#include <vector>

#include "rocksweep/integrator.hpp"

namespace rocksweep {

struct History {
    std::vector<double> t;             ///< [s]
    std::vector<double> theta;         ///< [rad]
    std::vector<double> theta_dot;     ///< [rad/s]
    std::vector<double> k_left;        ///< working stiffness of the left spring (theta > 0) [N/m]
    std::vector<double> k_right;       ///< of the right spring (theta < 0) [N/m]
    std::vector<double> ground_acc;    ///< horizontal ground acceleration [m/s^2]
    std::vector<double> w_excitation;  ///< cumulative work of the excitation, Eq. 23 [J]
    std::vector<double> w_anchorage;   ///< cumulative work of the anchorage, Eq. 24 [J]
    /// Cumulative energy the adaptive law's K_min -> K_max switches at nonzero elongation put
    /// into the spring [J] (the paper's law; 0 for other anchorages; physics.md §4).
    std::vector<double> e_switch;
    double switch_energy_j = 0.0;  ///< its total over the run [J]
    CellResult result;
};

/// Integrates `cell` to `t_end_s` (or until it overturns) and samples every `output_dt_s`
/// by cubic Hermite interpolation of the accepted steps; the works are integrated to each
/// sample time (step_works), so they converge at the order of theta.
History sample_history(const CellModel& cell, IntegratorSettings settings, double output_dt_s,
                       double t_end_s);

}  // namespace rocksweep
