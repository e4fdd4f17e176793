#pragma once
/// One accepted step of the kernel and the motion inside it: the cubic Hermite interpolant of
/// (theta, theta_dot) and of (theta_dot, theta''), fourth-order accurate like the step itself.

namespace rocksweep {

/// The state at both ends of one step (theta'' = acc), on one side: theta does not change sign
/// inside a step, since impacts end steps.
struct StepEnds {
    double t0, theta0, theta_dot0, acc0;  ///< start of step [s, rad, rad/s, rad/s^2]
    double t1, theta1, theta_dot1, acc1;  ///< end of step

    /// theta and theta_dot at t in [t0, t1] (the end state for a zero-length step).
    void at(double t, double& theta, double& theta_dot) const {
        const double dt = t1 - t0;
        const double u = dt > 0.0 ? (t - t0) / dt : 1.0;
        const double h00 = (1 + 2 * u) * (1 - u) * (1 - u), h10 = u * (1 - u) * (1 - u);
        const double h01 = u * u * (3 - 2 * u), h11 = u * u * (u - 1);
        theta = h00 * theta0 + h10 * dt * theta_dot0 + h01 * theta1 + h11 * dt * theta_dot1;
        theta_dot = h00 * theta_dot0 + h10 * dt * acc0 + h01 * theta_dot1 + h11 * dt * acc1;
    }
};

}  // namespace rocksweep
