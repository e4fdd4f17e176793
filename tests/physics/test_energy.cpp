// Energy of free rocking: potentials consistent with the equation of motion, and the energy
// decision agreeing with simulation (physics.md §5).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "rocksweep/physics/anchorage.hpp"
#include "rocksweep/physics/energy.hpp"
#include "rocksweep/physics/history.hpp"
#include "rocksweep/physics/integrator.hpp"
#include "smatteo_case.hpp"

using namespace rocksweep;

namespace {
const Block& kBlock = rocksweep::testing::kSMatteo;
const double kStrength = rocksweep::testing::kSMatteoStrength;
}  // namespace

TEST(Energy, PotentialsAreTheIntegralsOfTheRestoringTerms) {
    const CellModel m = make_cell_model(kBlock, constant_anchorage(kBlock, kStrength, kBlock.alpha_rad), Pulse{});
    for (Equations eq : {Equations::nonlinear, Equations::linearised}) {
        CellModel c = m;
        c.equations = eq;
        for (double phi : {0.01, 0.1, 0.2, 0.5, 1.2}) {
            const double h = 1e-6;
            auto v = [&](double x) { return gravity_potential(c, x) + spring_potential(c, c.kappa_max, x); };
            const double slope = (v(phi + h) - v(phi - h)) / (2 * h);
            // theta'' on side +1 at theta = phi, no ground motion, is -dV/dphi.
            EXPECT_NEAR(-slope, rocking_acceleration(c, 1, c.kappa_max, 0, 0, phi), 1e-6 * c.p2);
        }
    }
}

TEST(Energy, SwingPeakMatchesSimulatedFreeRocking) {
    // After the pulse, the first swing after an impact peaks where the energy says.
    for (int kind : {0, 1}) {
        const Anchorage a = kind ? constant_anchorage(kBlock, kStrength, kBlock.alpha_rad) : free_anchorage();
        Pulse p;
        p.omega = (kind ? 4.0 : 6.0) * kBlock.p();
        p.ax_g = (kind ? 2.7 : 4.0) * kBlock.alpha_rad;
        const CellModel m = make_cell_model(kBlock, a, p);
        IntegratorSettings s;
        s.energy_stop = false;
        s.steps_per_period = 512;
        s.t_end_s = 20.0;
        double v_out = NAN, peak = 0.0;
        int side = 0;
        bool done = false;
        integrate_cell(m, s, [&](const StepRecord& r) {
            if (done || r.t0 < p.end_time()) return;
            if (r.theta0 == 0.0 && std::isnan(v_out)) {
                v_out = std::abs(r.theta_dot0);
                side = r.theta_dot0 > 0 ? 1 : -1;
            }
            if (!std::isnan(v_out)) {
                if (side * r.theta1 < 0.0) done = true;
                else peak = std::max(peak, side * r.theta1);
            }
        });
        ASSERT_FALSE(std::isnan(v_out));
        const Swing sw = outward_swing(m, 0.5 * v_out * v_out, m.kappa_max, m.kappa_min, m.break_max);
        ASSERT_TRUE(sw.bounded);
        EXPECT_NEAR(sw.peak, peak, 1e-4 * peak);  // step-end samples: peak seen within O(dt^2)
        EXPECT_GE(sw.peak, peak);
        EXPECT_NEAR(sw.ke_return, 0.5 * v_out * v_out, 1e-15);  // conservative swing
    }
}

TEST(Energy, BarrierSeparatesReturnFromOverturning) {
    const CellModel m = make_cell_model(kBlock, free_anchorage(), Pulse{});
    const double barrier = gravity_potential(m, m.alpha);
    EXPECT_TRUE(outward_swing(m, barrier * (1 - 1e-9), 0, 0, INFINITY).bounded);
    EXPECT_FALSE(outward_swing(m, barrier * (1 + 1e-9), 0, 0, INFINITY).bounded);
    // Eq. 19 for the free block: theta_dot^2 = 2 p^2 (1 - cos(alpha)) from theta = 0.
    EXPECT_NEAR(2 * barrier, 2 * m.p2 * (1 - std::cos(m.alpha)), 1e-15);
}

TEST(Energy, AdaptiveSwingReturnsWithLessEnergy) {
    const CellModel m = make_cell_model(kBlock, adaptive_anchorage(kBlock, kStrength, kBlock.alpha_rad, 0.1), Pulse{});
    const Swing sw = outward_swing(m, 0.3 * gravity_potential(m, m.alpha), m.kappa_max, m.kappa_min, m.break_max);
    ASSERT_TRUE(sw.bounded);
    EXPECT_LT(sw.ke_return, 0.3 * gravity_potential(m, m.alpha));
    EXPECT_NEAR(sw.ke_return, gravity_potential(m, sw.peak) + spring_potential(m, m.kappa_min, sw.peak), 1e-12);
}

TEST(Energy, FreeFateCountsTheGeometricTailOfImpacts) {
    const CellModel m = make_cell_model(kBlock, free_anchorage(), Pulse{});
    const double v = 100 * m.v_threshold;
    const FreeFate f = free_fate(m, 1, v, true, true);
    ASSERT_TRUE(f.decided);
    // approach speeds v, e v, e^2 v, ... above the threshold: floor(ln(100) / ln(1/e)) + 1
    const int expected = static_cast<int>(std::floor(std::log(100.0) / -std::log(m.e))) + 1;
    EXPECT_EQ(f.impacts, expected);
    EXPECT_EQ(f.impacts_total, expected + 1);
}

TEST(Energy, AdaptiveSwitchesReportTheSpringEnergyTheyInject) {
    // The paper's adaptive law switches K_min -> K_max at nonzero elongation while the ground
    // moves: each switch raises the spring's potential 16 b^2 K (1 - cos(phi/2)) by
    // 16 b^2 (K_max - K_min)(1 - cos(phi/2)). Recomputed here from the sampled history (the
    // stiffness columns and theta at the first sample after each switch, 1e-5 s apart).
    // Several cycles of ground motion (a one-sine pulse changes sign only once), as a record:
    // 3 s of a 1.7 Hz and a 4.1 Hz sine, 0.9 and 0.5 tan(alpha) g, sampled every 5 ms.
    Pulse p;
    p.kind = PulseKind::record;
    p.record_dt_s = 0.005;
    auto samples = std::make_shared<std::vector<double>>();
    for (int i = 0; i <= 600; ++i) {
        const double t = i * p.record_dt_s;
        samples->push_back(std::tan(kBlock.alpha_rad) * (0.9 * std::sin(2 * M_PI * 1.7 * t) + 0.5 * std::sin(2 * M_PI * 4.1 * t)));
    }
    p.record = samples;
    const CellModel m = make_cell_model(kBlock, adaptive_anchorage(kBlock, kStrength, kBlock.alpha_rad, 0.1), p);
    const double dt = 1e-5;
    const History h = sample_history(m, {}, dt, 5.0);
    const double b = kBlock.half_width_m(), k_max = m.k_max_n_m, k_min = m.k_min_n_m;
    double expected = 0.0;
    int switches = 0;
    for (std::size_t i = 1; i < h.t.size(); ++i) {
        for (const auto* k : {&h.k_left, &h.k_right}) {
            if ((*k)[i - 1] == k_min && (*k)[i] == k_max && h.theta[i] != 0.0) {
                expected += 16.0 * b * b * (k_max - k_min) * (1.0 - std::cos(0.5 * std::abs(h.theta[i])));
                ++switches;
            }
        }
        ASSERT_GE(h.e_switch[i], h.e_switch[i - 1]);  // only the injections are counted
    }
    EXPECT_GE(switches, 3) << "switch energy " << h.switch_energy_j << " J";
    EXPECT_GT(expected, 1.0);  // joules, not rounding
    // theta moves by at most |theta_dot| dt between the switch and the sample.
    EXPECT_NEAR(h.switch_energy_j, expected, 1e-3 * expected);
    EXPECT_EQ(h.e_switch.back(), h.switch_energy_j);
    // A constant spring never switches.
    const CellModel c = make_cell_model(kBlock, constant_anchorage(kBlock, kStrength, kBlock.alpha_rad), p);
    EXPECT_EQ(sample_history(c, {}, 0.01, 5.0).switch_energy_j, 0.0);
}
