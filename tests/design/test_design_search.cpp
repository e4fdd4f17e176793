// The design search on synthetic criteria whose maximum is known: no physics, no files.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <vector>

#include "rocksweep/design/design_search.hpp"

using namespace rocksweep;

namespace {

struct Found {
    SearchPoint best;
    int rounds = 0;           ///< rounds run after the coarse one
    std::size_t evaluations = 0;
};

/// Runs the search to its end on `f`, as the design command does with sweeps.
Found search(const SearchSettings& s, const std::function<double(double)>& f) {
    const BracketSearch bs(s);
    std::vector<SearchPoint> seen;
    auto evaluate = [&](const std::vector<double>& xs) {
        for (double x : xs) {
            for (const SearchPoint& p : seen) EXPECT_NE(p.x, x) << "evaluated twice";
            EXPECT_GE(x, s.lo);
            EXPECT_LE(x, s.hi);
            seen.push_back({x, f(x)});
        }
    };
    evaluate(bs.first_round());
    Found out;
    for (int round = 1;; ++round) {
        const std::vector<double> xs = bs.next_round(round, seen);
        if (xs.empty()) break;
        EXPECT_TRUE(std::is_sorted(xs.begin(), xs.end()));
        evaluate(xs);
        out.rounds = round;
    }
    sort_by_x(seen);
    out.best = seen[best_point(seen)];
    out.evaluations = seen.size();
    return out;
}

}  // namespace

TEST(DesignSearch, SmoothMaximumWithinTheTolerance) {
    // A unimodal criterion: once both intervals beside the best point are below the
    // tolerance, the true maximum lies within one tolerance of it.
    const double x0 = 4.873;
    SearchSettings s{3.0, 7.0, 9, 2, 20, 1e-3};
    const Found f = search(s, [&](double x) { return 1.0 - (x - x0) * (x - x0); });
    EXPECT_NEAR(f.best.x, x0, s.tolerance);
    EXPECT_LT(f.rounds, s.max_rounds) << "stopped by the tolerance, not by the round cap";
    // 9 coarse points, then at most 4 per round.
    EXPECT_LE(f.evaluations, 9u + 4u * static_cast<std::size_t>(f.rounds));
}

TEST(DesignSearch, StepCriterionEndsOnItsTopPlateau) {
    // Like a safe fraction counted on a grid: steps of 1/20, the top step (value 1) for
    // |x - x0| < sqrt(0.1) ~ 0.316; the coarse grid, 0.5 apart, holds at most one point of it.
    const double x0 = 5.21;
    auto f = [&](double x) { return std::round(20.0 * (1.0 - (x - x0) * (x - x0) / 4.0)) / 20.0; };
    const Found found = search({3.0, 7.0, 9, 2, 6, 1e-3}, f);
    EXPECT_EQ(found.best.value, 1.0);
    EXPECT_LT(std::abs(found.best.x - x0), std::sqrt(0.1));
}

TEST(DesignSearch, HigherOfTwoMaximaWhenTheCoarseGridSeesBoth) {
    // A broad hump (0.6 at 3.5) and a narrower, higher one (0.8 at 6.1): bracketing keeps
    // every point, so it refines around the higher one.
    auto f = [](double x) { return std::max(0.6 - (x - 3.5) * (x - 3.5), 0.8 - 4.0 * (x - 6.1) * (x - 6.1)); };
    const Found found = search({3.0, 7.0, 9, 2, 20, 1e-3}, f);
    EXPECT_NEAR(found.best.x, 6.1, 1e-3);
    EXPECT_NEAR(found.best.value, 0.8, 1e-5);
}

TEST(DesignSearch, MaximumAtTheEndOfTheRange) {
    const Found found = search({-2.0, 0.0, 5, 3, 10, 1e-2}, [](double x) { return x; });
    EXPECT_EQ(found.best.x, 0.0);
    // The one interval beside the end shrinks 4x a round: 0.5, 0.125, 0.031, then 0.0078 < 0.01.
    EXPECT_EQ(found.rounds, 3);
}

TEST(DesignSearch, StopsAfterMaxRounds) {
    SearchSettings s{0.0, 1.0, 3, 1, 2, 1e-9};
    const Found found = search(s, [](double x) { return -std::abs(x - 0.3141); });
    EXPECT_EQ(found.rounds, 2);
    EXPECT_EQ(found.evaluations, 3u + 2u + 2u);
}

TEST(DesignSearch, ZeroRoundsIsTheCoarseGridAlone) {
    const BracketSearch bs({1.0, 2.0, 5, 2, 0, 0.01});
    const std::vector<double> x = bs.first_round();
    ASSERT_EQ(x.size(), 5u);
    EXPECT_EQ(x.front(), 1.0);
    EXPECT_EQ(x.back(), 2.0);
    EXPECT_DOUBLE_EQ(x[2], 1.5);
    std::vector<SearchPoint> seen;
    for (double v : x) seen.push_back({v, v});
    EXPECT_TRUE(bs.next_round(1, seen).empty());
}

TEST(DesignSearch, TiesGoToTheMiddleOfTheWidestRun) {
    // Runs of the top value: {0} alone and {2, 3, 4}: the middle of the wider one.
    std::vector<SearchPoint> p{{0.0, 1.0}, {1.0, 0.5}, {2.0, 1.0}, {3.0, 1.0}, {4.0, 1.0}, {5.0, 0.0}};
    EXPECT_EQ(best_point(p), 3u);
    // A single highest point wins over any plateau of lower values.
    std::vector<SearchPoint> q{{0.0, 0.9}, {1.0, 0.9}, {2.0, 0.9}, {3.0, 0.95}};
    EXPECT_EQ(best_point(q), 3u);
}

TEST(DesignSearch, NearBestRunStopsAtTheFirstValueBelowTheMargin) {
    std::vector<SearchPoint> p{{0.0, 0.80}, {1.0, 0.896}, {2.0, 0.90}, {3.0, 0.899}, {4.0, 0.70}, {5.0, 0.899}};
    EXPECT_EQ(near_best(p, 2, 0.005), (std::pair<std::size_t, std::size_t>{1, 3}));
    EXPECT_EQ(near_best(p, 2, 0.0), (std::pair<std::size_t, std::size_t>{2, 2}));
    EXPECT_EQ(near_best(p, 2, 1.0), (std::pair<std::size_t, std::size_t>{0, 5}));
    EXPECT_THROW(near_best(p, 6, 0.1), std::invalid_argument);
}

TEST(DesignSearch, RefusesSettingsItCannotHonour) {
    EXPECT_THROW(BracketSearch({1.0, 1.0, 9, 2, 4, 0.01}), std::invalid_argument);
    EXPECT_THROW(BracketSearch({2.0, 1.0, 9, 2, 4, 0.01}), std::invalid_argument);
    EXPECT_THROW(BracketSearch({0.0, 1.0, 2, 2, 4, 0.01}), std::invalid_argument);
    EXPECT_THROW(BracketSearch({0.0, 1.0, 9, 0, 4, 0.01}), std::invalid_argument);
    EXPECT_THROW(BracketSearch({0.0, 1.0, 9, 2, 4, 0.0}), std::invalid_argument);
    EXPECT_THROW(BracketSearch({0.0, NAN, 9, 2, 4, 0.01}), std::invalid_argument);
}
