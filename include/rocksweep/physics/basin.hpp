#pragma once
/// Basins of attraction of free rocking (paper Section 3.4, Fig. 7; physics.md "Basins"): from a
/// state (theta, theta_dot) with the ground at rest, does the block come back to rest or
/// overturn, with or without an impact? Decided by energy alone, swing by swing.
#include <vector>

#include "rocksweep/physics/model.hpp"
#include "rocksweep/physics/outcome.hpp"

namespace rocksweep {

/// The two boundaries of Fig. 7 at one rotation theta, as angular velocities [rad/s]: the
/// paper's Eq. 19-20 derived again from the energy (physics.md "Basins").
struct BasinBoundary {
    /// theta > 0: the states above overturn without an impact (through the potential's
    /// barrier, or back over it when already past); theta < 0: the states below (mirror image).
    double no_impact = 0.0;
    /// theta > 0: the states below (moving inward fast enough) overturn on the other side after
    /// one impact; theta < 0: the states above.
    double impact = 0.0;
};

/// A potential of gravity and one spring on [0, pi/2] with its extrema located, so that a swing's
/// turning point is a bisection on a piece where the potential is monotone. Per unit I0.
class SwingPotential {
public:
    /// kappa = 8 b^2 K / I0 of the spring [1/s^2], 0 for gravity alone.
    SwingPotential(const CellModel& m, double kappa);
    double operator()(double phi) const;
    /// Largest value on [a, b], a <= b.
    double max_on(double a, double b) const;
    /// The first phi after `from` towards `to` (either direction, `from` itself excluded)
    /// where the potential reaches `energy`; NaN if it stays below it.
    double first_reach(double from, double to, double energy) const;
    /// True if the potential grows with phi at phi (the force points to theta = 0).
    bool restoring_at(double phi) const;
    /// The end of the first piece where it rises from 0: its first maximum, or pi/2.
    double first_peak() const { return knots_[1]; }

private:
    const CellModel* m_;
    double kappa_;
    std::vector<double> knots_;  ///< 0, the extrema in order, pi/2: the potential is monotone between
};

/// The energy argument for one cell's block and anchorage (CellModel; its pulse is ignored).
class BasinEnergy {
public:
    explicit BasinEnergy(const CellModel& m);

    /// The fate of the state (theta [rad], theta_dot [rad/s]) in free rocking, followed over
    /// every swing: the potential of gravity and of the intact spring; a spring that reaches its
    /// fracture angle breaks and its stored energy is lost; theta_dot <- e theta_dot at each
    /// impact; the adaptive law as the integrator applies it after the excitation (K_max from
    /// an impact outward, K_min from an outward turning point on; the passive law's start with
    /// K_min away from theta = 0 included). The state's springs and K
    /// are those the integrator starts a lane with (CellModel::theta0). Needs |theta| < pi/2.
    /// Returns safe, overturned_impact or overturned_no_impact; not_converged for a block at
    /// rest exactly on the potential's peak (theta = alpha of a free block), which never moves.
    Outcome outcome(double theta, double theta_dot) const;

    BasinBoundary boundary(double theta) const;

private:
    const CellModel& m_;
    SwingPotential gravity_, stiff_, soft_;  ///< no spring, K (K_max), K_min
    double barrier_from_rest_;  ///< energy that overturns from theta = 0 outward, springs intact
    double bounded_below_;      ///< below this energy at theta = 0 every later swing turns back intact
};

}  // namespace rocksweep
