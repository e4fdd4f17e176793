#pragma once
/// A damped linear oscillator under a base acceleration that is linear between samples, as the
/// engine reads a record: u'' + 2 zeta w u' + w^2 u = -a(t), u the displacement relative to the
/// base. Stepped from sample to sample by its exact map (docs/physics.md, "Floor motions").
/// Standard library and Eigen only.
namespace rocksweep::motion {

/// One linear single-degree-of-freedom oscillator.
struct Oscillator {
    double period_s = 1.0;  ///< natural period T = 2 pi / w [s], > 0
    double damping = 0.05;  ///< fraction of critical zeta, 0 <= zeta < 1
    double omega() const;   ///< w = 2 pi / T [rad/s]
};

/// The oscillator's state: displacement and velocity relative to its base.
struct OscillatorState {
    double u = 0.0, v = 0.0;
};

/// The exact map over one step dt with the base acceleration linear from a0 to a1:
/// x1 = Phi x0 + G0 a0 + G1 a1. Phi, G0 and G1 come from the matrix exponential of the system
/// augmented with the input and its slope (a first-order hold), computed once per oscillator
/// and dt: no truncation error at the samples, only rounding.
class ExactStep {
public:
    /// Throws std::invalid_argument for T <= 0, zeta outside [0, 1) or dt <= 0 (callers check
    /// user input first and name the option).
    ExactStep(const Oscillator& o, double dt_s);
    OscillatorState advance(const OscillatorState& x, double a0, double a1) const {
        return {phi_[0][0] * x.u + phi_[0][1] * x.v + g0_[0] * a0 + g1_[0] * a1,
                phi_[1][0] * x.u + phi_[1][1] * x.v + g0_[1] * a0 + g1_[1] * a1};
    }
    /// The relative acceleration u'' = -a - 2 zeta w v - w^2 u.
    double relative_acceleration(const OscillatorState& x, double a) const { return -a - c_ * x.v - k_ * x.u; }

private:
    double phi_[2][2]{}, g0_[2]{}, g1_[2]{};
    double c_ = 0.0, k_ = 0.0;  // 2 zeta w, w^2
};

}  // namespace rocksweep::motion
