#include "rocksweep/motion/high_pass.hpp"

#include <cmath>
#include <stdexcept>

#include "state_space.hpp"

namespace rocksweep::motion {

HighPass::HighPass(double corner_hz, double dt_s) {
    if (!(corner_hz > 0.0 && std::isfinite(corner_hz)) || !(dt_s > 0.0 && std::isfinite(dt_s)))
        throw std::invalid_argument("HighPass: needs f_c > 0 and dt > 0");
    const double w = 2.0 * M_PI * corner_hz;
    // s = (u, u'), s' = (u', y): the double integrator of the output y = u''; x = y + w^2 u + 2 w u'.
    detail::StateSpace s{Eigen::Matrix2d{{0.0, 1.0}, {0.0, 0.0}}, Eigen::Vector2d{0.0, 1.0}, Eigen::RowVector2d{w * w, 2.0 * w},
                         1.0};
    const detail::FirstOrderHold map(s, dt_s);
    for (int i = 0; i < 2; ++i) {
        for (int j = 0; j < 2; ++j) phi_[i][j] = map.phi(i, j);
        g0_[i] = map.g0(i);
        g1_[i] = map.g1(i);
        c_[i] = s.c(i);
    }
    denominator_ = 1.0 + c_[0] * g1_[0] + c_[1] * g1_[1];
}

void HighPass::apply(std::span<double> x) const {
    double u = 0.0, v = 0.0, y = 0.0;  // at rest, x(0) = 0
    for (std::size_t k = 1; k < x.size(); ++k) {
        // The state the old y carries to the sample, then the new y that makes x there.
        const double pu = phi_[0][0] * u + phi_[0][1] * v + g0_[0] * y, pv = phi_[1][0] * u + phi_[1][1] * v + g0_[1] * y;
        const double y_new = (x[k] - c_[0] * pu - c_[1] * pv) / denominator_;
        u = pu + g1_[0] * y_new;
        v = pv + g1_[1] * y_new;
        y = y_new;
        x[k] = y;
    }
}

}  // namespace rocksweep::motion
