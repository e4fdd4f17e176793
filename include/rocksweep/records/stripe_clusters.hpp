#pragma once
/// Standard errors of a stripe fit whose runs come in records. In an incremental dynamic analysis
/// every record is run at every level, and one record's runs are not independent trials: its
/// capacity decides them all (it reaches the state at every level above it, give or take a
/// resurrection). fit_stripes' observed information counts each run as a trial, so its standard
/// errors shrink with levels as well as records, by about the square root of the levels across
/// the fragility's rise (3-4 times for 30 levels over 0.05-1.5 g). The cure is the cluster-robust
/// (sandwich) variance, records as the clusters (Liang & Zeger 1986; Huber 1967; White 1980):
/// V = H^-1 (sum over records of g_r g_r^T) H^-1 * G / (G - 1), with H the likelihood's Hessian
/// and g_r record r's score at the fit, G the records. The estimate is fit_stripes' own.
/// Flat in the records: a first pass fits the stripes, a second adds each record's score.
/// docs/fragility.md, "Records as clusters".
#include <cstdint>
#include <span>
#include <vector>

#include "rocksweep/records/fragility.hpp"

namespace rocksweep {

class StripeClusters {
public:
    /// For `fit` (fit_stripes of the pooled runs; any status) at `intensities` (the levels,
    /// positive and finite, each record's outcomes given in this order).
    StripeClusters(const FragilityFit& fit, std::vector<double> intensities);

    /// One record's runs: per level, -1 no observation (not converged, or not run), 0 the state
    /// not reached, 1 reached. Throws std::invalid_argument for another length.
    void add(std::span<const std::int8_t> outcome);
    std::size_t records() const { return records_; }

    /// `fit` with se_ln_median, se_beta, cov_ln_median_beta and the 95 % intervals from the sandwich over the records
    /// added (`stripes`: the pooled runs it was fitted to, for the Hessian). Unchanged unless
    /// its status is ok and beta was fitted, and at least two records were added.
    FragilityFit corrected(std::span<const Stripe> stripes) const;

private:
    FragilityFit fit_;
    std::vector<double> ln_x_;
    std::vector<double> score_reached_, score_missed_;  // d ln L / dz of one run at each level
    double m00_ = 0.0, m01_ = 0.0, m11_ = 0.0;         // sum of g_r g_r^T, g in (a, b) of z = a + b ln x
    std::size_t records_ = 0;
    bool active_ = false;
};

}  // namespace rocksweep
