// --check-sensitivity (SensitivityCheck in suite_sweep.hpp): a run at a record's overturning
// edge, found by bisection on the record's scale, is flagged; a run far from every edge is not;
// the check never changes the run's own results.
#include <gtest/gtest.h>

#include <cmath>

#include "rocksweep/physics/integrator.hpp"
#include "rocksweep/records/suite_sweep.hpp"

using namespace rocksweep;

namespace {

const Block kBlock = rectangular_block(0.30, 1.36, 3361.0);  // S. Matteo

struct Runner {
    SuiteSpec spec;
    IntegratorSettings settings;

    Runner() {
        const std::vector<Scenario> free{{"free", free_anchorage(), 0.0, 1.0}};
        spec = make_suite_spec(ROCKSWEEP_CONFIGS_DIR "/records_suite.csv", kBlock, free, IntensityMeasure::scale,
                               Axis{1.0, 1.0, 1}, {});
        settings.tolerance = 1e-8;  // the suite's default
        spec.sensitivity.damage_ratios = {0.1, 0.3, 0.5};
    }
    /// The free block under the suite's first record times `scale` (cell 0 of a one-level suite).
    CellResult run(double scale, bool check) {
        spec.intensity = Axis{scale, scale, 1};
        spec.sensitivity.on = check;
        CellResult r;
        compute_suite_cells(spec, settings, 0, 1, &r);
        return r;
    }
};

TEST(SuiteSensitivity, RunsBracketingAnOverturningEdgeAreFlagged) {
    Runner t;
    double lo = 0.05, hi = 0.1;
    while (t.run(hi, false).outcome == Outcome::safe) {
        lo = hi;
        hi *= 2.0;
        ASSERT_LT(hi, 100.0) << "the block never overturns";
    }
    ASSERT_EQ(t.run(lo, false).outcome, Outcome::safe);
    // To a relative width far below the check's 1e-9: the rerun of one of the two end runs
    // (at 1 + 1e-9 their scale, tighter) must land on the other side of its own edge, unless
    // that edge sits in a window 1e-12 wide.
    while (hi - lo > 1e-13 * hi) {
        const double mid = 0.5 * (lo + hi);
        (t.run(mid, false).outcome == Outcome::safe ? lo : hi) = mid;
    }
    const CellResult below = t.run(lo, true), above = t.run(hi, true);
    EXPECT_EQ(below.outcome, Outcome::safe);
    EXPECT_NE(above.outcome, Outcome::safe);
    EXPECT_EQ(below.sensitive + above.sensitive >= 1, true) << "edge between scales " << lo << " and " << hi;
    // The flag is all the check adds: the run's own results are those without it.
    CellResult plain = t.run(lo, false);
    plain.sensitive = below.sensitive;
    EXPECT_TRUE(bitwise_equal(plain, below));
}

TEST(SuiteSensitivity, RunsFarFromEveryEdgeAreNotFlagged) {
    Runner t;
    // Well below any uplift (0.02 x the record: theta_max / alpha far under 0.1) and far above
    // overturning (x 20): a 1e-9 change moves neither across a damage state.
    const CellResult small = t.run(0.02, true), big = t.run(20.0, true);
    ASSERT_LT(small.max_rotation, 0.05);
    ASSERT_NE(big.outcome, Outcome::safe);
    EXPECT_EQ(small.sensitive, 0);
    EXPECT_EQ(big.sensitive, 0);
}

TEST(SuiteSensitivity, DifferCountsOutcomeAndEveryDamageState) {
    SensitivityCheck c;
    c.damage_ratios = {0.1, 0.3, 0.5};
    CellResult a, b;
    a.max_rotation = 0.29;
    b.max_rotation = 0.31;  // across 0.3
    EXPECT_TRUE(c.differ(a, b));
    b.max_rotation = 0.2999;  // same state, 0.1 <= x < 0.3
    EXPECT_FALSE(c.differ(a, b));
    b.outcome = Outcome::overturned_impact;
    EXPECT_TRUE(c.differ(a, b));
    IntegratorSettings s;
    s.tolerance = 1e-8;
    EXPECT_DOUBLE_EQ(SensitivityCheck::tighter(s).tolerance, 1e-10);
    s.tolerance = 0.0;
    EXPECT_NEAR(SensitivityCheck::tighter(s).steps_per_period, 48.0 * std::sqrt(10.0), 1e-12);
}

}  // namespace
