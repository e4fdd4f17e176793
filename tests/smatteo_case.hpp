#pragma once
// The block most physics tests run: the S. Matteo statue of the paper (b = 0.30 m, h = 1.36 m,
// m = 3361 kg), its anchorage strength F_u = 0.4 m g, and a one-sine pulse given as the paper's
// ratios omega_p / p and a_p0 / (alpha g).
#include "rocksweep/physics/block.hpp"
#include "rocksweep/physics/excitation.hpp"

namespace rocksweep::testing {

inline const Block kSMatteo = rectangular_block(0.30, 1.36, 3361.0);
inline const double kSMatteoStrength = 0.4 * 3361.0 * 9.81;

inline Pulse smatteo_sine(double omega_ratio, double amplitude_ratio) {
    Pulse p;
    p.omega = omega_ratio * kSMatteo.p();
    p.ax_g = amplitude_ratio * kSMatteo.alpha_rad;
    return p;
}

}  // namespace rocksweep::testing
