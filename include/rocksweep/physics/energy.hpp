#pragma once
/// Energy of free rocking (physics.md §5): the potentials, one swing, and the fate of a block
/// after the excitation has ended. Energies are per unit I0: [rad^2/s^2].
#include <cstdint>

#include "rocksweep/physics/model.hpp"
#include "rocksweep/physics/step.hpp"

namespace rocksweep {

/// Gravity potential at |theta| = phi, zero at rest.
double gravity_potential(const CellModel& m, double phi);
/// Potential of the Eq. 8 moment kappa sin(phi/2): 2 kappa (1 - cos(phi/2)).
double spring_potential(const CellModel& m, double kappa, double phi);

/// One outward swing from theta = 0 with kinetic energy `ke` on a side whose spring has
/// stiffness kappa_out going out and kappa_in coming back (0 when broken or free).
struct Swing {
    bool bounded = false;     ///< turns back before breaking its spring or passing the barrier
    double peak = 0.0;        ///< |theta| at the turning point
    double ke_return = 0.0;   ///< kinetic energy back at theta = 0
};
Swing outward_swing(const CellModel& m, double ke, double kappa_out, double kappa_in,
                    double break_angle);

/// Running extremes of a run, which the energy decision completes.
struct FreeFate {
    bool decided = false;      ///< false: some swing breaks a spring or overturns; integrate on
    double max_phi = 0.0;
    double peak_force = 0.0;
    std::int32_t impacts = 0;        ///< further impacts above the threshold
    std::int32_t impacts_total = 0;  ///< further impacts, the settling one included
};

/// Fate of a block just after an impact, after the excitation has ended: moving outward on
/// side `side` (+1: theta > 0) with speed `v`. `left_intact`/`right_intact` are the springs.
/// Decided iff every later swing stays bounded; then the block is safe and the result holds
/// the extremes and impact counts of the whole remaining motion.
FreeFate free_fate(const CellModel& m, int side, double v, bool left_intact, bool right_intact);

/// Works done on the block (Eq. 23-24) [J]: by the excitation, -m ax R cos(alpha - |theta|)
/// theta_dot, and by the working spring of stiffness k [N/m], -8 b^2 k sin(|theta|/2) sgn(theta)
/// theta_dot, integrated over [t0, t] of one step by 3-point Gauss-Legendre on the step's cubic
/// Hermite interpolant: O(dt^5) per step, so the cumulative works converge at fourth order like
/// theta. Precondition: step.t0 <= t <= step.t1; the ground acts at nodes before the pulse's end.
struct Works {
    double excitation_j = 0.0;
    double anchorage_j = 0.0;
};
Works step_works(const CellModel& m, double k_n_m, const StepEnds& step, double t);
/// The same over [ta, tb] of the step (step.t0 <= ta <= tb <= step.t1): a history that samples
/// a long step adds these pieces up instead of integrating from t0 at each sample.
Works step_works(const CellModel& m, double k_n_m, const StepEnds& step, double ta, double tb);

}  // namespace rocksweep
