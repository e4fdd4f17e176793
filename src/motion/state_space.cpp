#include "state_space.hpp"

#include <unsupported/Eigen/MatrixFunctions>

namespace rocksweep::motion::detail {

StateSpace series(const StateSpace& first, const StateSpace& second) {
    const Eigen::Index n1 = first.a.rows(), n2 = second.a.rows();
    StateSpace s;
    s.a = Eigen::MatrixXd::Zero(n1 + n2, n1 + n2);
    s.a.topLeftCorner(n1, n1) = first.a;
    s.a.bottomLeftCorner(n2, n1) = second.b * first.c;
    s.a.bottomRightCorner(n2, n2) = second.a;
    s.b.resize(n1 + n2);
    s.b << first.b, second.b * first.d;
    s.c.resize(n1 + n2);
    s.c << second.d * first.c, second.c;
    s.d = second.d * first.d;
    return s;
}

FirstOrderHold::FirstOrderHold(const StateSpace& s, double dt_s) : system(s) {
    const Eigen::Index n = s.a.rows();
    // z = (x, a, slope): a' = slope, slope' = 0 over the step.
    Eigen::MatrixXd m = Eigen::MatrixXd::Zero(n + 2, n + 2);
    m.topLeftCorner(n, n) = s.a;
    m.block(0, n, n, 1) = s.b;
    m(n, n + 1) = 1.0;
    const Eigen::MatrixXd e = (m * dt_s).exp();
    phi = e.topLeftCorner(n, n);
    // a0 e(:, n) + (a1 - a0) / dt e(:, n+1)
    g1 = e.block(0, n + 1, n, 1) / dt_s;
    g0 = e.block(0, n, n, 1) - g1;
}

std::vector<double> FirstOrderHold::response(std::span<const double> input) const {
    std::vector<double> y(input.size());
    Eigen::VectorXd x = Eigen::VectorXd::Zero(phi.rows()), next(phi.rows());
    for (std::size_t i = 0; i < input.size(); ++i) {
        if (i > 0) {
            next.noalias() = phi * x;
            next += g0 * input[i - 1] + g1 * input[i];
            x.swap(next);
        }
        y[i] = system.c.dot(x) + system.d * input[i];
    }
    return y;
}

}  // namespace rocksweep::motion::detail
