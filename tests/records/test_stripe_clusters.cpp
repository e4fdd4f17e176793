// Record-clustered standard errors of a stripe fit (records/stripe_clusters.hpp): an IDA gives
// every record at every level, and the errors must be those of the records, not of the runs.
#include "rocksweep/records/stripe_clusters.hpp"

#include "simulated_ida.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

namespace rocksweep {
namespace {

constexpr double kMedian = 0.7, kBeta = 0.6;

std::vector<double> levels() { return simulated::ida_levels(); }

struct Spread {
    double sd_ln_median = 0.0, sd_beta = 0.0;          // of the estimates over the experiments
    double naive_se = 0.0, clustered_se = 0.0;         // mean standard errors of ln median
    double naive_se_beta = 0.0, clustered_se_beta = 0.0;
    int covered = 0, n = 0;                            // clustered intervals holding the true median
};

Spread spread(int experiments, int records, bool independent, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::vector<double> m, b;
    Spread s;
    for (int k = 0; k < experiments; ++k) {
        const simulated::Ida e = simulated::ida(rng, records, kMedian, kBeta, independent);
        if (e.pooled.status != FitStatus::ok) continue;
        m.push_back(std::log(e.pooled.curve.median));
        b.push_back(e.pooled.curve.beta);
        s.naive_se += e.pooled.se_ln_median;
        s.clustered_se += e.clustered.se_ln_median;
        s.naive_se_beta += e.pooled.se_beta;
        s.clustered_se_beta += e.clustered.se_beta;
        s.covered += e.clustered.median_lo <= kMedian && kMedian <= e.clustered.median_hi ? 1 : 0;
    }
    s.n = static_cast<int>(m.size());
    auto sd = [](const std::vector<double>& v) {
        double mean = 0.0, ss = 0.0;
        for (double x : v) mean += x / v.size();
        for (double x : v) ss += (x - mean) * (x - mean);
        return std::sqrt(ss / (v.size() - 1));
    };
    s.sd_ln_median = sd(m);
    s.sd_beta = sd(b);
    s.naive_se /= s.n;
    s.clustered_se /= s.n;
    s.naive_se_beta /= s.n;
    s.clustered_se_beta /= s.n;
    return s;
}

// 400 IDA experiments of 100 records at 30 levels: the estimates scatter by what the clustered
// errors say (within 12 %: the scatter's own sampling error at 400 is ~3.5 %), the run-counting
// errors are far smaller (measured 0.28 of it: sd 0.060, clustered 0.061, run-counting 0.017;
// beta 0.047, 0.048, 0.021), and the clustered 95 % intervals hold the
// true median in 0.91-0.98 of the experiments (measured 0.96; binomial sd at 400: 0.011).
TEST(StripeClusters, IdaErrorsAreThoseOfTheRecords) {
    const Spread s = spread(400, 100, false, 20261127);
    ASSERT_EQ(s.n, 400);
    std::printf("sd ln median %.4f, clustered se %.4f, naive se %.4f; sd beta %.4f, clustered %.4f, naive %.4f; covered %d of %d\n", s.sd_ln_median, s.clustered_se, s.naive_se, s.sd_beta, s.clustered_se_beta, s.naive_se_beta, s.covered, s.n);
    EXPECT_NEAR(s.clustered_se / s.sd_ln_median, 1.0, 0.12) << s.clustered_se << " vs " << s.sd_ln_median;
    EXPECT_NEAR(s.clustered_se_beta / s.sd_beta, 1.0, 0.15) << s.clustered_se_beta << " vs " << s.sd_beta;
    EXPECT_LT(s.naive_se / s.sd_ln_median, 0.5) << "the runs-as-trials error is not too small here: the test shows nothing";
    EXPECT_GE(s.covered, static_cast<int>(0.91 * s.n));
    EXPECT_LE(s.covered, static_cast<int>(0.98 * s.n));
    // For the README's sizes: close to the closed form of one capacity per record, beta / sqrt(G).
    EXPECT_NEAR(s.clustered_se / (kBeta / std::sqrt(100.0)), 1.0, 0.2);
}

// When every run is its own trial the clusters carry no extra correlation: the sandwich
// agrees with the observed information (on average within 6 %).
TEST(StripeClusters, IndependentRunsKeepTheObservedInformation) {
    const Spread s = spread(200, 100, true, 7);
    ASSERT_GT(s.n, 190);
    std::printf("independent: clustered se %.4f, naive se %.4f; beta %.4f, %.4f\n", s.clustered_se, s.naive_se, s.clustered_se_beta, s.naive_se_beta);
    EXPECT_NEAR(s.clustered_se / s.naive_se, 1.0, 0.06);
    EXPECT_NEAR(s.clustered_se_beta / s.naive_se_beta, 1.0, 0.08);
}

TEST(StripeClusters, DegenerateFitsAndInputsAreLeftAlone) {
    const std::vector<double> x = {0.2, 0.4};
    const std::vector<Stripe> none = {{0.2, 0, 3}, {0.4, 0, 3}};
    const FragilityFit f = fit_stripes(none);
    StripeClusters c(f, x);
    const std::vector<std::int8_t> miss = {0, 0};
    c.add(miss);
    c.add(miss);
    const FragilityFit g = c.corrected(none);
    EXPECT_EQ(g.status, FitStatus::none_reached);
    EXPECT_TRUE(std::isnan(g.se_ln_median));
    const std::vector<std::int8_t> wrong = {0};
    EXPECT_THROW(c.add(wrong), std::invalid_argument);
    EXPECT_THROW(StripeClusters(f, {0.2, -1.0}), std::invalid_argument);

    // One record is no spread: the fit's own errors are kept.
    std::mt19937_64 rng(3);
    const simulated::Ida e = simulated::ida(rng, 40, kMedian, kBeta);
    StripeClusters one(e.pooled, levels());
    one.add(std::vector<std::int8_t>(30, 0));
    EXPECT_EQ(one.corrected({}).se_ln_median, e.pooled.se_ln_median);
}

// A record with a run that did not converge counts the runs it has.
TEST(StripeClusters, UnobservedRunsAreLeftOut) {
    std::mt19937_64 rng(11);
    const simulated::Ida e = simulated::ida(rng, 60, kMedian, kBeta);
    const std::vector<double> x = levels();
    StripeClusters a(e.pooled, x), b(e.pooled, x);
    std::vector<std::int8_t> r(30, 0), with_gap(30, 0);
    for (int l = 15; l < 30; ++l) r[l] = with_gap[l] = 1;
    with_gap[3] = -1;  // a safe run (score < 0 there) left out: the record's score grows
    for (int k = 0; k < 5; ++k) a.add(r), b.add(with_gap);
    std::vector<Stripe> s;
    for (double xl : x) s.push_back({xl, xl >= 0.8 ? 5 : 0, 5});
    EXPECT_NE(a.corrected(s).se_ln_median, b.corrected(s).se_ln_median);
}

}  // namespace
}  // namespace rocksweep
