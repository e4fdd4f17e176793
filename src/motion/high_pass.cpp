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
    // With the input held at 0, one sample takes z = (u, u', u'') to A z; the energy of the free
    // output after z is z' R z, R = sum over k >= 1 of (A^k)' e e' A^k, e picking u''. Summed by
    // doubling, R_2m = R_m + (A^m)' R_m A^m: 2^64 samples, far past the ring-down (rho(A) < 1).
    Eigen::Matrix3d a;
    for (int j = 0; j < 3; ++j) {
        const Eigen::Vector3d z = Eigen::Vector3d::Unit(j);
        const double pu = phi_[0][0] * z[0] + phi_[0][1] * z[1] + g0_[0] * z[2];
        const double pv = phi_[1][0] * z[0] + phi_[1][1] * z[1] + g0_[1] * z[2];
        const double y = (-c_[0] * pu - c_[1] * pv) / denominator_;
        a.col(j) = Eigen::Vector3d{pu + g1_[0] * y, pv + g1_[1] * y, y};
    }
    Eigen::Matrix3d ring = a.row(2).transpose() * a.row(2), power = a;
    for (int i = 0; i < 64; ++i) {
        ring += power.transpose() * ring * power;
        power = power * power;
    }
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) ring_[i][j] = ring(i, j), free_[i][j] = a(i, j);
}

HighPass::State HighPass::run(std::span<double> x) const {
    State s;  // at rest, x(0) = 0
    for (std::size_t k = 1; k < x.size(); ++k) {
        // The state the old y carries to the sample, then the new y that makes x there.
        const double pu = phi_[0][0] * s.u + phi_[0][1] * s.v + g0_[0] * s.y, pv = phi_[1][0] * s.u + phi_[1][1] * s.v + g0_[1] * s.y;
        const double y_new = (x[k] - c_[0] * pu - c_[1] * pv) / denominator_;
        s.u = pu + g1_[0] * y_new;
        s.v = pv + g1_[1] * y_new;
        s.y = y_new;
        x[k] = s.y;
    }
    return s;
}

void HighPass::apply(std::span<double> x) const { run(x); }

double HighPass::apply_and_ring_down(std::span<double> x, std::size_t samples) const {
    const State s = run(x);
    const Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> ring(&ring_[0][0]), a(&free_[0][0]);
    const Eigen::Vector3d z{s.u, s.v, s.y};
    // The energy from z on, less that from where `samples` steps take it, A^samples z (by squaring).
    Eigen::Vector3d later = z;
    Eigen::Matrix3d power = a;
    for (std::size_t r = samples; r > 0 && later.squaredNorm() > 0.0; r >>= 1) {
        if (r & 1) later = power * later;
        power = power * power;
    }
    return z.dot(ring * z) - later.dot(ring * later);
}

}  // namespace rocksweep::motion
