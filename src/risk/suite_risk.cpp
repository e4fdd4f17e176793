#include "rocksweep/risk/suite_risk.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

#include "rocksweep/core/errors.hpp"
#include "rocksweep/records/fragility.hpp"
#include "rocksweep/risk/risk_integral.hpp"

namespace rocksweep {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr double z95 = 1.959963984540054;  // Phi^-1(0.975)

/// The fit's lambda over the corners of the box of the 95 % intervals of the median and beta:
/// the range of a suite file that holds no covariance.
void box_interval(const HazardCurve& h, const ScenarioFragility& s, std::size_t b, double& lo, double& hi) {
    lo = hi = nan;
    const double medians[] = {s.median_lo[b], s.median_hi[b]}, betas[] = {s.beta_lo[b], s.beta_hi[b]};
    for (const double m : medians)
        for (const double beta : betas) {
            if (!std::isfinite(m) || !std::isfinite(beta)) return;
            const double r = annual_rate(h, LognormalFragility{m, beta}).rate;
            lo = std::isnan(lo) ? r : std::min(lo, r);
            hi = std::isnan(hi) ? r : std::max(hi, r);
        }
}

/// The delta method on ln lambda: var = g^T Sigma g, g its gradient in (ln median, beta) by
/// central differences, Sigma the fit's covariance; the range lambda exp(+-1.96 sd).
void delta_interval(const HazardCurve& h, const ScenarioFragility& s, std::size_t b, double rate, double& lo, double& hi) {
    lo = hi = nan;
    const double m = s.median[b], beta = s.beta[b];
    const double vm = s.se_ln_median[b] * s.se_ln_median[b], vb = s.se_beta[b] * s.se_beta[b], c = s.cov_ln_median_beta[b];
    if (!(beta > 0.0) || !(rate > 0.0) || !std::isfinite(vm) || !std::isfinite(vb) || !std::isfinite(c)) return;
    // Steps far below any standard error and far above the quadrature's 1e-14 relative error.
    const double du = 1e-3, db = 1e-3 * beta;
    const auto ln_rate = [&](double median, double dispersion) {
        return std::log(annual_rate(h, LognormalFragility{median, dispersion}).rate);
    };
    const double g0 = (ln_rate(m * std::exp(du), beta) - ln_rate(m * std::exp(-du), beta)) / (2.0 * du);
    const double g1 = (ln_rate(m, beta + db) - ln_rate(m, beta - db)) / (2.0 * db);
    const double sd = std::sqrt(std::max(0.0, g0 * g0 * vm + 2.0 * g0 * g1 * c + g1 * g1 * vb));
    lo = rate * std::exp(-z95 * sd);
    hi = rate * std::exp(z95 * sd);
}

}  // namespace

bool SuiteFragilityTable::covariance() const {
    return std::all_of(scenarios.begin(), scenarios.end(),
                       [&](const ScenarioFragility& s) { return s.cov_ln_median_beta.size() == blocks(); });
}

void check_same_measure(const HazardCurve& h, const std::string& hazard_path, const SuiteFragilityTable& t) {
    const std::string name = hazard_measure_name(h.measure(), h.period_s());
    bool same = false;
    if (h.measure() == HazardMeasure::pga) same = t.measure == "pga_g";
    if (h.measure() == HazardMeasure::pgv) same = t.measure == "pgv_m_s";
    if (h.measure() == HazardMeasure::sa)
        same = t.measure == "sa_g" && std::abs(t.period_s - h.period_s()) <= 1e-6 * h.period_s();
    if (same && h.measure() == HazardMeasure::sa && std::abs(t.damping - hazard_sa_damping) > 1e-9)
        throw InputError("hazard", hazard_path + " (" + name + ")",
                         "a hazard curve of the suite's Sa: SA(T) curves are 5 %-damped, the suite's Sa is zeta = " +
                             format_short(t.damping) + " (run the suite with --sa-damping 0.05)");
    if (!same) {
        const std::string suite = t.measure + (t.period_s > 0 ? " at T = " + format_short(t.period_s) + " s" : "");
        throw InputError("hazard", hazard_path + " (" + name + ")",
                         "a hazard curve of the suite's intensity measure, " + suite +
                             " (PGA for pga_g, PGV for pgv_m_s; a suite scaled by pga_ratio or scale has none)");
    }
}

std::vector<double> deaggregation_grid(const HazardCurve& h, const std::vector<double>& levels, std::size_t points) {
    double lo = h.intensity().front(), hi = h.intensity().back();
    if (!levels.empty()) lo = std::min(lo, levels.front()), hi = std::max(hi, levels.back());
    lo /= 4, hi *= 4;
    std::vector<double> x(points);
    for (std::size_t i = 0; i < points; ++i)
        x[i] = std::exp(std::log(lo) + (std::log(hi) - std::log(lo)) * static_cast<double>(i) / static_cast<double>(points - 1));
    return x;
}

SuiteRisk suite_risk(const HazardCurve& h, const SuiteFragilityTable& t) {
    SuiteRisk out;
    out.deaggregation_intensity = deaggregation_grid(h, t.levels);
    const std::size_t blocks = t.blocks(), levels = t.levels.size(), points = out.deaggregation_intensity.size();
    const bool delta = t.covariance();  // else the box (docs/risk.md, "From the fit")
    for (const ScenarioFragility& s : t.scenarios) {
        ScenarioRisk r;
        r.name = s.name;
        for (std::size_t b = 0; b < blocks; ++b) {
            const auto status = static_cast<FitStatus>(s.fit_status[b]);
            const bool fitted = status == FitStatus::ok || status == FitStatus::zero_dispersion;
            const LognormalFragility curve{fitted ? s.median[b] : nan, fitted ? s.beta[b] : nan};
            const RiskRate fit = annual_rate(h, curve);
            double lo = nan, hi = nan;
            if (fitted && delta) delta_interval(h, s, b, fit.rate, lo, hi);
            else if (fitted) box_interval(h, s, b, lo, hi);
            r.rate_fit.push_back(fit.rate), r.below_fit.push_back(fit.below), r.above_fit.push_back(fit.above);
            r.rate_fit_lo.push_back(lo), r.rate_fit_hi.push_back(hi);

            const std::span<const double> lv(t.levels);
            const auto row = [&](const std::vector<double>& v) { return std::span<const double>(v).subspan(b * levels, levels); };
            const RiskRate emp = annual_rate(h, lv, row(s.fraction));
            r.rate_empirical.push_back(emp.rate), r.below_empirical.push_back(emp.below), r.above_empirical.push_back(emp.above);
            r.rate_empirical_lo.push_back(annual_rate(h, lv, row(s.fraction_lo)).rate);
            r.rate_empirical_hi.push_back(annual_rate(h, lv, row(s.fraction_hi)).rate);
            for (std::size_t k = 0; k < points; ++k) {
                const double x = out.deaggregation_intensity[k];
                r.density_fit.push_back(fitted ? rate_density(h, curve, x) : nan);
                r.density_empirical.push_back(rate_density(h, lv, row(s.fraction), x));
            }
        }
        out.scenarios.push_back(std::move(r));
    }
    return out;
}

}  // namespace rocksweep
