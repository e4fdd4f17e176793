#pragma once
/// One time history sampled at a fixed output interval.
#include <vector>

#include "rocksweep/physics/integrator.hpp"

namespace rocksweep {

/// Accuracy defaults of a single history (`simulate`), chosen from measurement (physics_kernel.md,
/// Numerics): a history should overlay a reference, and one run is cheap. Against 4096 steps per
/// period with threshold 1e-9 p alpha, the largest |theta| error over the samples was, at 384 steps
/// and 1e-4: 2e-11 rad on the paper's sample case (free, constant, adaptive), 1.7e-9, 1.5e-9 and
/// 5.1e-9 rad on El Centro (free, constant, adaptive), 3.7e-10 and 1.5e-9 rad on Sylmar (free,
/// adaptive), outcomes equal. 320 steps gave 1.2e-8 rad (El Centro, adaptive); a threshold of 1e-3
/// leaves up to 3.7e-8 rad from settling early. Sweeps keep IntegratorSettings' 48 and
/// make_cell_model's 1e-3. Used only where the user gave neither --steps-per-period nor
/// --impact-threshold.
struct HistoryDefaults {
    double steps_per_period;  ///< IntegratorSettings::steps_per_period
    double impact_threshold;  ///< settling threshold / (p alpha), make_cell_model's argument
    double tolerance;  ///< IntegratorSettings::tolerance (records)
};
inline constexpr HistoryDefaults kHistoryDefaults{384.0, 1e-4, 1e-9};

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
