#pragma once
/// A critically damped oscillator as a high-pass filter: a motion x replaced by the relative
/// acceleration u'' of the oscillator u'' + 2 w u' + w^2 u = x, w = 2 pi f_c, so that the new
/// motion's velocity u' and displacement u come to rest once x has (Rezaeian & Der Kiureghian
/// 2010; docs/synthetic.md, "High-pass"). Standard library and Eigen only.
#include <cstddef>
#include <cstdint>
#include <span>

namespace rocksweep::motion {

/// Unlike the floors (floor_filter.hpp), which hold their input linear between samples, this
/// holds its output linear between samples, as the engine reads the motion: u' and u are then
/// exactly that motion's own velocity and displacement, and its residuals the oscillator's,
/// which decay. It is the motion layer's exact first-order-hold map (state_space.hpp) of the
/// system run backwards, the double integrator (u, u') of the output u'' read out as
/// x = u'' + 2 w u' + w^2 u, solved at each sample for the new u'': the linear-acceleration
/// method (its closed form gives the same samples to 8e-16 of the PGA). Held on the input
/// instead (the floors' map at zeta = 1), the samples move by up to 2.2e-4 of the PGA at
/// dt = 0.02 s and the motion read linear drifts from u', u by 1e-7 of their peaks (measured on
/// 200 motions of the generator's test): either would do; this one keeps the residuals exact.
class HighPass {
public:
    /// Throws std::invalid_argument for f_c <= 0 or dt <= 0.
    HighPass(double corner_hz, double dt_s);
    /// `x` (samples dt apart from t = 0, where it is 0 and the oscillator at rest) replaced by u''.
    void apply(std::span<double> x) const;
    /// apply(x), and the sum of the squares of the `samples` u'' that would follow x's end with
    /// the input held at 0 from there on (the oscillator ringing down; all of them to rest by
    /// default), in closed form: quadratic forms of the free motion's energy in the state x leaves.
    double apply_and_ring_down(std::span<double> x, std::size_t samples = SIZE_MAX) const;

private:
    struct State {
        double u = 0.0, v = 0.0, y = 0.0;  // u, u' and the output u'' at the last sample
    };
    State run(std::span<double> x) const;

    double phi_[2][2]{}, g0_[2]{}, g1_[2]{};  // the double integrator's map: s1 = Phi s0 + G0 y0 + G1 y1
    double c_[2]{};                            // x = y + c . s, s = (u, u')
    double denominator_ = 1.0;                 // 1 + c . G1: y1 from x1
    double free_[3][3]{};                      // the free motion's step: (u, u', u'') -> the next
    double ring_[3][3]{};                      // (u, u', u'') -> energy of the free u'' after it
};

}  // namespace rocksweep::motion
