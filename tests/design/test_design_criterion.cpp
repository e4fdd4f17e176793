// The design criterion on hand-made results: area weights, limits, and what it refuses.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <stdexcept>

#include "rocksweep/design/design_criterion.hpp"
#include "rocksweep/grid/refine.hpp"

using namespace rocksweep;

namespace {

// 3 amplitudes x 5 frequencies, two scenarios; every cell computed, safe, small rotation.
struct Fixture {
    SweepSpec spec;
    SweepResults r;
    Fixture() {
        spec.omega_ratio = Axis{1.0, 5.0, 5};
        spec.amplitude_ratio = Axis{2.0, 4.0, 3};
        spec.scenarios = {Scenario{"free", free_anchorage(), 0.0, 1.0}, Scenario{"free2", free_anchorage(), 0.0, 1.0}};
        r.resize(spec.cell_count());
        for (std::size_t k = 0; k < r.size(); ++k) {
            r.done[k] = cell_computed;
            r.outcome[k] = 0;
            r.max_rotation[k] = 0.5;
            r.peak_force_ratio[k] = 0.5;
        }
    }
    std::size_t cell(std::size_t s, std::size_t i_amp, std::size_t i_omega) const {
        return s * spec.cells_per_scenario() + i_amp * spec.omega_ratio.points + i_omega;
    }
};

}  // namespace

TEST(DesignCriterion, TrapezoidWeightsSumToTheRange) {
    const std::vector<double> w = node_weights(Axis{1.0, 10.0, 181});
    EXPECT_NEAR(std::accumulate(w.begin(), w.end(), 0.0), 9.0, 1e-12);
    EXPECT_NEAR(w.front(), 0.025, 1e-15);  // half of the 0.05 spacing
    EXPECT_NEAR(w[90], 0.05, 1e-15);
    EXPECT_EQ(node_weights(Axis{2.0, 2.0, 1}), std::vector<double>{1.0});
}

TEST(DesignCriterion, AreaFractionOfTheOverturnedCells) {
    Fixture f;
    // A corner cell owns 1/4 of an interior cell's area: (0.5 x 0.5) of a 4 x 2 rectangle.
    f.r.outcome[f.cell(0, 0, 0)] = 1;
    RegionScore s = score_scenario(f.spec, f.r, 0, {});
    EXPECT_NEAR(s.standing, 1.0 - 0.25 / 8.0, 1e-15);
    EXPECT_EQ(s.acceptable, s.standing);
    // An interior cell: 1 x 1 of 8.
    f.r.outcome[f.cell(0, 1, 2)] = 2;
    s = score_scenario(f.spec, f.r, 0, {});
    EXPECT_NEAR(s.standing, 1.0 - 1.25 / 8.0, 1e-15);
    // The other scenario is untouched.
    EXPECT_EQ(score_scenario(f.spec, f.r, 1, {}).standing, 1.0);
}

TEST(DesignCriterion, NotConvergedIsNotSafe) {
    Fixture f;
    f.r.outcome[f.cell(1, 1, 1)] = 255;
    EXPECT_NEAR(score_scenario(f.spec, f.r, 1, {}).standing, 1.0 - 1.0 / 8.0, 1e-15);
}

TEST(DesignCriterion, RotationAndForceLimits) {
    Fixture f;
    f.r.max_rotation[f.cell(0, 1, 1)] = 0.8;       // interior: 1/8
    f.r.peak_force_ratio[f.cell(0, 0, 2)] = 0.9;   // edge: 1/16
    f.r.peak_force_ratio[f.cell(0, 2, 4)] = NAN;   // no anchorage: no force
    EXPECT_EQ(score_scenario(f.spec, f.r, 0, {}).acceptable, 1.0);
    EXPECT_NEAR(score_scenario(f.spec, f.r, 0, {0.7, 0.0}).acceptable, 1.0 - 1.0 / 8.0, 1e-15);
    EXPECT_NEAR(score_scenario(f.spec, f.r, 0, {0.0, 0.6}).acceptable, 1.0 - 1.0 / 16.0, 1e-15);
    const RegionScore both = score_scenario(f.spec, f.r, 0, {0.7, 0.6});
    EXPECT_NEAR(both.acceptable, 1.0 - 3.0 / 16.0, 1e-15);
    EXPECT_EQ(both.standing, 1.0);
    // A limit equal to the value is met.
    EXPECT_EQ(score_scenario(f.spec, f.r, 0, {0.8, 0.9}).acceptable, 1.0);
}

TEST(DesignCriterion, RefusesWhatItCannotJudge) {
    Fixture f;
    f.r.done[f.cell(0, 2, 3)] = cell_inferred;
    EXPECT_NO_THROW(score_scenario(f.spec, f.r, 0, {}));  // the outcome alone is known
    EXPECT_THROW(score_scenario(f.spec, f.r, 0, {1.0, 0.0}), std::invalid_argument);
    f.r.done[f.cell(0, 2, 3)] = cell_pending;
    EXPECT_THROW(score_scenario(f.spec, f.r, 0, {}), std::invalid_argument);
    EXPECT_THROW(score_scenario(f.spec, f.r, 2, {}), std::invalid_argument);
}

TEST(DesignCriterion, PerLevelSharesOfASuiteScenario) {
    // The fixture's 15 cells of scenario 1 read as 3 records x 5 levels (C order, record slowest).
    Fixture f;
    const std::size_t first = f.spec.cells_per_scenario();
    f.r.outcome[first + 0 * 5 + 4] = 1;                // record 0 overturns at the top level
    f.r.outcome[first + 2 * 5 + 4] = 255;              // record 2 did not converge there: not safe
    f.r.max_rotation[first + 1 * 5 + 3] = 0.9;         // record 1 rocks beyond a 0.7 limit at level 3
    const std::vector<RegionScore> s = score_levels(f.r, first, 3, 5, {0.7, 0.0});
    ASSERT_EQ(s.size(), 5u);
    for (std::size_t l = 0; l < 3; ++l) EXPECT_EQ(s[l].acceptable, 1.0);
    EXPECT_NEAR(s[3].acceptable, 2.0 / 3.0, 1e-15);
    EXPECT_EQ(s[3].standing, 1.0);
    EXPECT_NEAR(s[4].standing, 1.0 / 3.0, 1e-15);
    EXPECT_NEAR(s[4].acceptable, 1.0 / 3.0, 1e-15);
    EXPECT_THROW(score_levels(f.r, first, 3, 6, {}), std::invalid_argument);  // past the results
}
