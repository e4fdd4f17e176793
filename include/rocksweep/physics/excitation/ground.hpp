#pragma once
/// What a ground-motion family hands the W-lane kernel: its coefficients as plain doubles (one
/// lane's worth), and the ground it yields at a stage time.

namespace rocksweep {

/// Ground acceleration / g at one time: (horizontal, vertical).
struct Ground {
    double ax = 0.0, ay = 0.0;
};

/// One lane's ground coefficients, which the lane loop holds as structure of arrays. Each family
/// documents which fields it uses; the others keep their defaults. A tabulated family (a record)
/// reads its tables at a scale (ax_g) only in its scalar questions (ax, ay); in the lane loop
/// its lane hands the ground at the step's nodes instead (Recorded::moment_nodes).
struct GroundLane {
    double ax_g = 0.0, ay_g = 0.0;           ///< amplitudes / g (a record: its scale factors)
    double omega = 0.0;                       ///< [rad/s]
    double phase = 0.0, phase_y = 0.0;        ///< [rad]
    double t_ref = 0.0;                       ///< a family's reference time [s] (the Ricker's centre)
    const double* samples = nullptr;          ///< a record's horizontal samples / g
    const double* samples_y = nullptr;        ///< its vertical samples / g (the horizontal's if none: ay_g = 0)
    double sample_dt_s = 1.0;                 ///< a record's sampling interval [s] (1: a lane reading nothing)
    int last_segment = 0;                     ///< a record's last segment, samples - 2
};

}  // namespace rocksweep
