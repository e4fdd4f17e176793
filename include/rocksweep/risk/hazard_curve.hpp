#pragma once
/// A site's hazard curve: the mean annual rate H(x) at which an intensity measure exceeds x,
/// given at a few points and interpolated log-log (ln H linear in ln x) between them. Beyond
/// its first and last points it is extrapolated log-log with the slope of the end segment: the
/// rule is stated here and in docs/risk.md, and the risk integral reports the share of its result
/// that comes from there. Pure math: no I/O.
#include <cstddef>
#include <string>
#include <vector>

namespace rocksweep {

/// The measures hazard curves are published for, in rocksweep's units.
enum class HazardMeasure {
    pga,  ///< peak ground acceleration [g]
    pgv,  ///< peak ground velocity [m/s]
    sa,   ///< 5 %-damped spectral (pseudo-)acceleration at a period [g]
};

/// "PGA", "PGV" or "SA(0.5)" (OpenQuake's spelling; the period in seconds).
std::string hazard_measure_name(HazardMeasure m, double period_s);
/// "g" or "m/s": the unit intensities are stored in.
const char* hazard_measure_units(HazardMeasure m);

class HazardCurve {
public:
    /// Checks and keeps the points: at least two; intensities positive, finite and strictly
    /// increasing; rates positive, finite and non-increasing, the last below the first (a
    /// curve that never falls holds no probability). `period_s` > 0 for SA only. Throws
    /// std::invalid_argument naming the first offending point (1-based).
    HazardCurve(HazardMeasure measure, double period_s, std::vector<double> intensity, std::vector<double> rate);

    HazardMeasure measure() const { return measure_; }
    double period_s() const { return period_s_; }
    const std::vector<double>& intensity() const { return x_; }
    const std::vector<double>& rate() const { return h_; }
    std::size_t size() const { return x_.size(); }

    /// H(x) [1/yr] for any x > 0, log-log between points, extrapolated log-log beyond them.
    double rate_at(double x) const;
    /// The log-log slope k = -d ln H / d ln x at x (of the end segment beyond the points; at a
    /// point, of the segment above it). k >= 0.
    double slope_at(double x) const;
    /// The slopes of the segment below the first and above the last point (the extrapolations).
    double slope_below() const { return k_.front(); }
    double slope_above() const { return k_.back(); }
    /// The largest slope of any segment: bounds how fast H grows downwards.
    double max_slope() const;

private:
    std::size_t segment(double x) const;  ///< index i of [x_i, x_i+1] holding x, clamped to the end segments
    HazardMeasure measure_;
    double period_s_;
    std::vector<double> x_, h_, k_;  ///< k_[i]: slope of segment i
};

/// The mean annual rate of events from a probability of exceedance P in an investigation time
/// t [yr] under a Poisson model: -ln(1 - P) / t (+inf at P = 1).
double rate_from_probability(double probability, double years);
/// The probability of at least one event in t years at annual rate r: 1 - exp(-r t).
double probability_in(double rate, double years);

}  // namespace rocksweep
