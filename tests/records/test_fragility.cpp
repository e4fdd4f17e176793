// Fragility fits (include/rocksweep/records/fragility.hpp): recovery of a known median and beta from
// seeded synthetic data, with tolerances of a few standard errors of the sample size used; the
// coverage of the 95 % intervals; the degenerate data each fit must answer without iterating;
// and reading capacities off IDA curves.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

#include "rocksweep/records/fragility.hpp"

using namespace rocksweep;

namespace {

constexpr double kMedian = 0.8, kBeta = 0.45;  // the synthetic truth (intensity in g, say)

std::vector<Capacity> lognormal_capacities(std::mt19937_64& rng, int n, double censor_at = INFINITY) {
    std::normal_distribution<double> z(0.0, 1.0);
    std::vector<Capacity> c;
    for (int i = 0; i < n; ++i) {
        const double x = kMedian * std::exp(kBeta * z(rng));
        c.push_back(x > censor_at ? Capacity{censor_at, true} : Capacity{x, false});
    }
    return c;
}

/// `per_stripe` runs at each of `k` intensities spanning the median +- 2 beta.
std::vector<Stripe> binomial_stripes(std::mt19937_64& rng, int k, int per_stripe) {
    std::vector<Stripe> s;
    for (int j = 0; j < k; ++j) {
        const double x = kMedian * std::exp(kBeta * (-2.0 + 4.0 * j / (k - 1)));
        std::binomial_distribution<int> draw(per_stripe, LognormalFragility{kMedian, kBeta}.probability(x));
        s.push_back({x, draw(rng), per_stripe});
    }
    return s;
}

double stripe_log_likelihood(const std::vector<Stripe>& stripes, LognormalFragility f) {
    double l = 0.0;
    for (const Stripe& s : stripes) {
        const double p = f.probability(s.intensity);
        l += s.exceed * std::log(p) + (s.total - s.exceed) * std::log1p(-p);
    }
    return l;
}

bool covers(const FragilityFit& f) {
    return f.median_lo <= kMedian && kMedian <= f.median_hi && f.beta_lo <= kBeta && kBeta <= f.beta_hi;
}

}  // namespace

TEST(Fragility, ProbabilityIsTheLognormalCdf) {
    const LognormalFragility f{kMedian, kBeta};
    EXPECT_DOUBLE_EQ(f.probability(kMedian), 0.5);
    EXPECT_NEAR(f.probability(kMedian * std::exp(kBeta)), 0.841344746068543, 1e-15);
    EXPECT_EQ((LognormalFragility{kMedian, 0.0}.probability(0.79)), 0.0);
    EXPECT_EQ((LognormalFragility{kMedian, 0.0}.probability(0.8)), 1.0);
}

// n = 4000: the standard errors are beta / sqrt(n) = 0.0071 on ln(median) and beta / sqrt(2n)
// = 0.0050 on beta; 4 of them is a failure chance of 6e-5 per parameter.
TEST(FragilityCapacities, RecoverMedianAndBetaOfSyntheticLognormalData) {
    std::mt19937_64 rng(20261123);
    const int n = 4000;
    const FragilityFit f = fit_capacities(lognormal_capacities(rng, n));
    ASSERT_EQ(f.status, FitStatus::ok);
    EXPECT_EQ(f.iterations, 0);  // closed form
    EXPECT_NEAR(std::log(f.curve.median), std::log(kMedian), 4 * kBeta / std::sqrt(n));
    EXPECT_NEAR(f.curve.beta, kBeta, 4 * kBeta / std::sqrt(2.0 * n));
    EXPECT_DOUBLE_EQ(f.se_ln_median, f.curve.beta / std::sqrt(n));
    EXPECT_DOUBLE_EQ(f.se_beta, f.curve.beta / std::sqrt(2.0 * n));
    EXPECT_LT(f.median_lo, f.curve.median);
    EXPECT_GT(f.median_hi, f.curve.median);
}

// 1000 samples of n = 40: the Wald interval of ln(median) with the MLE beta covers with
// P(|t_39| <= 1.96 sqrt(39/40)) = 0.940, that of beta about the same; the joint coverage of the
// two (nearly independent) is ~0.89. The binomial standard deviation of 1000 trials is 0.01:
// [0.85, 0.93] is 4 of them either side.
TEST(FragilityCapacities, IntervalsCoverTheTruthAsOftenAsTheyClaim) {
    std::mt19937_64 rng(7);
    int hits = 0;
    for (int r = 0; r < 1000; ++r) hits += covers(fit_capacities(lognormal_capacities(rng, 40))) ? 1 : 0;
    EXPECT_GE(hits, 850);
    EXPECT_LE(hits, 930);
}

// A record censored far below all capacities ("not reached by 1e-6 g") adds
// ln P(capacity > 1e-6) = ln Phi(~30) = 0 to the likelihood: the Newton fit must land on the
// closed form (to its convergence, 1e-9 relative).
TEST(FragilityCapacities, NewtonFitMatchesTheClosedFormWhenCensoringIsVacuous) {
    std::mt19937_64 rng(11);
    std::vector<Capacity> c = lognormal_capacities(rng, 200);
    const FragilityFit closed = fit_capacities(c);
    c.push_back({1e-6, true});
    const FragilityFit newton = fit_capacities(c);
    ASSERT_EQ(newton.status, FitStatus::ok);
    EXPECT_GT(newton.iterations, 0);
    EXPECT_NEAR(newton.curve.median, closed.curve.median, 1e-9 * closed.curve.median);
    EXPECT_NEAR(newton.curve.beta, closed.curve.beta, 1e-9 * closed.curve.beta);
    EXPECT_NEAR(newton.se_ln_median, closed.se_ln_median, 1e-6 * closed.se_ln_median);
    EXPECT_NEAR(newton.se_beta, closed.se_beta, 1e-6 * closed.se_beta);
}

// IDA that stops at 1.2 x the median: a third of the records never reach the state. Dropping
// them would bias the median low; the censored likelihood recovers it within 4 of its own
// standard errors (n = 3000).
TEST(FragilityCapacities, CensoredCapacitiesRecoverTheTruth) {
    std::mt19937_64 rng(3);
    const std::vector<Capacity> c = lognormal_capacities(rng, 3000, 1.2 * kMedian);
    int censored = 0;
    for (const Capacity& x : c) censored += x.censored ? 1 : 0;
    ASSERT_GT(censored, 800);
    const FragilityFit f = fit_capacities(c);
    ASSERT_EQ(f.status, FitStatus::ok);
    EXPECT_NEAR(std::log(f.curve.median), std::log(kMedian), 4 * f.se_ln_median);
    EXPECT_NEAR(f.curve.beta, kBeta, 4 * f.se_beta);
    EXPECT_GT(f.se_beta, kBeta / std::sqrt(2.0 * 3000));  // censoring costs information
}

TEST(FragilityCapacities, DegenerateData) {
    const std::vector<Capacity> none = {{1.0, true}, {1.0, true}};
    const FragilityFit a = fit_capacities(none);
    EXPECT_EQ(a.status, FitStatus::none_reached);
    EXPECT_EQ(a.curve.median, INFINITY);
    EXPECT_TRUE(std::isnan(a.curve.beta));

    const std::vector<Capacity> same = {{0.7, false}, {0.7, false}, {0.7, true}};
    const FragilityFit b = fit_capacities(same);
    EXPECT_EQ(b.status, FitStatus::zero_dispersion);
    EXPECT_DOUBLE_EQ(b.curve.median, 0.7);
    EXPECT_EQ(b.curve.beta, 0.0);
    EXPECT_TRUE(std::isnan(b.se_ln_median));

    // One capacity, and a record that survived beyond it: a finite fit exists.
    const std::vector<Capacity> one = {{0.5, false}, {1.0, true}};
    const FragilityFit c = fit_capacities(one);
    EXPECT_EQ(c.status, FitStatus::ok);
    EXPECT_TRUE(std::isfinite(c.curve.median) && c.curve.beta > 0.0);

    EXPECT_THROW(fit_capacities(std::vector<Capacity>{}), std::invalid_argument);
    EXPECT_THROW(fit_capacities(std::vector<Capacity>{{-1.0, false}}), std::invalid_argument);
    EXPECT_THROW(fit_capacities(std::vector<Capacity>{{NAN, false}}), std::invalid_argument);
}

// 10 stripes of 500 runs over the median +- 2 beta: within 4 of the fit's own standard errors,
// which must themselves be of the size 5000 runs give (ln median ~ 0.01, beta ~ 0.01).
TEST(FragilityStripes, RecoverMedianAndBetaOfSyntheticBinomialData) {
    std::mt19937_64 rng(20261124);
    const std::vector<Stripe> s = binomial_stripes(rng, 10, 500);
    const FragilityFit f = fit_stripes(s);
    ASSERT_EQ(f.status, FitStatus::ok);
    EXPECT_NEAR(std::log(f.curve.median), std::log(kMedian), 4 * f.se_ln_median);
    EXPECT_NEAR(f.curve.beta, kBeta, 4 * f.se_beta);
    EXPECT_LT(f.se_ln_median, 0.02);
    EXPECT_LT(f.se_beta, 0.02);
    EXPECT_NEAR(f.log_likelihood, stripe_log_likelihood(s, f.curve), 1e-9 * std::abs(f.log_likelihood));
}

// The maximum is the maximum: no point of a fine grid around it is more likely.
TEST(FragilityStripes, NoGridPointBeatsTheFit) {
    std::mt19937_64 rng(5);
    const std::vector<Stripe> s = binomial_stripes(rng, 6, 20);
    const FragilityFit f = fit_stripes(s);
    ASSERT_EQ(f.status, FitStatus::ok);
    const double best = stripe_log_likelihood(s, f.curve);
    for (int i = -50; i <= 50; ++i)
        for (int j = -50; j <= 50; ++j) {
            const LognormalFragility g{f.curve.median * std::exp(0.01 * i), f.curve.beta * std::exp(0.01 * j)};
            EXPECT_LE(stripe_log_likelihood(s, g), best + 1e-12) << i << " " << j;
        }
}

// 500 experiments of 8 stripes x 30 runs: the observed-information intervals are asymptotic;
// at 240 runs their joint coverage measured ~0.90 (each parameter ~0.94-0.95). Binomial sd of
// 500 trials 0.013: [0.84, 0.96].
TEST(FragilityStripes, IntervalsCoverTheTruthAsOftenAsTheyClaim) {
    std::mt19937_64 rng(9);
    int hits = 0, fitted = 0;
    for (int r = 0; r < 500; ++r) {
        const FragilityFit f = fit_stripes(binomial_stripes(rng, 8, 30));
        if (f.status != FitStatus::ok) continue;
        ++fitted;
        hits += covers(f) ? 1 : 0;
    }
    EXPECT_EQ(fitted, 500);
    EXPECT_GE(hits, 420);
    EXPECT_LE(hits, 480);
}

TEST(FragilityStripes, DegenerateData) {
    const std::vector<Stripe> zeros = {{0.2, 0, 10}, {0.4, 0, 10}};
    EXPECT_EQ(fit_stripes(zeros).status, FitStatus::none_reached);
    EXPECT_EQ(fit_stripes(zeros).curve.median, INFINITY);
    EXPECT_EQ(fit_stripes(zeros, 0.4).curve.beta, 0.4);

    const std::vector<Stripe> ones = {{0.2, 10, 10}, {0.4, 10, 10}};
    EXPECT_EQ(fit_stripes(ones).status, FitStatus::all_reached);
    EXPECT_EQ(fit_stripes(ones).curve.median, 0.0);

    // Perfectly separated: any median in (0.4, 0.9) fits as well with beta -> 0.
    const std::vector<Stripe> split = {{0.2, 0, 10}, {0.4, 0, 10}, {0.9, 10, 10}};
    const FragilityFit a = fit_stripes(split);
    EXPECT_EQ(a.status, FitStatus::zero_dispersion);
    EXPECT_DOUBLE_EQ(a.curve.median, std::sqrt(0.4 * 0.9));
    EXPECT_EQ(a.curve.beta, 0.0);
    EXPECT_TRUE(std::isnan(a.se_beta));

    // Quasi-separated: mixed only at 0.4, saturated elsewhere: beta -> 0 with the median at 0.4.
    const std::vector<Stripe> quasi = {{0.2, 0, 10}, {0.4, 3, 10}, {0.9, 10, 10}};
    EXPECT_EQ(fit_stripes(quasi).status, FitStatus::zero_dispersion);
    EXPECT_DOUBLE_EQ(fit_stripes(quasi).curve.median, 0.4);

    // One stripe: median and beta trade off along a ridge unless beta is given, and then
    // Phi(ln(x / median) / beta) = n / N in closed form; Phi^-1(0.3) = -0.5244005127080407.
    const std::vector<Stripe> single = {{0.5, 3, 10}};
    EXPECT_EQ(fit_stripes(single).status, FitStatus::not_identifiable);
    EXPECT_TRUE(std::isnan(fit_stripes(single).curve.median));
    const FragilityFit b = fit_stripes(single, 0.4);
    ASSERT_EQ(b.status, FitStatus::ok);
    EXPECT_NEAR(b.curve.median, 0.5 * std::exp(0.4 * 0.5244005127080407), 1e-9);
    EXPECT_EQ(b.curve.beta, 0.4);
    EXPECT_EQ(b.se_beta, 0.0);
    // Binomial information of one stripe: var(ln median) = beta^2 p (1 - p) / (N phi(z)^2).
    const double z = -0.5244005127080407, phi = std::exp(-0.5 * z * z) / std::sqrt(2 * M_PI);
    EXPECT_NEAR(b.se_ln_median, 0.4 * std::sqrt(0.3 * 0.7 / 10) / phi, 1e-6);

    // More exceedances at the lower intensity: no increasing curve fits.
    const std::vector<Stripe> falling = {{0.2, 8, 10}, {0.4, 5, 10}, {0.9, 2, 10}};
    EXPECT_EQ(fit_stripes(falling).status, FitStatus::decreasing);

    EXPECT_THROW(fit_stripes(std::vector<Stripe>{}), std::invalid_argument);
    EXPECT_THROW(fit_stripes(std::vector<Stripe>{{0.5, 11, 10}}), std::invalid_argument);
    EXPECT_THROW(fit_stripes(std::vector<Stripe>{{0.5, 1, 0}}), std::invalid_argument);
    EXPECT_THROW(fit_stripes(std::vector<Stripe>{{0.0, 1, 2}}), std::invalid_argument);
    EXPECT_THROW(fit_stripes(single, -1.0), std::invalid_argument);
}

TEST(FragilityStripes, WilsonIntervalIsHonestAtTheEnds) {
    double lo, hi;
    wilson_interval({1.0, 0, 10}, lo, hi);
    EXPECT_EQ(lo, 0.0);
    EXPECT_NEAR(hi, 0.277533, 1e-6);
    wilson_interval({1.0, 10, 10}, lo, hi);
    EXPECT_NEAR(lo, 1.0 - 0.277533, 1e-6);
    EXPECT_NEAR(hi, 1.0, 1e-15);
    wilson_interval({1.0, 5, 10}, lo, hi);
    EXPECT_NEAR(lo, 0.236593, 1e-6);
    EXPECT_NEAR(hi, 0.763407, 1e-6);
}

TEST(FragilityIda, DefaultStates) {
    const std::vector<DamageState> s = default_damage_states();
    ASSERT_EQ(s.size(), 4u);
    EXPECT_EQ(s[0].name(), "rotation>=0.1");
    EXPECT_EQ(s[2].name(), "rotation>=0.5");
    EXPECT_EQ(s[3].name(), "overturning");
}

// Overturning at scale 1.5, safe at 2.0, overturned again at 2.5: the first level is 1.5 and
// the curve says that safe levels lie above it.
TEST(FragilityIda, CapacitiesFromOneRecord) {
    const std::vector<IdaPoint> curve = {
        {0.5, 0.05, false}, {1.0, 0.25, false}, {1.5, 7.2, true}, {2.0, 0.9, false}, {2.5, 7.2, true}};
    const IdaCapacity r01 = ida_capacity(curve, {0.1, false});
    EXPECT_TRUE(r01.reached);
    EXPECT_EQ(r01.first_level, 1.0);
    EXPECT_EQ(r01.below, 0.5);
    EXPECT_DOUBLE_EQ(r01.capacity.intensity, 0.5 + 0.5 * (0.1 - 0.05) / (0.25 - 0.05));
    EXPECT_FALSE(r01.capacity.censored);
    EXPECT_FALSE(r01.safe_above);

    const IdaCapacity r05 = ida_capacity(curve, {0.5, false});  // reached by overturning first
    EXPECT_EQ(r05.first_level, 1.5);
    EXPECT_EQ(r05.capacity.intensity, 1.5);

    const IdaCapacity over = ida_capacity(curve, {0.0, true});
    EXPECT_TRUE(over.reached);
    EXPECT_EQ(over.first_level, 1.5);
    EXPECT_EQ(over.below, 1.0);
    EXPECT_EQ(over.capacity.intensity, 1.5);
    EXPECT_TRUE(over.safe_above);

    const IdaCapacity never = ida_capacity(std::vector<IdaPoint>(curve.begin(), curve.begin() + 2), {0.0, true});
    EXPECT_FALSE(never.reached);
    EXPECT_TRUE(std::isnan(never.first_level));
    EXPECT_EQ(never.capacity.intensity, 1.0);
    EXPECT_TRUE(never.capacity.censored);

    const IdaCapacity at_once = ida_capacity(curve, {0.01, false});
    EXPECT_EQ(at_once.first_level, 0.5);
    EXPECT_TRUE(std::isnan(at_once.below));
    EXPECT_EQ(at_once.capacity.intensity, 0.5);

    const std::vector<IdaPoint> unsorted = {{1.0, 0.1, false}, {1.0, 0.2, false}};
    EXPECT_THROW(ida_capacity(unsorted, {0.1, false}), std::invalid_argument);
    EXPECT_THROW(ida_capacity(std::vector<IdaPoint>{}, {0.1, false}), std::invalid_argument);
}

TEST(FragilityStripes, CountedFromRunsPerIntensity) {
    const std::vector<IdaPoint> runs = {
        {1.0, 0.2, false}, {0.5, 0.05, false}, {1.0, 7.2, true}, {0.5, 0.4, false}, {1.0, 0.6, false}};
    const std::vector<Stripe> over = stripes_from_runs(runs, {0.0, true});
    ASSERT_EQ(over.size(), 2u);
    EXPECT_EQ(over[0].intensity, 0.5);
    EXPECT_EQ(over[0].exceed, 0);
    EXPECT_EQ(over[0].total, 2);
    EXPECT_EQ(over[1].exceed, 1);
    EXPECT_EQ(over[1].total, 3);
    const std::vector<Stripe> r03 = stripes_from_runs(runs, {0.3, false});
    EXPECT_EQ(r03[0].exceed, 1);
    EXPECT_EQ(r03[1].exceed, 2);  // the overturned run and theta_max = 0.6 alpha
    EXPECT_DOUBLE_EQ(r03[1].fraction(), 2.0 / 3.0);
    EXPECT_THROW(stripes_from_runs(std::vector<IdaPoint>{{0.0, 0.1, false}}, {0.3, false}), std::invalid_argument);
}
