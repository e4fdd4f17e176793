#pragma once
/// The risk of every anchorage scenario, block and damage state of a finished record suite at
/// one site: the suite's fragility (fit and empirical fractions, as the suite file holds them)
/// integrated over the site's hazard curve (docs/risk.md). Pure math: the io layer reads the
/// suite file into a SuiteFragilityTable and writes the SuiteRisk.
#include <cstdint>
#include <string>
#include <vector>

#include "rocksweep/risk/hazard_curve.hpp"

namespace rocksweep {

/// One scenario's fragility, in the suite file's C order.
struct ScenarioFragility {
    std::string name;
    std::int64_t index = 0;     ///< the suite's order of its scenarios
    std::string floor = "ground";  ///< the suite's /floors group the blocks stood on
    std::vector<double> fraction, fraction_lo, fraction_hi;  ///< [state, alpha, radius, level]
    std::vector<double> median, beta, median_lo, median_hi, beta_lo, beta_hi;  ///< [state, alpha, radius]
    /// The fit's standard errors and covariance of (ln median, beta), [state, alpha, radius];
    /// empty for a suite file written before the covariance.
    std::vector<double> se_ln_median, se_beta, cov_ln_median_beta;
    std::vector<std::uint8_t> fit_status;                     ///< FitStatus codes, [state, alpha, radius]
};

struct SuiteFragilityTable {
    std::string measure;  ///< the suite's intensity_measure: "pga_g", "pgv_m_s", ...
    double period_s = 0;  ///< of a spectral measure; 0 otherwise
    double damping = 0.05;  ///< of a spectral measure: hazard curves of SA(T) are 5 %-damped
    std::vector<std::string> states;
    std::vector<double> alphas, radii, levels;
    std::vector<ScenarioFragility> scenarios;
    /// Every scenario has the fit's covariance: the fit's rate ranges are the delta method's;
    /// otherwise the box of the marginal intervals (docs/risk.md, "From the fit").
    bool covariance() const;
    std::size_t blocks() const { return states.size() * alphas.size() * radii.size(); }
};

/// Throws InputError("hazard", ...) unless the hazard curve's measure is the suite's: PGA for
/// pga_g, PGV for pgv_m_s, SA(T) for a spectral suite measure "sa_g" of the same period (to
/// 1e-6 relative) and 5 % damping, the damping hazard curves of SA(T) are computed for. A suite
/// scaled by pga_ratio or scale has no hazard curve.
void check_same_measure(const HazardCurve& h, const std::string& hazard_path, const SuiteFragilityTable& t);

/// The damping of the SA(T) a hazard curve gives (ground-motion models and OpenQuake's SA).
inline constexpr double hazard_sa_damping = 0.05;

struct ScenarioRisk {
    std::string name;
    /// [state, alpha, radius]: lambda [1/yr] from the lognormal fit, its 95 % range (the delta
    /// method on ln lambda with the fit's covariance; for a file without it, the lowest and
    /// highest lambda over the corners of the box of the median's and beta's 95 % intervals),
    /// the parts from below / above the hazard curve's points; NaN where the fit status is
    /// neither ok nor zero_dispersion (the range NaN too where the fit has no errors).
    std::vector<double> rate_fit, rate_fit_lo, rate_fit_hi, below_fit, above_fit;
    /// The same from the empirical fractions (P linear in ln x between levels, 0 below the
    /// first, the last held above), the interval from Wilson's bounds of every fraction.
    std::vector<double> rate_empirical, rate_empirical_lo, rate_empirical_hi, below_empirical, above_empirical;
    /// [state, alpha, radius, deaggregation point]: d lambda / d ln x.
    std::vector<double> density_fit, density_empirical;
};

struct SuiteRisk {
    std::vector<double> deaggregation_intensity;  ///< where the densities are given
    std::vector<ScenarioRisk> scenarios;
};

/// The deaggregation grid: `points` log-spaced from a quarter of the lowest hazard point or
/// suite level to four times the highest.
std::vector<double> deaggregation_grid(const HazardCurve& h, const std::vector<double>& levels, std::size_t points = 121);

SuiteRisk suite_risk(const HazardCurve& h, const SuiteFragilityTable& t);

}  // namespace rocksweep
