#pragma once
/// Everything the kernel needs about one cell, reduced to the numbers it uses.
#include "rocksweep/physics/anchorage.hpp"
#include "rocksweep/physics/block.hpp"
#include "rocksweep/physics/excitation.hpp"

namespace rocksweep {

enum class Equations { nonlinear, linearised };
std::string to_string(Equations e);

/// Per-cell constants in kernel units: rotations in rad, time in s, accelerations / g.
/// The anchorage moment / I0 is kappa sin(|theta|/2) (Eq. 8), kappa = 8 b^2 K / I0 [1/s^2].
struct CellModel {
    double p2 = 0.0;          ///< p^2 [1/s^2]
    double alpha = 0.0;       ///< [rad]
    double cos_alpha = 1.0;   ///< cos(alpha), for the potentials
    double e = 1.0;           ///< impact velocity ratio
    Equations equations = Equations::nonlinear;
    AnchorageKind anchorage = AnchorageKind::free;
    AdaptiveLaw adaptive_law = AdaptiveLaw::paper;
    double kappa_max = 0.0;   ///< constant: kappa of K; adaptive: of K_max
    double kappa_min = 0.0;   ///< adaptive: of K_min; otherwise = kappa_max
    double break_max = 0.0;   ///< fracture angle while K = K_max [rad]
    double break_min = 0.0;   ///< fracture angle while K = K_min [rad]
    double force_max = 0.0;   ///< F / F_u = force_max tan(|theta|/2) while K = K_max
    double force_min = 0.0;   ///< same while K = K_min
    double k_max_n_m = 0.0;   ///< K_max [N/m], for histories
    double k_min_n_m = 0.0;   ///< K_min [N/m]
    double v_threshold = 0.0; ///< approach speed below which an impact is settling [rad/s]
    double mass_kg = 0.0, radius_m = 0.0, gravity = 9.81;  ///< for the work of Eq. 23
    double half_width_m = 0.0;                            ///< b, for the work of Eq. 24
    double inertia = 0.0;                                  ///< I0 [kg m^2]
    /// State at t = 0 [rad, rad/s]; (0, 0) is rest, where every run of a spectrum starts. A
    /// spring whose fracture angle lies below |theta0| on theta0's side breaks at once.
    double theta0 = 0.0, theta_dot0 = 0.0;
    Pulse pulse;

    double p() const;
    /// Uplift from rest (Eq. 1): |ax| > (1 + ay) tan(alpha).
    bool uplifts(double t) const { return uplifts(t, uplift_slope()); }
    /// The same with tan(alpha) (alpha, linearised: uplift_slope()) computed once by the caller,
    /// who scans many times.
    bool uplifts(double t, double slope) const;
    double uplift_slope() const;
    /// True if no time of the pulse can satisfy Eq. 1: |ax| <= (1 - |ay|) threshold throughout.
    bool never_uplifts() const;
    /// Fastest time scale of the cell's ground and rocking [rad/s] (the kernel takes the larger
    /// of this and its anchorage law's).
    double omega_max() const;
};

/// Eq. 1 under the ground (ax, ay) [g], with CellModel::uplift_slope.
inline bool lifts(double ax, double ay, double slope) { return std::abs(ax) > (1.0 + ay) * slope; }

/// Right-hand side theta'' [rad/s^2] for a cell on side s (+1: theta > 0) with Eq. 8's spring of
/// coefficient kappa, ground accelerations ax, ay [g]: the kernel's equation (system.hpp) under
/// its spring law (spring_law.hpp).
double rocking_acceleration(const CellModel& m, int side, double kappa, double ax, double ay,
                            double theta);

/// Base reactions at the pivot per unit m g while rocking (physics.md §6): horizontal (friction)
/// and vertical.
struct BaseReactions {
    double fx = 0.0, fy = 0.0;
};
/// The pivot's reaction on side s (+1: theta > 0, pivot at x = +b) at rotation theta [rad] and
/// angular velocity theta_dot [rad/s], ground accelerations ax, ay [g], with the working spring
/// of stiffness k [N/m] and kernel coefficient kappa = 8 b^2 k / I0 (both 0 when none): from the
/// motion of the centre of mass, the spring's pull F = 4 b k tan(|theta|/2) acting along the
/// line at |theta|/2 to the vertical (the moment arm 2 b cos(|theta|/2) of Eq. 8).
BaseReactions base_reactions(const CellModel& m, int side, double kappa, double k_n_m, double ax, double ay,
                             double theta, double theta_dot);

/// `impact_threshold` is the settling threshold as a fraction of p alpha (physics.md §5).
CellModel make_cell_model(const Block& block, const Anchorage& anchorage, const Pulse& pulse,
                          Equations equations = Equations::nonlinear,
                          double impact_threshold = 1e-3);

}  // namespace rocksweep
