// The base reactions and the friction a pure rocking motion needs (physics.md §6, observers.hpp:
// FrictionDemand): at rest, while rocking against the motion of the centre of mass, with an
// inclined spring, and at a spring that breaks at theta_f = alpha.
#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "rocksweep/physics/anchorage.hpp"
#include "rocksweep/physics/history.hpp"
#include "rocksweep/physics/integrator.hpp"
#include "smatteo_case.hpp"

using namespace rocksweep;

namespace {

const Block& kBlock = rocksweep::testing::kSMatteo;
const double kStrength = rocksweep::testing::kSMatteoStrength;
Pulse sine(double omega_ratio, double amplitude_ratio) { return rocksweep::testing::smatteo_sine(omega_ratio, amplitude_ratio); }

}  // namespace

TEST(Reactions, AtRestTheFrictionNeededIsTheGroundAcceleration) {
    // Below the uplift threshold the block moves with the ground: mu = max |ax| / g.
    const Pulse p = sine(3.0, 0.9);
    const CellResult r = integrate_cell(make_cell_model(kBlock, free_anchorage(), p), {});
    EXPECT_EQ(r.max_rotation, 0.0);
    EXPECT_DOUBLE_EQ(r.mu_required, p.ax_g);
    EXPECT_EQ(r.pivot_uplift, 0);
}

TEST(Reactions, RockingNeedsAtLeastTanAlphaAndMatchesTheMotionOfTheCentreOfMass) {
    const Pulse p = sine(6.0, 4.0);
    const CellModel m = make_cell_model(kBlock, free_anchorage(), p);
    const History h = sample_history(m, {}, 1e-4, 4.0);
    const CellResult& r = h.result;
    EXPECT_GE(r.mu_required, std::tan(kBlock.alpha_rad) * (1 - 1e-12));
    EXPECT_EQ(r.pivot_uplift, 0);
    // f_x / (m g) and f_y / (m g) from second differences of the sampled centre of mass.
    const double R = kBlock.radius_m, b = kBlock.half_width_m(), g = kBlock.gravity, dt = 1e-4;
    auto cm = [&](std::size_t i, double& x, double& y) {
        const double s = h.theta[i] > 0 ? 1.0 : -1.0, phi = std::abs(h.theta[i]);
        x = s * b - s * R * std::sin(kBlock.alpha_rad - phi);
        y = R * std::cos(kBlock.alpha_rad - phi);
    };
    double worst = 0.0;
    std::size_t used = 0;
    for (std::size_t i = 1; i + 1 < h.t.size(); ++i) {
        // only where the pivot stays the same across the stencil
        if (!(h.theta[i - 1] * h.theta[i] > 0 && h.theta[i] * h.theta[i + 1] > 0)) continue;
        double x0, y0, x1, y1, x2, y2;
        cm(i - 1, x0, y0);
        cm(i, x1, y1);
        cm(i + 1, x2, y2);
        const double ax = h.ground_acc[i] / g, ay = 0.0;
        const double fx = ax + (x0 - 2 * x1 + x2) / (dt * dt) / g;
        const double fy = 1.0 + ay + (y0 - 2 * y1 + y2) / (dt * dt) / g;
        worst = std::max(worst, std::abs(fx) / fy);
        ++used;
    }
    EXPECT_GT(used, 10000u);
    EXPECT_LE(worst, r.mu_required * (1 + 2e-3));  // sampled demand never exceeds the reported one
    EXPECT_GE(worst, r.mu_required * (1 - 2e-2));  // and comes close to it
}

TEST(Reactions, InclinedSpringForceMatchesAVectorEvaluation) {
    // Issue 7, item 5. Independently of base_reactions: the spring's line from the coordinates
    // of the lifted corner and of its anchor, its magnitude from the Eq. 8 moment about the
    // pivot, the centre of mass's acceleration from rigid-body kinematics (a = phi'' x r -
    // phi'^2 r, rotation -s phi about the pivot); f = m (a_ground + a_cm) - spring - weight.
    const CellModel m = make_cell_model(kBlock, constant_anchorage(kBlock, kStrength, kBlock.alpha_rad / 4), sine(4.0, 2.7));
    const double b = kBlock.half_width_m(), h = kBlock.half_height_m(), mg = kBlock.mass_kg * kBlock.gravity;
    double worst_spring_fx = 0.0;
    for (int side : {1, -1}) {
        for (double phi : {0.01, 0.05, 0.1, 0.2}) {
            for (double thd : {0.0, 0.3, -0.4}) {
                const double ax = 0.12, ay = 0.05, theta = side * phi, k = m.k_max_n_m;
                const BaseReactions f = base_reactions(m, side, m.kappa_max, k, ax, ay, theta, thd);
                // Body points relative to the pivot (x = s b), rotated by beta = -s phi.
                const double beta = -side * phi, c = std::cos(beta), sn = std::sin(beta);
                auto rot = [&](double x, double y) { return std::pair{x * c - y * sn, x * sn + y * c}; };
                const auto [rx, ry] = rot(-side * b, h);               // centre of mass
                const auto [cx, cy] = rot(-side * 2.0 * b, 0.0);       // lifted corner
                const double dx = -side * 2.0 * b - cx, dy = -cy;      // corner -> anchor (x = -s b)
                const double len = std::hypot(dx, dy), ux = dx / len, uy = dy / len;
                // |moment of a unit force along u about the pivot| = |r_corner x u|
                const double arm = std::abs(cx * uy - cy * ux);
                const double F = 8.0 * b * b * k * std::sin(0.5 * phi) / arm;
                // Angular acceleration of the body: beta'' = -s phi'' = -theta''.
                const double thdd = rocking_acceleration(m, side, m.kappa_max, ax, ay, theta);
                const double bdd = -thdd, bd = -thd;
                const double acx = -bdd * ry - bd * bd * rx, acy = bdd * rx - bd * bd * ry;
                const double g = kBlock.gravity;
                const double fx = (kBlock.mass_kg * (ax * g + acx) - F * ux) / mg;
                const double fy = (kBlock.mass_kg * (ay * g + acy) - F * uy + mg) / mg;
                EXPECT_NEAR(f.fx, fx, 1e-12) << side << " " << phi << " " << thd;
                EXPECT_NEAR(f.fy, fy, 1e-12) << side << " " << phi << " " << thd;
                worst_spring_fx = std::max(worst_spring_fx, std::abs(F * ux) / mg);
            }
        }
    }
    EXPECT_GT(worst_spring_fx, 1e-3);  // the horizontal pull matters at these angles
}

TEST(Reactions, TheDemandAtASpringBreakingAtAlphaCounts) {
    // A spring breaking at theta_f = alpha under a strong pulse: the demand peaks just before
    // the break, at |theta| = alpha. The located fracture lands a rounding past alpha, where
    // the block was once taken as beyond its stability limit and the peak was dropped at 48
    // steps per period (4.59 instead of 34.92) depending on the last bits of the location.
    const CellModel m = make_cell_model(kBlock, constant_anchorage(kBlock, kStrength, kBlock.alpha_rad), sine(4.6, 22.0));
    IntegratorSettings tight;
    tight.steps_per_period = 4096;
    const double reference = integrate_cell(m, tight).mu_required;
    EXPECT_NEAR(reference, 34.92, 0.01);
    for (const double n : {48.0, 96.0, 384.0}) {
        IntegratorSettings s;
        s.steps_per_period = n;
        EXPECT_NEAR(integrate_cell(m, s).mu_required, reference, 1e-4 * reference) << n << " steps per period";
    }
}
