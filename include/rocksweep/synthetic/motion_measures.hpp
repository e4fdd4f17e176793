#pragma once
/// The measures the model is fitted on, for any sampled acceleration (a record's or a synthetic
/// motion's), taken as piecewise linear between samples: the cumulative Arias intensity's
/// landmarks (from the sum of squared samples), the zero-level up-crossings and the positive minima and negative maxima.
#include <cstddef>
#include <vector>

namespace rocksweep::synthetic {

struct AriasTimes {
    double arias_m_s = 0.0;  ///< pi/(2 g) * sum of a_k^2 dt
    double t05_s = 0.0, t45_s = 0.0, t95_s = 0.0;  ///< when 5, 45 and 95 % of it have arrived
    double d595_s() const { return t95_s - t05_s; }
};

/// Of `a_g` (units of standard gravity, sampled every `dt_s`, at least two samples, not all 0).
AriasTimes arias_times(const std::vector<double>& a_g, double dt_s);

/// Times of the zero-level up-crossings (a sample <= 0 followed by one > 0), linearly interpolated.
std::vector<double> upcrossing_times(const std::vector<double>& a_g, double dt_s);

/// Count of the samples in [t0_s, t1_s] that are a positive local minimum or a negative local
/// maximum (strictly below / above both neighbours): the measure of the filter's bandwidth.
std::size_t count_positive_minima_negative_maxima(const std::vector<double>& a_g, double dt_s, double t0_s, double t1_s);

/// Up-crossings per second in [t0_s, t1_s].
double upcrossing_rate_hz(const std::vector<double>& a_g, double dt_s, double t0_s, double t1_s);

}  // namespace rocksweep::synthetic
