#include "rocksweep/motion/oscillator.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <stdexcept>
#include <unsupported/Eigen/MatrixFunctions>

namespace rocksweep::motion {

double Oscillator::omega() const { return 2.0 * M_PI / period_s; }

ExactStep::ExactStep(const Oscillator& o, double dt_s) {
    if (!(o.period_s > 0.0 && std::isfinite(o.period_s)) || !(o.damping >= 0.0 && o.damping < 1.0) ||
        !(dt_s > 0.0 && std::isfinite(dt_s)))
        throw std::invalid_argument("ExactStep: needs T > 0, 0 <= zeta < 1 and dt > 0");
    const double w = o.omega();
    c_ = 2.0 * o.damping * w;
    k_ = w * w;
    // z = (u, v, a, s): the base acceleration a and its slope s over the step ride along as
    // states (a' = s, s' = 0), so exp(M dt) carries the forced response exactly.
    Eigen::Matrix4d m = Eigen::Matrix4d::Zero();
    m(0, 1) = 1.0;
    m(1, 0) = -k_;
    m(1, 1) = -c_;
    m(1, 2) = -1.0;
    m(2, 3) = 1.0;
    const Eigen::Matrix4d e = (m * dt_s).exp();
    for (int i = 0; i < 2; ++i) {
        for (int j = 0; j < 2; ++j) phi_[i][j] = e(i, j);
        // a0 e(i,2) + s e(i,3) with s = (a1 - a0) / dt
        g0_[i] = e(i, 2) - e(i, 3) / dt_s;
        g1_[i] = e(i, 3) / dt_s;
    }
}

}  // namespace rocksweep::motion
