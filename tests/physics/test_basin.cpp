// The energy argument of the basins of attraction (basin.hpp) against its closed forms and
// against the kernel integrating free rocking from a grid of initial states, cell by cell.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "rocksweep/physics/anchorage.hpp"
#include "rocksweep/physics/basin.hpp"
#include "rocksweep/physics/basin_map.hpp"

namespace rocksweep {
namespace {

Block smatteo() { return rectangular_block(0.30, 1.36, 3361.0); }

struct Case {
    std::string name;
    Anchorage anchorage;
};

std::vector<Case> paper_cases() {
    const Block b = smatteo();
    const double fu = 0.4 * b.mass_kg * b.gravity, a = b.alpha_rad;
    return {{"free", free_anchorage()},
            {"constant_1", constant_anchorage(b, fu, a)},
            {"constant_0.5", constant_anchorage(b, fu, a / 2)},
            {"constant_0.333", constant_anchorage(b, fu, a / 3)},
            {"constant_0.25", constant_anchorage(b, fu, a / 4)},
            {"adaptive_0.5", adaptive_anchorage(b, fu, a, 0.5)},
            {"adaptive_0.1", adaptive_anchorage(b, fu, a, 0.1)}};
}

CellModel free_cell(const Anchorage& a) { return free_rocking_cell(smatteo(), a, Equations::nonlinear, 1e-3); }

// Free block: the no-impact boundary is the separatrix through (alpha, 0),
// theta_dot^2 / 2 = p^2 (1 - cos(alpha - theta)); after one impact it takes 1/e^2 of the barrier.
TEST(BasinBoundary, FreeBlockClosedForm) {
    const CellModel m = free_cell(free_anchorage());
    const BasinEnergy en(m);
    const double p = m.p(), a = m.alpha;
    for (double r : {0.0, 0.3, 0.7, 0.99}) {
        const double th = r * a;
        const BasinBoundary b = en.boundary(th);
        EXPECT_NEAR(b.no_impact, p * std::sqrt(2.0 * (1.0 - std::cos(a - th))), 1e-12 * p) << r;
        const double need = (1.0 - std::cos(a)) / (m.e * m.e) - (std::cos(a - th) - std::cos(a));
        EXPECT_NEAR(b.impact, -p * std::sqrt(2.0 * need), 1e-12 * p) << r;
        if (r == 0.0) continue;  // theta = 0 belongs to both sides
        const BasinBoundary mirror = en.boundary(-th);
        EXPECT_EQ(mirror.no_impact, -b.no_impact);
        EXPECT_EQ(mirror.impact, -b.impact);
    }
    // Past alpha the separatrix runs below the axis: moving inward slower than it, the block falls back.
    const double th = 1.3 * a;
    EXPECT_NEAR(en.boundary(th).no_impact, -p * std::sqrt(2.0 * (1.0 - std::cos(th - a))), 1e-12 * p);
}

// A spring that breaks before alpha (theta_f = alpha/2) takes its energy 2 kappa (1 - cos(theta_f/2))
// with it: the barrier from rest is gravity's plus that, not the potential at alpha of an
// unbroken spring (the misprinted Eq. 19).
TEST(BasinBoundary, SpringBrokenBeforeAlphaAddsOnlyItsStoredEnergy) {
    const Block b = smatteo();
    const double tf = b.alpha_rad / 2;
    const CellModel m = free_cell(constant_anchorage(b, 0.4 * b.mass_kg * b.gravity, tf));
    const BasinEnergy en(m);
    const double vg = m.p2 * (1.0 - std::cos(m.alpha)), vs = 2.0 * m.kappa_max * (1.0 - std::cos(tf / 2));
    EXPECT_NEAR(en.boundary(0.0).no_impact, std::sqrt(2.0 * (vg + vs)), 1e-9 * m.p());
    // Just past theta_f the spring is gone: the free block's separatrix.
    const double th = 1.01 * tf;
    EXPECT_NEAR(en.boundary(th).no_impact, m.p() * std::sqrt(2.0 * (1.0 - std::cos(m.alpha - th))), 1e-9 * m.p());
}

// The curves bound what the swing-by-swing argument predicts: 1 % of p beyond the no-impact
// boundary the block falls without an impact, 1 % short of it it does not; beyond the one-impact
// boundary it falls after an impact.
TEST(BasinBoundary, CurvesSeparateThePredictedOutcomes) {
    for (const Case& c : paper_cases()) {
        const CellModel m = free_cell(c.anchorage);
        const BasinEnergy en(m);
        const double d = 0.01 * m.p();
        for (double r : {0.1, 0.2, 0.3, 0.6, 0.9, 1.2, 1.45}) {
            const double th = r * m.alpha;
            const BasinBoundary b = en.boundary(th);
            EXPECT_EQ(en.outcome(th, b.no_impact + d), Outcome::overturned_no_impact) << c.name << " " << r;
            EXPECT_NE(en.outcome(th, b.no_impact - d), Outcome::overturned_no_impact) << c.name << " " << r;
            EXPECT_EQ(en.outcome(th, b.impact - d), Outcome::overturned_impact) << c.name << " " << r;
            EXPECT_EQ(en.outcome(-th, -b.impact + d), Outcome::overturned_impact) << c.name << " " << r;
        }
    }
}

TEST(BasinEnergy, MirrorSymmetric) {
    for (const Case& c : paper_cases()) {
        const CellModel m = free_cell(c.anchorage);
        const BasinEnergy en(m);
        for (double r : {-1.4, -0.8, -0.2, 0.0, 0.4, 1.1})
            for (double q : {-0.4, -0.1, 0.0, 0.05, 0.3}) {
                const double th = r * m.alpha, thd = q * m.p();
                EXPECT_EQ(en.outcome(th, thd), en.outcome(-th, -thd)) << c.name << " " << r << " " << q;
            }
    }
}

// A lane started from (0, theta_dot0) swings out to the angle where the potential takes all of its
// kinetic energy: the integrator's max rotation against the energy's turning point.
TEST(BasinMap, LaneStartsFromTheGivenState) {
    const CellModel m = free_cell(free_anchorage());
    const SwingPotential v(m, 0.0);
    CellModel c = m;
    c.theta_dot0 = -0.15 * m.p();
    IntegratorSettings s;
    s.t_end_s = 1.3 / m.p();  // past the turning point (p t = 0.85), before the block is back
    const CellResult r = integrate_cell(c, s);
    const double peak = v.first_reach(0.0, M_PI / 2, 0.5 * c.theta_dot0 * c.theta_dot0);
    EXPECT_NEAR(r.max_rotation, peak / m.alpha, 1e-6);  // the default 48 steps per period
    EXPECT_EQ(r.outcome, Outcome::safe);
    EXPECT_EQ(r.impacts_total, 0);
}

// Exactly on gravity's peak and at rest the block never moves: both say so (not converged).
TEST(BasinMap, BalancedOnTheCornerNeverDecides) {
    CellModel c = free_cell(free_anchorage());
    c.theta0 = c.alpha;
    IntegratorSettings s;
    s.max_steps = 1000;
    EXPECT_EQ(integrate_cell(c, s).outcome, Outcome::not_converged);
    EXPECT_EQ(BasinEnergy(c).outcome(c.alpha, 0.0), Outcome::not_converged);
    EXPECT_EQ(BasinEnergy(c).outcome(c.alpha, 1e-4 * c.p()), Outcome::overturned_no_impact);
    EXPECT_EQ(BasinEnergy(c).outcome(c.alpha, -1e-4 * c.p()), Outcome::safe);
}

TEST(BasinMap, StateBeyondTheFractureAngleHasLostItsSpring) {
    const Block b = smatteo();
    CellModel c = free_cell(constant_anchorage(b, 0.4 * b.mass_kg * b.gravity, b.alpha_rad / 4));
    c.theta0 = -0.5 * b.alpha_rad;
    c.theta_dot0 = 1e-3 * c.p();  // inward: no further stretching
    IntegratorSettings s;
    s.t_end_s = 1e-3;
    EXPECT_EQ(integrate_cell(c, s).broken, broken_right);
}

// The simulated map against the energy argument on a 61 x 61 grid per anchorage of the paper:
// every cell farther than 1 % of each axis's span from a boundary agrees; the few near one may not.
TEST(BasinMap, SimulationConfirmsTheEnergyBoundaryCellByCell) {
    BasinGrid g;
    g.theta_ratio = {-1.5, 1.5, 61};
    g.theta_dot_ratio = {-0.45, 0.45, 61};
    for (const Case& c : paper_cases()) {
        const CellModel m = free_cell(c.anchorage);
        const BasinEnergy en(m);
        const std::vector<std::uint8_t> sim = simulate_basin(m, g, IntegratorSettings{});
        const std::vector<std::uint8_t> pred = predict_basin(en, m, g);
        const BasinComparison cmp = compare_basin(en, m, g, sim, pred, 0.01);
        EXPECT_EQ(cmp.clear_disagree, 0u) << c.name;
        EXPECT_GT(cmp.clear, 0.9 * cmp.cells) << c.name;
        std::printf("%-16s rest %.4f (predicted %.4f)  clear %zu, disagree %zu; near %zu, disagree %zu\n", c.name.c_str(),
                    rest_fraction(sim), rest_fraction(pred), cmp.clear, cmp.clear_disagree, cmp.near, cmp.near_disagree);
    }
}

// A K_max spring that breaks only at 2 alpha lets an outward swing turn where the K_min potential
// already falls: the law's switch to K_min there throws the block over. The energy argument
// follows it; so does the kernel integrating to the end (energy_stop off: the kernel's own
// energy decision, energy.hpp's free_fate, does not yet see this case and calls such blocks safe).
TEST(BasinMap, AdaptiveSwitchBeyondTheSoftPotentialsPeak) {
    const Block b = smatteo();
    const CellModel m = free_cell(adaptive_anchorage(b, 0.4 * b.mass_kg * b.gravity, 2 * b.alpha_rad, 0.1));
    const BasinEnergy en(m);
    BasinGrid g;
    g.theta_ratio = {-1.5, 1.5, 41};
    g.theta_dot_ratio = {-0.45, 0.45, 41};
    IntegratorSettings s;
    s.energy_stop = false;
    const std::vector<std::uint8_t> sim = simulate_basin(m, g, s), pred = predict_basin(en, m, g);
    const BasinComparison cmp = compare_basin(en, m, g, sim, pred, 0.01);
    EXPECT_EQ(cmp.clear_disagree, 0u);
    // From (0, 0.268 p) the block turns below K_max's barrier (0.277 p from theta = 0) but past
    // K_min's peak (reached from 0.259 p): the switch there throws it over.
    EXPECT_EQ(en.outcome(0.0, 0.268 * m.p()), Outcome::overturned_no_impact);
    EXPECT_GT(en.boundary(0.0).no_impact, 0.268 * m.p());
    EXPECT_EQ(en.outcome(0.0, 0.25 * m.p()), Outcome::safe);
}

}  // namespace
}  // namespace rocksweep
