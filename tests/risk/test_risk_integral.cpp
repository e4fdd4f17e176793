// The risk integral against closed forms: a power-law hazard under a lognormal fragility
// (lambda = k0 theta^-k exp(k^2 beta^2 / 2), and its parts beyond the curve's points), a step,
// and empirical fractions linear in ln x.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "rocksweep/risk/hazard_curve.hpp"
#include "rocksweep/risk/risk_integral.hpp"
#include "rocksweep/risk/suite_risk.hpp"
#include "rocksweep/core/errors.hpp"
#include <cstdint>
#include <span>

namespace rocksweep {
namespace {

/// H(x) = k0 x^-k at n log-spaced points from lo to hi.
HazardCurve power_law(double k0, double k, double lo, double hi, int n = 9) {
    std::vector<double> x, h;
    for (int i = 0; i < n; ++i) {
        x.push_back(lo * std::pow(hi / lo, static_cast<double>(i) / (n - 1)));
        h.push_back(k0 * std::pow(x.back(), -k));
    }
    return HazardCurve(HazardMeasure::pga, 0, x, h);
}

/// integral of Phi((u - m) / beta) k k0 e^{-k u} du from a to +inf (closed form by parts).
double above_exact(double k0, double k, double m, double beta, double a) {
    const double za = (a - m) / beta;
    return k0 * std::exp(-k * a) * normal_cdf(za) +
           k0 * std::exp(-k * m + k * k * beta * beta / 2) * (1 - normal_cdf(za + k * beta));
}

struct Case {
    double k0, k, median, beta, lo, hi;
};

TEST(RiskIntegral, PowerLawHazardLognormalFragilityClosedForm) {
    const Case cases[] = {
        {1e-4, 2.5, 0.4, 0.5, 0.02, 3.0},   // median inside the curve
        {3e-4, 1.8, 0.15, 0.3, 0.05, 2.0},  // steep fragility
        {2e-5, 3.2, 1.2, 0.6, 0.01, 0.8},   // median above the last point: most of lambda extrapolated
        {1e-3, 1.2, 0.02, 0.8, 0.05, 1.5},  // median below the first point
    };
    for (const Case& c : cases) {
        const HazardCurve h = power_law(c.k0, c.k, c.lo, c.hi);
        const double m = std::log(c.median);
        const double exact = c.k0 * std::pow(c.median, -c.k) * std::exp(c.k * c.k * c.beta * c.beta / 2);
        const RiskRate r = annual_rate(h, LognormalFragility{c.median, c.beta});
        EXPECT_NEAR(r.rate / exact, 1.0, 1e-6) << "median " << c.median << " beta " << c.beta;
        const double above = above_exact(c.k0, c.k, m, c.beta, std::log(c.hi));
        const double below = exact - above_exact(c.k0, c.k, m, c.beta, std::log(c.lo));
        EXPECT_NEAR(r.above, above, 1e-6 * exact);
        EXPECT_NEAR(r.below, below, 1e-6 * exact);
    }
}

TEST(RiskIntegral, CurvedHazardAgainstFineQuadrature) {
    // A hazard bending in log-log (slopes 1, 2, 3.5): the quadrature against a plain midpoint
    // sum over 2 million pieces of ln x, each within its segment's exact power law.
    const HazardCurve h(HazardMeasure::pga, 0, {0.05, 0.2, 0.5, 1.5}, {2e-2, 2e-2 * 0.25, 2e-2 * 0.25 * 0.16, 2e-2 * 0.25 * 0.16 / std::pow(3.0, 3.5)});
    const LognormalFragility f{0.35, 0.45};
    // Pieces end at the curve's points, where the density jumps with the slope.
    const double ends[] = {std::log(1e-4), std::log(0.05), std::log(0.2), std::log(0.5), std::log(1.5), std::log(1e3)};
    const int n = 400000;
    double sum = 0;
    for (int s = 0; s + 1 < 6; ++s) {
        const double a = ends[s], b = ends[s + 1];
        for (int i = 0; i < n; ++i) sum += rate_density(h, f, std::exp(a + (i + 0.5) * (b - a) / n)) * (b - a) / n;
    }
    EXPECT_NEAR(annual_rate(h, f).rate / sum, 1.0, 1e-6);
}

TEST(RiskIntegral, StepFragilityIsTheRateAtItsMedian) {
    const HazardCurve h = power_law(1e-4, 2.0, 0.05, 2.0);
    const RiskRate r = annual_rate(h, LognormalFragility{0.3, 0.0});
    EXPECT_NEAR(r.rate, 1e-4 / 0.09, 1e-12);
    EXPECT_NEAR(r.above, 1e-4 / 4.0, 1e-15);  // H at the last point
    EXPECT_EQ(r.below, 0.0);
    EXPECT_EQ(annual_rate(h, LognormalFragility{INFINITY, NAN}).rate, 0.0);
    EXPECT_TRUE(std::isnan(annual_rate(h, LognormalFragility{NAN, NAN}).rate));
}

TEST(RiskIntegral, EmpiricalFractionsLinearInLnX) {
    // P rises linearly in u = ln x from 0 at a to 1 at b and stays 1: lambda = k0 (e^-ka - e^-kb) / (k (b - a)).
    const double k0 = 1e-4, k = 2.2;
    const HazardCurve h = power_law(k0, k, 0.02, 3.0);
    std::vector<double> levels, fractions;
    const double a = std::log(0.1), b = std::log(1.0);
    for (int i = 0; i <= 12; ++i) {
        levels.push_back(std::exp(a + (b - a) * i / 12));
        fractions.push_back(i / 12.0);
    }
    const double exact = k0 * (std::exp(-k * a) - std::exp(-k * b)) / (k * (b - a));
    EXPECT_NEAR(annual_rate(h, levels, fractions).rate / exact, 1.0, 1e-9);
    // A level with no converged run (NaN) is skipped: the line through its neighbours is the same.
    fractions[5] = NAN;
    EXPECT_NEAR(annual_rate(h, levels, fractions).rate / exact, 1.0, 1e-9);
    // A constant fraction p from the first level on: p H(first level).
    const std::vector<double> flat(levels.size(), 0.25);
    EXPECT_NEAR(annual_rate(h, levels, flat).rate, 0.25 * k0 * std::pow(0.1, -k), 1e-12 * k0 * std::pow(0.1, -k));
    const std::vector<double> none(levels.size(), NAN);
    EXPECT_TRUE(std::isnan(annual_rate(h, levels, none).rate));
    const std::vector<double> short_list{0.1};
    EXPECT_THROW(annual_rate(h, levels, short_list), std::invalid_argument);
}

TEST(RiskIntegral, EmpiricalBeyondTheHazardCurveIsReported) {
    // Levels up to 2 g on a curve ending at 1 g: P = 1 held above the last level; what lies
    // above 1 g is the whole H(1 g) times P there.
    const HazardCurve h = power_law(1e-4, 2.0, 0.05, 1.0);
    const std::vector<double> levels{0.5, 1.0, 2.0}, fractions{1.0, 1.0, 1.0};
    const RiskRate r = annual_rate(h, levels, fractions);
    EXPECT_NEAR(r.rate, 1e-4 / 0.25, 1e-12);
    EXPECT_NEAR(r.above, 1e-4, 1e-12);
    EXPECT_EQ(r.below, 0.0);
}

TEST(RiskIntegral, ExposureTimeProbabilityAndRates) {
    EXPECT_NEAR(probability_in(1.0 / 475, 50), 1 - std::exp(-50.0 / 475), 1e-15);
    EXPECT_NEAR(rate_from_probability(0.10, 50), 0.0021072103131565, 1e-15);  // the 475-year return period
    EXPECT_NEAR(1 / rate_from_probability(0.10, 50), 474.56, 0.01);
    EXPECT_NEAR(probability_in(1e-12, 50), 5e-11, 1e-20);  // no cancellation at small rates
    EXPECT_TRUE(std::isinf(rate_from_probability(1.0, 50)));
}

TEST(HazardCurve, RefusesCurvesThatAreNotRatesOfExceedance) {
    const auto make = [](std::vector<double> x, std::vector<double> h) { return HazardCurve(HazardMeasure::pga, 0, x, h); };
    EXPECT_THROW(make({0.1, 0.05, 0.3}, {1e-2, 5e-3, 1e-3}), std::invalid_argument);  // intensities out of order
    EXPECT_THROW(make({0.1, 0.2, 0.3}, {1e-2, 2e-2, 1e-3}), std::invalid_argument);   // rate rising
    EXPECT_THROW(make({0.1, 0.2, 0.3}, {1e-2, -1e-3, 1e-3}), std::invalid_argument);  // negative
    EXPECT_THROW(make({0.1}, {1e-2}), std::invalid_argument);                          // one point
    EXPECT_THROW(make({0.1, 0.2}, {1e-2, 1e-2}), std::invalid_argument);               // never falls
    EXPECT_THROW(HazardCurve(HazardMeasure::sa, 0, {0.1, 0.2}, {1e-2, 1e-3}), std::invalid_argument);  // SA without period
    const HazardCurve h = make({0.1, 0.2, 0.4}, {1e-2, 2.5e-3, 1e-3});
    EXPECT_NEAR(h.slope_at(0.15), 2.0, 1e-12);
    EXPECT_NEAR(h.rate_at(0.05), 4e-2, 1e-15);                       // extrapolated with the first slope
    EXPECT_NEAR(h.rate_at(0.8), 1e-3 * std::pow(2.0, -std::log2(2.5)), 1e-15);  // and the last
    EXPECT_NEAR(h.rate_at(std::sqrt(0.02)), std::sqrt(1e-2 * 2.5e-3), 1e-15);  // log-log between points
}

TEST(SuiteRisk, RefusesAHazardOfAnotherMeasure) {
    const HazardCurve pga = power_law(1e-4, 2.0, 0.05, 1.0);
    SuiteFragilityTable t;
    t.measure = "pgv_m_s";
    try {
        check_same_measure(pga, "site.csv", t);
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("pgv_m_s"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("PGA"), std::string::npos) << e.what();
    }
    t.measure = "pga_g";
    EXPECT_NO_THROW(check_same_measure(pga, "site.csv", t));
    t.measure = "scale";
    EXPECT_THROW(check_same_measure(pga, "site.csv", t), InputError);
    // A spectral measure matches at its own period only.
    const HazardCurve sa(HazardMeasure::sa, 0.5, {0.1, 0.2}, {1e-2, 1e-3});
    t.measure = "sa_g";
    t.period_s = 0.5;
    EXPECT_NO_THROW(check_same_measure(sa, "site.csv", t));
    t.period_s = 1.0;
    EXPECT_THROW(check_same_measure(sa, "site.csv", t), InputError);
    EXPECT_THROW(check_same_measure(pga, "site.csv", t), InputError);
}

TEST(SuiteRisk, RatesIntervalsAndStatusesOfOneScenario) {
    // One block, two states: an ok fit with intervals, and a fit that did not converge to a curve.
    const HazardCurve h = power_law(1e-4, 2.5, 0.02, 3.0);
    SuiteFragilityTable t;
    t.measure = "pga_g";
    t.states = {"rotation>=0.5", "overturning"};
    t.alphas = {0.2};
    t.radii = {1.0};
    t.levels = {0.1, 0.2, 0.4, 0.8};
    ScenarioFragility s;
    s.name = "free";
    s.fraction = {0.0, 0.25, 0.5, 1.0, 0.0, 0.0, 0.25, 0.5};
    s.fraction_lo = {0.0, 0.1, 0.3, 0.8, 0.0, 0.0, 0.1, 0.3};
    s.fraction_hi = {0.2, 0.5, 0.7, 1.0, 0.2, 0.2, 0.5, 0.7};
    s.median = {0.4, NAN};
    s.beta = {0.5, NAN};
    s.median_lo = {0.3, NAN};
    s.median_hi = {0.5, NAN};
    s.beta_lo = {0.35, NAN};
    s.beta_hi = {0.7, NAN};
    s.fit_status = {static_cast<std::uint8_t>(FitStatus::ok), static_cast<std::uint8_t>(FitStatus::not_identifiable)};
    t.scenarios = {s};
    const SuiteRisk r = suite_risk(h, t);
    ASSERT_EQ(r.scenarios.size(), 1u);
    const ScenarioRisk& k = r.scenarios[0];
    const double exact = 1e-4 * std::pow(0.4, -2.5) * std::exp(2.5 * 2.5 * 0.25 / 2);
    EXPECT_NEAR(k.rate_fit[0] / exact, 1.0, 1e-6);
    // The box's corners: the lowest rate at the high median and the low beta, the highest at the other corner.
    const double lo = 1e-4 * std::pow(0.5, -2.5) * std::exp(2.5 * 2.5 * 0.35 * 0.35 / 2);
    const double hi = 1e-4 * std::pow(0.3, -2.5) * std::exp(2.5 * 2.5 * 0.7 * 0.7 / 2);
    EXPECT_NEAR(k.rate_fit_lo[0] / lo, 1.0, 1e-6);
    EXPECT_NEAR(k.rate_fit_hi[0] / hi, 1.0, 1e-6);
    EXPECT_TRUE(std::isnan(k.rate_fit[1]) && std::isnan(k.rate_fit_lo[1]) && std::isnan(k.density_fit[r.deaggregation_intensity.size()]));
    for (std::size_t b = 0; b < 2; ++b) {
        EXPECT_LT(k.rate_empirical_lo[b], k.rate_empirical[b]);
        EXPECT_GT(k.rate_empirical_hi[b], k.rate_empirical[b]);
        EXPECT_NEAR(k.rate_empirical[b], annual_rate(h, t.levels, std::span<const double>(s.fraction).subspan(4 * b, 4)).rate, 0.0);
    }
    // The deaggregation integrates to the rate (trapezoid in ln x on its grid: to 1 %).
    const std::vector<double>& x = r.deaggregation_intensity;
    double area = 0;
    for (std::size_t i = 0; i + 1 < x.size(); ++i) area += 0.5 * (k.density_fit[i] + k.density_fit[i + 1]) * std::log(x[i + 1] / x[i]);
    EXPECT_NEAR(area / k.rate_fit[0], 1.0, 0.01);
}

// With the fit's covariance the range is the delta method's on ln lambda. On a power-law hazard
// H = k0 x^-k the rate is k0 median^-k exp(k^2 beta^2 / 2) exactly, so ln lambda has gradient
// (-k, k^2 beta) in (ln median, beta) and var = k^2 v_m - 2 k^3 beta c + k^4 beta^2 v_b; the
// central differences must give it to 1e-6. A positive covariance narrows the range here (the
// two terms pull ln lambda opposite ways); a fit without errors has no range.
TEST(SuiteRisk, FitRangeIsTheDeltaMethodWithTheCovariance) {
    const double k = 2.5, median = 0.4, beta = 0.5, sm = 0.3, sb = 0.15;
    const HazardCurve h = power_law(1e-4, k, 0.02, 3.0);
    SuiteFragilityTable t;
    t.measure = "pga_g";
    t.states = {"overturning"};
    t.alphas = {0.2};
    t.radii = {1.0, 2.0};
    t.levels = {0.1, 0.8};
    ScenarioFragility s;
    s.name = "free";
    s.fraction = {0.0, 0.5, 0.0, 0.5};
    s.fraction_lo = s.fraction_hi = s.fraction;
    s.median = {median, median};
    s.beta = {beta, beta};
    s.median_lo = s.median_hi = s.beta_lo = s.beta_hi = {NAN, NAN};  // unused with the covariance
    s.se_ln_median = {sm, NAN};
    s.se_beta = {sb, NAN};
    s.fit_status = {0, 0};
    const double rate = 1e-4 * std::pow(median, -k) * std::exp(k * k * beta * beta / 2);
    for (const double c : {0.0, 0.6 * sm * sb, -0.6 * sm * sb}) {
        s.cov_ln_median_beta = {c, NAN};
        t.scenarios = {s};
        ASSERT_TRUE(t.covariance());
        const ScenarioRisk r = suite_risk(h, t).scenarios[0];
        const double sd = std::sqrt(k * k * sm * sm - 2 * k * k * k * beta * c + k * k * k * k * beta * beta * sb * sb);
        EXPECT_NEAR(r.rate_fit[0] / rate, 1.0, 1e-9);
        EXPECT_NEAR(std::log(r.rate_fit_hi[0] / rate) / (1.959963984540054 * sd), 1.0, 1e-6) << c;
        EXPECT_NEAR(std::log(rate / r.rate_fit_lo[0]) / (1.959963984540054 * sd), 1.0, 1e-6) << c;
        EXPECT_TRUE(std::isnan(r.rate_fit_lo[1]) && std::isnan(r.rate_fit_hi[1]));
        EXPECT_NEAR(r.rate_fit[1] / rate, 1.0, 1e-9);
    }
    // A scenario without the covariance (an older file) sends every scenario back to the box.
    s.cov_ln_median_beta.clear();
    t.scenarios = {s};
    EXPECT_FALSE(t.covariance());
}

}  // namespace
}  // namespace rocksweep
