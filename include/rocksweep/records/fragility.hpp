#pragma once
/// Fragility curves: the probability that a block reaches a damage state (theta_max / alpha at
/// or above a threshold, or overturning) against an intensity measure x, as a lognormal
/// P(x) = Phi(ln(x / median) / beta), fitted by maximum likelihood from incremental dynamic
/// analysis (one capacity per record, some possibly right-censored) or from multiple stripes
/// (exceedance counts at a few intensities). Pure math: no I/O. Method and sources:
/// docs/fragility.md.
#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace rocksweep {

/// Standard normal CDF.
double normal_cdf(double z);

/// A lognormal fragility curve. median in the intensity's unit, beta dimensionless.
struct LognormalFragility {
    double median = 0.0;
    double beta = 0.0;
    /// P(state reached | x): Phi(ln(x / median) / beta); a step at the median when beta = 0.
    double probability(double x) const;
};

/// How a fit ended. Anything but `ok` leaves some estimates at their limits (see each fit).
enum class FitStatus {
    ok,
    none_reached,     ///< no record / no run reached the state: median above every intensity tried
    all_reached,      ///< stripes: every run reached it: median below every intensity tried
    zero_dispersion,  ///< capacities all equal, or stripes perfectly separated: beta -> 0
    not_identifiable, ///< one stripe with 0 < n < N and beta free: median and beta trade off
    decreasing,       ///< the stripes' best fit falls with intensity (beta < 0): not a fragility
};
std::string to_string(FitStatus s);

/// A fit with its uncertainty: standard errors from the inverse of the observed Fisher
/// information at the maximum (asymptotic: they assume many records / runs), and the 95 %
/// Wald intervals they imply, on ln(median) (so the median's interval is not symmetric) and
/// on ln(beta) (so it stays positive), and the covariance of ln(median) and beta, which a
/// function of both (an annual rate) needs. NaN where the status leaves them undefined.
struct FragilityFit {
    FitStatus status = FitStatus::ok;
    LognormalFragility curve;
    double se_ln_median = 0.0;  ///< standard error of ln(median)
    double se_beta = 0.0;       ///< standard error of beta (0 when beta was fixed)
    /// Covariance of ln(median) and beta (0 when beta was fixed, and in the closed form, where
    /// the normal MLE's mean and standard deviation are independent).
    double cov_ln_median_beta = 0.0;
    double median_lo = 0.0, median_hi = 0.0;  ///< 95 % interval of the median
    double beta_lo = 0.0, beta_hi = 0.0;      ///< 95 % interval of beta
    double log_likelihood = 0.0;
    int iterations = 0;                       ///< Newton iterations (0: closed form)
};

/// One record's capacity: the intensity at which it first reaches the state, or, if it never
/// does over the intensities tried, the highest one tried (censored: the capacity lies above).
struct Capacity {
    double intensity = 0.0;
    bool censored = false;
};

/// Lognormal fit of record capacities (IDA). Without censoring the MLE is closed form:
/// ln(median) = mean of ln c_i, beta = their standard deviation with divisor n (the MLE; the
/// n - 1 divisor is larger by sqrt(n / (n - 1))), se_ln_median = beta / sqrt(n),
/// se_beta = beta / sqrt(2 n). With censored capacities the likelihood of a censored record is
/// P(capacity > c_i) and the maximum is found by Newton's method (concave in 1/beta and
/// ln(median)/beta). Degenerate data: no uncensored capacity -> none_reached (median +inf, beta
/// NaN); all uncensored capacities equal, and no censored one above them -> zero_dispersion
/// (median = that value, beta 0, intervals NaN). Throws std::invalid_argument for an empty
/// list or an intensity that is not positive and finite.
FragilityFit fit_capacities(std::span<const Capacity> capacities);

/// n of N runs at intensity x reached the state.
struct Stripe {
    double intensity = 0.0;
    int exceed = 0;
    int total = 0;
    double fraction() const { return static_cast<double>(exceed) / total; }  ///< the empirical fraction
};

/// Wilson's 95 % score interval of a stripe's fraction: honest at 0 / N and N / N, where the
/// Wald interval collapses to a point.
void wilson_interval(const Stripe& s, double& lo, double& hi);

/// Lognormal fit of stripes by the binomial likelihood (Baker 2015): maximises
/// sum_j [n_j ln P(x_j) + (N_j - n_j) ln(1 - P(x_j))] by Newton's method with step halving on
/// (a, b), P = Phi(a + b ln x), where the likelihood is concave (probit regression); median =
/// exp(-a / b), beta = 1 / b. `fixed_beta` > 0 fixes beta and fits the median alone (what
/// one stripe needs). Degenerate data, decided before any iteration:
/// - every n_j = 0: none_reached, median +inf (beta NaN, or the fixed one);
/// - every n_j = N_j: all_reached, median 0;
/// - beta free and the stripes perfectly separated (every stripe below some x has n = 0, every
///   one above has n = N): zero_dispersion, beta 0, median the geometric mean of the highest
///   all-safe and the lowest all-reached intensity (any median between them is as likely);
/// - beta free and only one intensity with 0 < n < N: not_identifiable, median and beta NaN;
/// - beta free and the best fit decreasing: decreasing, median and beta NaN.
/// Throws std::invalid_argument for no stripes, an intensity not positive and finite, or
/// counts outside 0 <= n <= N, N >= 1.
FragilityFit fit_stripes(std::span<const Stripe> stripes, double fixed_beta = 0.0);

/// A damage state: theta_max / alpha >= rotation_ratio, or overturning.
struct DamageState {
    double rotation_ratio = 0.0;  ///< ignored for overturning
    bool overturning = false;
    std::string name() const;     ///< "rotation>=0.3" or "overturning"
};

/// The default states: theta_max / alpha >= 0.1, 0.3, 0.5, and overturning.
std::vector<DamageState> default_damage_states();

/// One point of an IDA curve: one record run at one intensity.
struct IdaPoint {
    double intensity = 0.0;
    double max_rotation = 0.0;  ///< theta_max / alpha
    bool overturned = false;
};

/// Where one record's IDA curve first reaches a state. A block that overturns at one scale can
/// survive a larger one (the pulse tips it back, or the impact sequence changes): the state
/// need not stay reached above `first_level`, and `safe_above` says so.
struct IdaCapacity {
    bool reached = false;
    double first_level = 0.0;  ///< lowest intensity at which it is reached (NaN if never)
    double below = 0.0;        ///< the intensity before it (NaN if first_level is the lowest)
    /// The capacity: for a rotation state the intensity where theta_max / alpha crosses the
    /// threshold, linear between `below` and `first_level`; for overturning `first_level`
    /// (overturning has no continuous measure to interpolate: the true level lies in
    /// (below, first_level]). If never reached: the highest intensity, censored.
    Capacity capacity;
    bool safe_above = false;   ///< some intensity above first_level does not reach the state
};

/// Reads a state off one record's IDA curve (intensities strictly increasing; throws
/// std::invalid_argument otherwise, or for an empty curve).
IdaCapacity ida_capacity(std::span<const IdaPoint> curve, const DamageState& state);

/// True if the run reached the state.
bool reaches(const IdaPoint& run, const DamageState& state);

/// Stripes from runs at a few intensities (each record scaled to each level): runs of equal
/// intensity form one stripe, in increasing intensity. Throws std::invalid_argument for an
/// intensity that is not positive and finite.
std::vector<Stripe> stripes_from_runs(std::span<const IdaPoint> runs, const DamageState& state);

}  // namespace rocksweep
