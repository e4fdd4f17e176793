// Block geometry and impact law (physics.md §1).
#include <gtest/gtest.h>

#include <cmath>

#include "rocksweep/physics/block.hpp"
#include "rocksweep/core/errors.hpp"

using namespace rocksweep;

TEST(Block, SanMatteoMatchesThePaper) {
    const Block b = rectangular_block(0.30, 1.36, 3361.0);
    EXPECT_NEAR(b.p(), 2.29846, 5e-6);             // paper: 2.2985 rad/s
    EXPECT_NEAR(b.alpha_rad, 0.217111, 5e-7);      // paper: 0.2171 rad
    EXPECT_NEAR(b.e, 0.930398, 5e-7);              // 1 - 3/2 sin^2(alpha)
    EXPECT_NEAR(b.radius_m, std::hypot(0.30, 1.36), 1e-15);
    EXPECT_NEAR(b.inertia(), 4.0 / 3.0 * 3361.0 * b.radius_m * b.radius_m, 1e-9);
}

TEST(Block, EquivalentBlockFromFrequencyParameterRoundTrips) {
    const double ratio = inertia_ratio_from_p(2.0, 1.5, 9.81);
    const Block b = equivalent_block(1.5, 0.2, ratio, 1000.0);
    EXPECT_NEAR(b.p(), 2.0, 1e-14);
    EXPECT_NEAR(b.e, 1.0 - 2.0 * std::pow(std::sin(0.2), 2) / ratio, 1e-15);
}

TEST(Block, UserRestitutionBelowHousnerIsKept) {
    const Block b = rectangular_block(0.30, 1.36, 3361.0, 9.81, 0.8);
    EXPECT_EQ(b.e, 0.8);
}

TEST(Block, RestitutionAboveHousnerIsRejected) {
    EXPECT_THROW(rectangular_block(0.30, 1.36, 3361.0, 9.81, 0.95), InputError);
}

TEST(Block, BlocksThatCannotRockAreRejected) {
    // sin^2(alpha) >= 2/3 for a rectangle: Housner's e <= 0.
    EXPECT_THROW(rectangular_block(1.5, 1.0, 100.0), InputError);
    // Just below the limit it rocks, with e barely above 0.
    const double alpha = std::asin(std::sqrt(2.0 / 3.0)) - 1e-6;
    const Block b = rectangular_block(std::tan(alpha), 1.0, 100.0);
    EXPECT_GT(b.e, 0.0);
    EXPECT_LT(b.e, 1e-5);
}

TEST(Block, NonPositiveSizesAndNaNAreRejectedWithTheFieldName) {
    try {
        rectangular_block(-0.3, 1.36, 3361.0);
        FAIL() << "no throw";
    } catch (const InputError& e) {
        EXPECT_EQ(e.field(), "block.half_width");
        EXPECT_NE(std::string(e.what()).find("-0.3"), std::string::npos);
    }
    EXPECT_THROW(rectangular_block(0.3, NAN, 3361.0), InputError);
    EXPECT_THROW(rectangular_block(0.3, 1.36, 0.0), InputError);
    EXPECT_THROW(rectangular_block(0.3, 1.36, 3361.0, -9.81), InputError);
}

TEST(Block, NeedlesAndUnboundedInertiaAreRejected) {
    // h / b = 1e5: alpha = 1e-5 rad, below min_alpha_rad; the error names the height.
    try {
        rectangular_block(1e-5, 1.0, 1.0);
        FAIL() << "no throw";
    } catch (const InputError& e) {
        EXPECT_EQ(e.field(), "block.half_height");
    }
    EXPECT_NO_THROW(rectangular_block(2e-4, 1.0, 1.0));  // alpha = 2e-4 rad: accepted
    // h / b = 1e4 exactly is the documented limit, accepted however b and h are scaled.
    for (double b : {1e-3, 3e-3, 7e-3, 1e-2, 0.1}) EXPECT_NO_THROW(rectangular_block(b, 1e4 * b, 1.0)) << b;
    EXPECT_THROW(rectangular_block(1e-3, 10.001, 1.0), InputError);
    EXPECT_EQ(min_alpha_rad, std::atan(1.0 / max_height_to_width));
    EXPECT_NO_THROW(equivalent_block(1.0, min_alpha_rad, 4.0 / 3.0, 1.0));
    EXPECT_NO_THROW(equivalent_block(1.0, 1e-4, 4.0 / 3.0, 1.0));
    EXPECT_THROW(equivalent_block(1.0, std::nextafter(min_alpha_rad, 0.0), 4.0 / 3.0, 1.0), InputError);
    // p = 1e-200 rad/s would need I0/(m R^2) = inf: every pulse "too fast", every cell safe.
    EXPECT_THROW(equivalent_block(1.0, 0.2, inertia_ratio_from_p(1e-200, 1.0, 9.81), 1.0), InputError);
    EXPECT_THROW(equivalent_block(1.0, 0.2, 1.0001e4, 1.0), InputError);
    EXPECT_NO_THROW(equivalent_block(1.0, 0.2, 1e4, 1.0));
    EXPECT_THROW(equivalent_block(INFINITY, 0.2, 4.0 / 3.0, 1.0), InputError);
    EXPECT_THROW(equivalent_block(1.0, 0.2, 4.0 / 3.0, INFINITY), InputError);
}
