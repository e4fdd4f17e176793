// Anchorages: Eq. 8 moment, fracture latched, adaptive law of Eq. 21-22 (physics.md §4).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "rocksweep/physics/anchorage.hpp"
#include "rocksweep/core/errors.hpp"
#include "rocksweep/physics/history.hpp"
#include "rocksweep/physics/integrator.hpp"
#include "smatteo_case.hpp"

using namespace rocksweep;

namespace {
const Block& kBlock = rocksweep::testing::kSMatteo;
const double kStrength = rocksweep::testing::kSMatteoStrength;
}  // namespace

TEST(Anchorage, StiffnessFromStrengthBreaksAtThetaF) {
    const Anchorage a = constant_anchorage(kBlock, kStrength, kBlock.alpha_rad / 2);
    const double b = kBlock.half_width_m();
    // F = K 4b tan(theta_f / 2) = F_u
    EXPECT_NEAR(a.k_max * 4 * b * std::tan(kBlock.alpha_rad / 4), kStrength, 1e-9 * kStrength);
    EXPECT_NEAR(a.break_angle(a.k_max), kBlock.alpha_rad / 2, 1e-15);
    const Anchorage k = constant_anchorage_k(kBlock, kStrength, a.k_max);
    EXPECT_NEAR(k.theta_f_rad, a.theta_f_rad, 1e-15);
}

TEST(Anchorage, MomentOfEquation8) {
    const Anchorage a = constant_anchorage(kBlock, kStrength, kBlock.alpha_rad);
    const CellModel m = make_cell_model(kBlock, a, Pulse{});
    const double b = kBlock.half_width_m();
    for (double theta : {0.01, 0.1, 0.2}) {
        for (int s : {1, -1}) {
            const double th = s * theta;
            const double with = rocking_acceleration(m, s, m.kappa_max, 0.0, 0.0, th);
            const double without = rocking_acceleration(m, s, 0.0, 0.0, 0.0, th);
            // M = K 4b tan(|theta|/2) 2b cos(|theta|/2), restoring (opposite to theta)
            const double moment = a.k_max * 4 * b * std::tan(theta / 2) * 2 * b * std::cos(theta / 2);
            EXPECT_NEAR(with - without, -s * moment / kBlock.inertia(), 1e-12 * moment / kBlock.inertia());
        }
    }
}

TEST(Anchorage, ValidationNamesTheField) {
    EXPECT_THROW(constant_anchorage(kBlock, kStrength, 0.0), InputError);
    EXPECT_THROW(constant_anchorage(kBlock, kStrength, -0.1), InputError);
    EXPECT_THROW(constant_anchorage(kBlock, 0.0, 0.1), InputError);
    EXPECT_THROW(adaptive_anchorage(kBlock, kStrength, 0.2, 0.0), InputError);
    EXPECT_THROW(adaptive_anchorage(kBlock, kStrength, 0.2, 1.5), InputError);
    EXPECT_THROW(adaptive_anchorage(kBlock, kStrength, 0.2, NAN), InputError);
    EXPECT_NO_THROW(adaptive_anchorage(kBlock, kStrength, 0.2, 1.0));
    try {
        adaptive_anchorage(kBlock, kStrength, 0.2, 1.5);
    } catch (const InputError& e) {
        EXPECT_EQ(e.field(), "anchorage.kmin_ratio");
    }
}

TEST(Anchorage, StiffnessTooSoftToBreakBeforePiIsRejectedAsStiffness) {
    // F_u / (4 b K) = 1e20: theta_f = 2 atan(1e20) rounds to pi, the spring could never break.
    const double k = kStrength / (4 * kBlock.half_width_m() * 1e20);
    try {
        constant_anchorage_k(kBlock, kStrength, k);
        FAIL() << "no throw";
    } catch (const InputError& e) {
        EXPECT_EQ(e.field(), "anchorage.stiffness");
    }
    EXPECT_THROW(constant_anchorage_k(kBlock, kStrength, INFINITY), InputError);
    EXPECT_THROW(constant_anchorage(kBlock, INFINITY, 0.1), InputError);
}

TEST(Anchorage, AdaptiveLawOnHandBuiltStates) {
    // Eq. 21, excitation acting: K_max where ax theta < 0, K_min where ax theta > 0.
    EXPECT_TRUE(adaptive_uses_kmax(true, 0.3, -0.01, 5.0, false));
    EXPECT_TRUE(adaptive_uses_kmax(true, -0.3, 0.01, -5.0, false));
    EXPECT_FALSE(adaptive_uses_kmax(true, 0.3, 0.01, 5.0, true));
    EXPECT_FALSE(adaptive_uses_kmax(true, -0.3, -0.01, 5.0, true));
    // Eq. 22, free oscillation: K_max while |theta| grows, K_min while it shrinks.
    EXPECT_TRUE(adaptive_uses_kmax(false, 0.0, 0.01, 0.5, false));
    EXPECT_TRUE(adaptive_uses_kmax(false, 0.0, -0.01, -0.5, false));
    EXPECT_FALSE(adaptive_uses_kmax(false, 0.0, 0.01, -0.5, true));
    EXPECT_FALSE(adaptive_uses_kmax(false, 0.0, -0.01, 0.5, true));
    // On the switching surface the previous K stays.
    EXPECT_TRUE(adaptive_uses_kmax(true, 0.0, 0.01, 1.0, true));
    EXPECT_FALSE(adaptive_uses_kmax(true, 0.0, 0.01, 1.0, false));
    EXPECT_TRUE(adaptive_uses_kmax(false, 0.0, 0.01, 0.0, true));
    EXPECT_FALSE(adaptive_uses_kmax(false, 0.0, 0.01, 0.0, false));
}

TEST(Anchorage, FractureIsLatchedPerCorner) {
    // theta_f = alpha/4: a pulse that swings the block past the fracture angle on one side.
    const Anchorage a = constant_anchorage(kBlock, kStrength, kBlock.alpha_rad / 4);
    Pulse p;
    p.omega = 4.0 * kBlock.p();
    p.ax_g = 2.0 * kBlock.alpha_rad;
    const CellModel m = make_cell_model(kBlock, a, p);
    const History h = sample_history(m, IntegratorSettings{}, 0.001, 8.0);
    ASSERT_NE(h.result.broken, 0);
    // Once a spring's stiffness has dropped to 0 while its side is rocking, it never comes back.
    for (int side : {1, -1}) {
        const std::vector<double>& k = side > 0 ? h.k_left : h.k_right;
        const std::uint8_t bit = side > 0 ? broken_left : broken_right;
        bool seen_broken = false;
        for (std::size_t i = 0; i < h.t.size(); ++i) {
            if (side * h.theta[i] <= 1e-9) continue;
            if (k[i] == 0.0) seen_broken = true;
            if (seen_broken) {
                EXPECT_EQ(k[i], 0.0) << "spring back at t = " << h.t[i];
            }
        }
        EXPECT_EQ(seen_broken, (h.result.broken & bit) != 0);
    }
    EXPECT_LE(h.result.peak_force_ratio, 1.0 + 1e-9);
}

TEST(Anchorage, AdaptiveStiffnessSwitchesWithTheLawDuringTheRun) {
    const Anchorage a = adaptive_anchorage(kBlock, kStrength, kBlock.alpha_rad, 0.5);
    Pulse p;
    p.omega = 4.0 * kBlock.p();
    p.ax_g = 2.7 * kBlock.alpha_rad;
    const CellModel m = make_cell_model(kBlock, a, p);
    const History h = sample_history(m, IntegratorSettings{}, 0.0005, 6.0);
    std::size_t checked = 0;
    for (std::size_t i = 0; i < h.t.size(); ++i) {
        const double k = h.theta[i] > 0 ? h.k_left[i] : h.k_right[i];
        if (h.theta[i] == 0.0 || k == 0.0) continue;
        const bool acting = h.t[i] < p.end_time();
        const double x = acting ? -h.ground_acc[i] * h.theta[i] : h.theta[i] * h.theta_dot[i];
        if (std::abs(x) < 1e-3 * std::abs(h.theta[i])) continue;  // too near a switch to tell
        EXPECT_EQ(k, x > 0 ? a.k_max : a.k_min) << "t = " << h.t[i];
        ++checked;
    }
    EXPECT_GT(checked, 1000u);
}
