#pragma once
// What the spectra file tests (whole-file and streaming writers) share: "the same results".
#include <gtest/gtest.h>

#include "rocksweep/grid/sweep.hpp"
#include "rocksweep/physics/anchorage.hpp"
#include "rocksweep/physics/block.hpp"
#include "test_support.hpp"

namespace rocksweep::testing {

/// Two scenarios (free, constant) on a 3 x 4 grid.
inline SweepSpec small_spec() {
    SweepSpec spec;
    spec.block = rectangular_block(0.3, 1.36, 3361);
    spec.omega_ratio = Axis{1.0, 4.0, 4};
    spec.amplitude_ratio = Axis{1.0, 3.0, 3};
    spec.phase = 0.25;
    spec.scenarios.push_back(Scenario{"free", free_anchorage(), 0.0, 1.0});
    spec.scenarios.push_back(Scenario{
        "constant_alpha", constant_anchorage(spec.block, 0.4 * 3361 * 9.81, spec.block.alpha_rad),
        1.0, 1.0});
    return spec;
}


/// Every column equal, doubles bit for bit (NaN == NaN).
inline void expect_same_results(const SweepResults& a, const SweepResults& b) {
    EXPECT_EQ(a.outcome, b.outcome);
    EXPECT_EQ(bits(a.max_rotation), bits(b.max_rotation));
    EXPECT_EQ(a.impacts, b.impacts);
    EXPECT_EQ(a.impacts_total, b.impacts_total);
    EXPECT_EQ(bits(a.t_overturn), bits(b.t_overturn));
    EXPECT_EQ(bits(a.peak_force_ratio), bits(b.peak_force_ratio));
    EXPECT_EQ(a.broken, b.broken);
    EXPECT_EQ(bits(a.mu_required), bits(b.mu_required));
    EXPECT_EQ(a.pivot_uplift, b.pivot_uplift);
    EXPECT_EQ(a.done, b.done);
}

}  // namespace rocksweep::testing
