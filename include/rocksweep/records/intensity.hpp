#pragma once
/// Intensity measures of a recorded ground motion, computed once per record and stored beside
/// the results. The ground is the record's piecewise-linear acceleration from rest at t = 0;
/// no baseline correction is applied (a velocity left at the end is reported, not removed),
/// so the measures describe exactly the motion the integrator sees.
#include "rocksweep/records/record.hpp"

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

/// Each measure's name, unit and meaning, for writers that store them one dataset per field
/// (name as the dataset, units and long_name as its attributes).
struct IntensityField {
    const char* name;
    const char* units;
    const char* long_name;
    double IntensityMeasures::*value;
};

inline constexpr IntensityField intensity_fields[] = {
    {"pga_g", "1", "peak ground acceleration / standard gravity", &IntensityMeasures::pga_g},
    {"pga_time_s", "s", "time of the peak ground acceleration", &IntensityMeasures::pga_time_s},
    {"pgv_m_s", "m/s", "peak ground velocity (integrated record, no baseline correction)", &IntensityMeasures::pgv_m_s},
    {"pgv_time_s", "s", "time of the peak ground velocity", &IntensityMeasures::pgv_time_s},
    {"residual_velocity_m_s", "m/s", "ground velocity at the end of the record", &IntensityMeasures::residual_velocity_m_s},
    {"arias_m_s", "m/s", "Arias intensity", &IntensityMeasures::arias_m_s},
    {"significant_duration_s", "s", "D5-95: time between 5 % and 95 % of the Arias intensity",
     &IntensityMeasures::significant_duration_s},
    {"duration_s", "s", "record length", &IntensityMeasures::duration_s},
    {"pga_vertical_g", "1", "peak vertical ground acceleration / standard gravity (NaN: none)",
     &IntensityMeasures::pga_vertical_g},
};

/// Measures of `record` (at least two samples, as read_record guarantees).
IntensityMeasures intensity_measures(const Record& record);

/// PGA / (g tan alpha) for a block of slenderness `alpha_rad` under gravity `gravity` [m/s^2]:
/// the dimensionless amplitude of rocking studies (a constant push uplifts the block above 1).
double pga_over_g_tan_alpha(double pga_g, double alpha_rad, double gravity);

}  // namespace rocksweep
