// The covariance of ln(median) and beta that each fragility fit reports (records/fragility.hpp,
// stripe_clusters.hpp), against the empirical covariance of the estimates over repeated seeded
// experiments, and its sign against what the data's position on the curve implies: data that
// see only the curve's lower part pin a low quantile, ln(median) - z beta with z < 0, so a
// larger beta goes with a larger median (covariance > 0); data above the median, the reverse.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <vector>

#include "rocksweep/records/fragility.hpp"
#include "rocksweep/records/stripe_clusters.hpp"

#include "simulated_ida.hpp"

namespace rocksweep {
namespace {

/// Estimates of (ln median, beta) over repeated experiments and the covariance each reported.
struct Scatter {
    std::vector<double> m, b;
    double reported = 0.0;  // mean of the reported covariances
    void add(const FragilityFit& f) {
        m.push_back(std::log(f.curve.median));
        b.push_back(f.curve.beta);
        reported += f.cov_ln_median_beta;
    }
    double n() const { return static_cast<double>(m.size()); }
    double mean(const std::vector<double>& v) const {
        double s = 0.0;
        for (double x : v) s += x;
        return s / n();
    }
    double cov(const std::vector<double>& x, const std::vector<double>& y) const {
        const double mx = mean(x), my = mean(y);
        double s = 0.0;
        for (std::size_t k = 0; k < x.size(); ++k) s += (x[k] - mx) * (y[k] - my);
        return s / (n() - 1);
    }
    double empirical() const { return cov(m, b); }
    double mean_reported() const { return reported / n(); }
    /// Sampling standard deviation of the empirical covariance (normal estimates):
    /// sqrt((var_m var_b + cov^2) / n).
    double sampling_sd() const {
        const double c = empirical();
        return std::sqrt((cov(m, m) * cov(b, b) + c * c) / n());
    }
    /// The reported covariance agrees with the scatter within 4 of its sampling standard
    /// deviations plus `bias` of its size (the formulas are asymptotic).
    void expect_agrees(double bias, const char* what) const {
        std::printf("%s: empirical %.3e +- %.1e, reported %.3e (n %g)\n", what, empirical(), sampling_sd(),
                    mean_reported(), n());
        EXPECT_NEAR(mean_reported(), empirical(), 4.0 * sampling_sd() + bias * std::abs(empirical())) << what;
    }
};

Scatter repeat(int times, unsigned seed, const std::function<FragilityFit(std::mt19937_64&)>& one) {
    std::mt19937_64 rng(seed);
    Scatter s;
    for (int k = 0; k < times; ++k) {
        const FragilityFit f = one(rng);
        if (f.status == FitStatus::ok) s.add(f);
    }
    return s;
}

std::vector<Capacity> capacities(std::mt19937_64& rng, int n, double median, double beta, double censor_at) {
    std::normal_distribution<double> z;
    std::vector<Capacity> c;
    for (int i = 0; i < n; ++i) {
        const double x = median * std::exp(beta * z(rng));
        c.push_back(x > censor_at ? Capacity{censor_at, true} : Capacity{x, false});
    }
    return c;
}

// Uncensored capacities: the normal MLE's mean and standard deviation are independent, so the
// covariance is 0, and 2000 experiments of 40 records scatter with none (within 4 sampling sd,
// 1.4e-4 here).
TEST(FitCovariance, ClosedFormIsZeroAndSoIsTheScatter) {
    const Scatter s = repeat(2000, 5, [](std::mt19937_64& r) { return fit_capacities(capacities(r, 40, 0.8, 0.6, INFINITY)); });
    ASSERT_EQ(s.n(), 2000);
    EXPECT_EQ(s.mean_reported(), 0.0);
    s.expect_agrees(0.0, "closed form");
}

// An IDA stopped at the median: the upper half censored, the lower half seen, so the
// covariance is positive; 1000 experiments of 200 records.
TEST(FitCovariance, CensoredAboveIsPositiveAndMatchesTheScatter) {
    const Scatter s = repeat(1000, 9, [](std::mt19937_64& r) { return fit_capacities(capacities(r, 200, 0.8, 0.6, 0.8)); });
    ASSERT_GT(s.n(), 990);
    EXPECT_GT(s.mean_reported(), 0.0);
    EXPECT_GT(s.empirical(), 4.0 * s.sampling_sd());
    s.expect_agrees(0.1, "censored at the median");
}

/// Independent binomial runs: `per` runs at each of 6 levels from `lo` to `hi` (log-spaced),
/// true median 0.7, beta 0.5.
FragilityFit binomial(std::mt19937_64& rng, double lo, double hi, int per, double fixed_beta = 0.0) {
    std::vector<Stripe> stripes;
    for (int j = 0; j < 6; ++j) {
        const double x = lo * std::pow(hi / lo, j / 5.0);
        std::binomial_distribution<int> draw(per, LognormalFragility{0.7, 0.5}.probability(x));
        stripes.push_back({x, draw(rng), per});
    }
    return fit_stripes(stripes, fixed_beta);
}

// Stripes below the median (0.25-0.7 g) give a positive covariance, above it (0.7-2 g) a
// negative one, each matching the scatter of 1000 experiments of 100 runs per stripe; a fixed
// beta has none.
TEST(FitCovariance, StripesSignFollowsWhereTheDataAre) {
    const Scatter below = repeat(1000, 21, [](std::mt19937_64& r) { return binomial(r, 0.25, 0.7, 100); });
    const Scatter above = repeat(1000, 22, [](std::mt19937_64& r) { return binomial(r, 0.7, 2.0, 100); });
    ASSERT_GT(below.n(), 990);
    ASSERT_GT(above.n(), 990);
    EXPECT_GT(below.mean_reported(), 0.0);
    EXPECT_LT(above.mean_reported(), 0.0);
    below.expect_agrees(0.1, "stripes below the median");
    above.expect_agrees(0.1, "stripes above the median");
    std::mt19937_64 rng(1);
    EXPECT_EQ(binomial(rng, 0.25, 2.0, 50, 0.5).cov_ln_median_beta, 0.0);
}

// The sandwich's covariance matches the scatter of 600 IDA experiments of 60 records; with the
// median high in the levels (1.2 of 0.05-1.5 g: its upper part unseen) it is positive, as
// censoring above makes it; the pooled fit's observed information, counting each run as a
// trial, claims a covariance several times too small.
TEST(FitCovariance, ClusteredMatchesTheScatterOfRecords) {
    for (const double median : {0.7, 1.2}) {
        Scatter clustered, pooled;
        std::mt19937_64 rng(static_cast<unsigned>(100 * median));
        for (int k = 0; k < 600; ++k) {
            const simulated::Ida e = simulated::ida(rng, 60, median, 0.6);
            if (e.clustered.status != FitStatus::ok) continue;
            clustered.add(e.clustered);
            pooled.add(e.pooled);
        }
        ASSERT_GT(clustered.n(), 590);
        clustered.expect_agrees(0.15, median < 1 ? "clustered, median 0.7" : "clustered, median 1.2");
        if (median > 1) {
            EXPECT_GT(clustered.mean_reported(), 0.0);
            EXPECT_GT(clustered.empirical(), 4.0 * clustered.sampling_sd());
            EXPECT_LT(std::abs(pooled.mean_reported()), 0.5 * clustered.empirical());
        }
    }
}

}  // namespace
}  // namespace rocksweep
