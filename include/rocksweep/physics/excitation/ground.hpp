#pragma once
/// What a ground-motion family hands the W-lane kernel: its coefficients as plain doubles (one
/// lane's worth), and the ground it yields at a stage time.
#include <cstddef>
#include <vector>

namespace rocksweep {

/// Ground acceleration / g at one time: (horizontal, vertical).
struct Ground {
    double ax = 0.0, ay = 0.0;
};

/// One lane's ground coefficients. Analytic families read the numbers, which the lane loop holds
/// as structure of arrays; a tabulated family (a record) reads `samples`, outside the vector
/// loop. Each family documents which fields it uses; the others stay 0.
struct GroundLane {
    double ax_g = 0.0, ay_g = 0.0;           ///< amplitudes / g
    double omega = 0.0;                       ///< [rad/s]
    double phase = 0.0, phase_y = 0.0;        ///< [rad]
    double t_ref = 0.0;                       ///< a family's reference time [s] (the Ricker's centre)
    const std::vector<double>* samples = nullptr;  ///< a record's samples / g
    double sample_dt_s = 0.0;
};

}  // namespace rocksweep
