#pragma once
// A single-input single-output linear system x' = A x + B a, y = C x + D a, its series
// connection, and its exact discretisation for an input linear between samples.
#include <Eigen/Dense>
#include <span>
#include <vector>

namespace rocksweep::motion::detail {

struct StateSpace {
    Eigen::MatrixXd a;     // n x n
    Eigen::VectorXd b;     // n
    Eigen::RowVectorXd c;  // n
    double d = 1.0;
};

// `first` then `second`: second's input is first's output.
StateSpace series(const StateSpace& first, const StateSpace& second);

// x_{k+1} = Phi x_k + G0 a_k + G1 a_{k+1}: the exact map of `s` over dt for an input linear
// between samples (a first-order hold), from exp of the system augmented with the input and its
// slope as states (Franklin, Powell & Workman, Digital Control of Dynamic Systems, sec. 6.3).
struct FirstOrderHold {
    FirstOrderHold(const StateSpace& s, double dt_s);
    // y at every sample of `input`, from rest at t = 0.
    std::vector<double> response(std::span<const double> input) const;

    StateSpace system;
    Eigen::MatrixXd phi;
    Eigen::VectorXd g0, g1;
};

}  // namespace rocksweep::motion::detail
