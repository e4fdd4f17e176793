#pragma once
/// Intensity measures of a recorded ground motion, computed once per record and stored beside
/// the results. The ground is the record's piecewise-linear acceleration from rest at t = 0;
/// no baseline correction is applied (a velocity left at the end is reported, not removed),
/// so the measures describe exactly the motion the integrator sees.
#include "rocksweep/record.hpp"

namespace rocksweep {

/// Measures of the horizontal component (and the vertical's peak). Accelerations in units of
/// standard gravity, velocities in m/s, times in s.
struct IntensityMeasures {
    double pga_g = 0.0;       ///< max |a|
    double pga_time_s = 0.0;  ///< when it occurs
    double pgv_m_s = 0.0;     ///< max |v|, v(t) = integral of a from rest (exact for linear segments)
    double pgv_time_s = 0.0;
    double residual_velocity_m_s = 0.0;   ///< v at the record's end: drift an uncorrected baseline leaves
    double arias_m_s = 0.0;               ///< Arias intensity, pi/(2 g) * integral of a^2 dt
    double significant_duration_s = 0.0;  ///< D5-95: time between 5 % and 95 % of the Arias intensity
    double duration_s = 0.0;              ///< the record's length, (N - 1) dt
    double pga_vertical_g = 0.0;          ///< max |a_v|; NaN when the record has no vertical component
};

/// Measures of `record` (at least two samples, as read_record guarantees).
IntensityMeasures intensity_measures(const Record& record);

/// PGA / (g tan alpha) for a block of slenderness `alpha_rad` under gravity `gravity` [m/s^2]:
/// the dimensionless amplitude of rocking studies (a constant push uplifts the block above 1).
double pga_over_g_tan_alpha(double pga_g, double alpha_rad, double gravity);

}  // namespace rocksweep
