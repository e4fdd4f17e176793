// The excitation seam and the pulse library on it (docs/physics.md, "Pulse families"): each
// family's definition, scalar = W-lane bitwise, fourth order through impacts, and the closed
// forms where the linearised response has one.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "rocksweep/physics/anchorage.hpp"
#include "rocksweep/physics/integrator.hpp"
#include "rocksweep/physics/pulse_library.hpp"
#include "rocksweep/grid/sweep.hpp"

using namespace rocksweep;

namespace {

const Block kBlock = rectangular_block(0.30, 1.36, 3361.0);
const double kStrength = 0.4 * 3361.0 * 9.81;

const PulseFamily kFamilies[] = {PulseFamily::one_sine, PulseFamily::n_sine,   PulseFamily::cycloidal_a,
                                 PulseFamily::cycloidal_b, PulseFamily::cycloidal_c, PulseFamily::rectangle,
                                 PulseFamily::ricker};

Pulse pulse(PulseFamily f, double omega_ratio, double amplitude_ratio, int cycles = 2) {
    PulseShape s;
    s.family = f;
    s.cycles = cycles;
    return make_pulse(s, amplitude_ratio * kBlock.alpha_rad, omega_ratio * kBlock.p());
}

Anchorage anchorage(int kind) {
    switch (kind) {
        case 1: return constant_anchorage(kBlock, kStrength, kBlock.alpha_rad / 2);
        case 2: return adaptive_anchorage(kBlock, kStrength, kBlock.alpha_rad, 0.1);
        default: return free_anchorage();
    }
}

/// Ground velocity and displacement at the window's end [g s, g s^2], by composite Simpson on
/// 200 000 intervals (error ~1e-20 relative for these smooth pulses).
void ground_at_end(const Pulse& p, double& v, double& d) {
    const int n = 200000;
    const double T = p.end_time(), h = T / n;
    v = d = 0.0;
    // v(T) = int a, d(T) = int (T - t) a dt
    for (int i = 0; i <= n; ++i) {
        const double t = i * h, w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
        v += w * p.ax(t);
        d += w * (T - t) * p.ax(t);
    }
    v *= h / 3.0;
    d *= h / 3.0;
}

}  // namespace

TEST(PulseLibrary, CycloidalPhaseIsTheRootInTheOpenQuarterPeriod) {
    // docs/physics.md: phi = 0.218979522476 rad (C1), 0.128729797037 rad (C2).
    EXPECT_NEAR(cycloidal_phase(1), 0.218979522476, 1e-12);
    EXPECT_NEAR(cycloidal_phase(2), 0.128729797037, 1e-12);
    for (int n : {1, 2, 3, 7}) {
        const double phi = cycloidal_phase(n);
        EXPECT_GT(phi, 0.0);
        EXPECT_LT(phi, M_PI / 2);
        EXPECT_NEAR(std::cos(phi), std::sin(phi) * ((2 * n + 1) * M_PI / 2 - phi), 1e-15);
    }
}

TEST(PulseLibrary, CycloidalCReturnsTheGroundToRestAndBStartsWithAJump) {
    for (int n : {1, 2, 3}) {
        const Pulse p = pulse(PulseFamily::cycloidal_c, 3.0, 2.0, n);
        double v, d;
        ground_at_end(p, v, d);
        const double w = p.omega, a = p.ax_g;
        // Scales: a / w and a / w^2; a rounded phi (0.0697 pi) leaves ~1e-4 of them.
        EXPECT_LT(std::abs(v), 1e-12 * a / w) << "C" << n;
        EXPECT_LT(std::abs(d), 1e-12 * a / (w * w)) << "C" << n;
        EXPECT_NEAR(p.end_time(), ((2 * n + 1) * M_PI - 2 * cycloidal_phase(n)) / w, 1e-13 * p.end_time());
        EXPECT_NEAR(p.ax(0.0), a * std::cos(cycloidal_phase(n)), 1e-15 * a);
    }
    const Pulse b = pulse(PulseFamily::cycloidal_b, 3.0, 2.0);
    EXPECT_NEAR(b.ax(0.0), b.ax_g, 1e-15 * b.ax_g);
    EXPECT_NEAR(b.end_time(), 2 * M_PI / b.omega, 1e-15);
    const Pulse n3 = pulse(PulseFamily::n_sine, 3.0, 2.0, 3);
    EXPECT_NEAR(n3.end_time(), 3 * 2 * M_PI / n3.omega, 1e-14);
}

TEST(PulseLibrary, RickerIsTheWaveletToRoundingWithTinyEndsZerosAndPeaksWhereItSays) {
    const Pulse r = pulse(PulseFamily::ricker, 2.0, 3.0);
    const double a = r.ax_g, T = 2 * M_PI / r.omega;
    EXPECT_NEAR(r.end_time(), 3 * T, 1e-15);
    for (int i = 0; i <= 3000; ++i) {
        const double t = 3 * T * i / 3000.0, tau = t - 1.5 * T, q = M_PI * M_PI * tau * tau / (T * T);
        EXPECT_NEAR(r.ax(t), a * (1 - 2 * q) * std::exp(-q), 1e-13 * a) << t;  // our exp: ~1e-14
    }
    EXPECT_LT(std::abs(r.ax(0.0)), 1.1e-8 * a);  // truncated below ~1e-8 a_p
    EXPECT_NEAR(r.ax(1.5 * T), a, 1e-15 * a);
    const double z = r.next_ax_zero(0.0);
    EXPECT_NEAR(r.ax(z), 0.0, 1e-14 * a);
    EXPECT_NEAR(r.ax(r.next_ax_zero(z)), 0.0, 1e-14 * a);
    EXPECT_EQ(r.next_ax_zero(r.next_ax_zero(z)), INFINITY);
    // The side lobe: -2 e^(-3/2) a at u^2 = 3/2.
    EXPECT_NEAR(r.ax(1.5 * T - std::sqrt(1.5) * T / M_PI), -2 * std::exp(-1.5) * a, 1e-13 * a);
}

TEST(PulseLibrary, RickerLiftsOnItsLeadingSideLobeAboveTheLobeThreshold) {
    // docs/physics.md §8: above a_p/(alpha g) ~ 2.28 the first uplift is on the negative side
    // lobe (theta > 0). 2.28 = tan(alpha) / alpha / (2 e^(-3/2)).
    const double lobe = std::tan(kBlock.alpha_rad) / kBlock.alpha_rad / (2 * std::exp(-1.5));
    EXPECT_NEAR(lobe, 2.28, 0.01);
    for (double ratio : {lobe * 0.99, lobe * 1.01}) {
        const CellModel m = make_cell_model(kBlock, free_anchorage(), pulse(PulseFamily::ricker, 3.0, ratio));
        IntegratorSettings s;
        s.t_end_s = m.pulse.end_time();
        s.energy_stop = false;
        int first_side = 0;
        integrate_cell(m, s, [&](const StepRecord& rec) {
            if (first_side == 0 && rec.theta1 != 0.0) first_side = rec.theta1 > 0 ? 1 : -1;
        });
        EXPECT_EQ(first_side, ratio > lobe ? 1 : -1) << ratio;
    }
}

TEST(Excitation, EveryFamilyGivesTheSameBitsAloneAndInEveryBatchWidth) {
    for (PulseFamily f : kFamilies) {
        std::vector<CellModel> cells;
        for (int kind : {0, 1, 2})
            for (double w : {1.5, 4.0, 9.0})
                for (double a : {1.3, 3.0, 8.0, 20.0}) cells.push_back(make_cell_model(kBlock, anchorage(kind), pulse(f, w, a)));
        for (Method method : {Method::events, Method::paper}) {
            IntegratorSettings s;
            s.method = method;
            std::vector<CellResult> scalar(cells.size());
            for (std::size_t i = 0; i < cells.size(); ++i) scalar[i] = integrate_cell(cells[i], s);
            for (int lanes : {4, 8, 16}) {
                std::vector<CellResult> batch(cells.size());
                integrate_cells(cells, batch, s, lanes);
                for (std::size_t i = 0; i < cells.size(); ++i)
                    ASSERT_TRUE(bitwise_equal(batch[i], scalar[i])) << to_string(f) << " cell " << i << " lanes " << lanes;
            }
        }
    }
}

TEST(Excitation, AMixedBatchOfFamiliesGivesEachLaneItsOwnBits) {
    std::vector<CellModel> cells;
    for (double a : {1.3, 3.0, 8.0})
        for (PulseFamily f : kFamilies) cells.push_back(make_cell_model(kBlock, anchorage(2), pulse(f, 4.0, a)));
    std::vector<CellResult> batch(cells.size());
    integrate_cells(cells, batch, IntegratorSettings{}, 8);
    for (std::size_t i = 0; i < cells.size(); ++i)
        ASSERT_TRUE(bitwise_equal(batch[i], integrate_cell(cells[i], IntegratorSettings{}))) << "cell " << i;
}

TEST(Excitation, EveryFamilyIsFourthOrderThroughImpacts) {
    for (PulseFamily f : kFamilies) {
        // A safe run with impacts during and after the pulse, to a fixed time (a held rectangle
        // of 2.5 alpha g overturns the block).
        const double a = f == PulseFamily::rectangle ? 1.5 : 2.5;
        const CellModel m = make_cell_model(kBlock, anchorage(2), pulse(f, 4.0, a));
        const double t_end = m.pulse.end_time() + 3.0;
        auto theta_at = [&](double steps, int* impacts) {
            IntegratorSettings s;
            s.steps_per_period = steps;
            s.t_end_s = t_end;
            s.energy_stop = false;
            double theta = NAN;
            const CellResult r = integrate_cell(m, s, [&](const StepRecord& rec) { theta = rec.theta1; });
            if (impacts) *impacts = r.impacts;
            return theta;
        };
        int impacts = 0;
        const double ref = theta_at(4096, &impacts);
        EXPECT_GE(impacts, 3) << to_string(f);
        // From 64 steps per period of the fastest time scale (errors 1e-9 to 1e-7, well above
        // rounding); the rectangle's time scale is the spring's, where 64 steps are not yet in
        // the asymptotic range (ratio 8): from 128.
        const double n = f == PulseFamily::rectangle ? 128.0 : 64.0;
        const double e1 = std::abs(theta_at(n, nullptr) - ref), e2 = std::abs(theta_at(2 * n, nullptr) - ref),
                     e3 = std::abs(theta_at(4 * n, nullptr) - ref);
        // halving the step divides the error by 2^4 = 16
        EXPECT_NEAR(e1 / e2, 16.0, 4.0) << to_string(f);
        EXPECT_NEAR(e2 / e3, 16.0, 4.0) << to_string(f);
    }
}

TEST(Excitation, RectangleInASweepOverturnsOnHousnersClosedForm) {
    // Linearised, free: a_p = A alpha g held for t_d overturns without impact iff
    // t_d > t* = ln(A / (A - 1)) / p. The sweep's rectangle lasts pi / omega_p, so the critical
    // frequency ratio is pi / (t* p) = pi / ln(A / (A - 1)).
    SweepSpec spec;
    spec.block = kBlock;
    spec.equations = Equations::linearised;
    spec.pulse_family = PulseFamily::rectangle;
    spec.scenarios = {{"free", free_anchorage(), 0.0, 1.0}};
    for (double A : {1.3, 2.0, 5.0}) {
        const double critical = M_PI / std::log(A / (A - 1.0));
        spec.amplitude_ratio = Axis{A, A, 1};
        spec.omega_ratio = Axis{critical * (1 - 1e-4), critical * (1 + 1e-4), 2};
        std::vector<CellResult> r(2);
        compute_cells(spec, IntegratorSettings{}, 0, 2, r.data());
        EXPECT_EQ(r[0].outcome, Outcome::overturned_no_impact) << A;  // lower frequency: longer pulse
        EXPECT_EQ(r[1].outcome, Outcome::safe) << A;
    }
}

TEST(Excitation, OneSineMode2MatchesTheLinearisedClosedForm) {
    // Linearised, free, one-sine a_p = A alpha g: the block lifts at sin(omega t_u) = 1 / A to
    // theta < 0; with phi = -theta, phi'' = p^2 (phi - alpha) + p^2 A alpha sin(omega t), so
    // phi = alpha + K sin(omega t) + c1 cosh(p (t - t_u)) + c2 sinh(p (t - t_u)),
    // K = -p^2 A alpha / (p^2 + omega^2), c1 = -alpha - K sin(omega t_u), c2 = -K omega cos(omega t_u) / p.
    // After the pulse phi - alpha = D+ e^(p (t - T)) + D- e^(-p (t - T)): mode 2 iff phi stays
    // above 0 on (t_u, T] and either reaches pi/2 there or D+ = (phi - alpha + phi' / p) / 2 > 0
    // at T. Cells within 1e-3 alpha of either boundary (min phi, D+), or whose phi stays below
    // 1e-2 alpha, are not judged; phi(T) is compared to 1e-5 rad (48 steps per period: up to
    // 2e-6 seen).
    const double p = kBlock.p(), alpha = kBlock.alpha_rad;
    int judged = 0, mode2 = 0;
    for (double wr = 1.0; wr <= 10.0; wr += 0.75)
        for (double A = 1.1; A <= 20.0; A *= 1.35) {
            const double w = wr * p, T = 2 * M_PI / w, tu = std::asin(1.0 / A) / w;
            const double K = -p * p * A * alpha / (p * p + w * w);
            const double c1 = -alpha - K * std::sin(w * tu), c2 = -K * w * std::cos(w * tu) / p;
            auto phi = [&](double t) { return alpha + K * std::sin(w * t) + c1 * std::cosh(p * (t - tu)) + c2 * std::sinh(p * (t - tu)); };
            auto phi_dot = [&](double t) {
                return K * w * std::cos(w * t) + p * (c1 * std::sinh(p * (t - tu)) + c2 * std::cosh(p * (t - tu)));
            };
            // The lowest phi once it has risen past 1e-2 alpha: a return to 0 is an impact.
            double lowest = INFINITY, highest = 0.0;
            for (int i = 1; i <= 4000; ++i) {
                const double f = phi(tu + (T - tu) * i / 4000.0);
                if (highest > 1e-2 * alpha) lowest = std::min(lowest, f);
                highest = std::max(highest, f);
            }
            const bool falls = highest >= M_PI / 2;
            const double d_plus = 0.5 * (phi(T) - alpha + phi_dot(T) / p);
            if (highest <= 1e-2 * alpha) continue;  // barely lifts: not judged
            if (!falls && (std::abs(lowest) < 1e-3 * alpha || std::abs(d_plus) < 1e-3 * alpha)) continue;
            const bool expect2 = lowest > 0.0 && (falls || d_plus > 0.0);
            const CellModel m = make_cell_model(kBlock, free_anchorage(), pulse(PulseFamily::one_sine, wr, A), Equations::linearised);
            const CellResult r = integrate_cell(m, IntegratorSettings{});
            EXPECT_EQ(r.outcome == Outcome::overturned_no_impact, expect2) << "omega_p/p " << wr << " A " << A;
            ++judged;
            mode2 += expect2;
            if (lowest > 0.0 && !falls) {
                IntegratorSettings s;
                s.t_end_s = T;
                s.energy_stop = false;
                double theta_T = NAN;
                integrate_cell(m, s, [&](const StepRecord& rec) { theta_T = rec.theta1; });
                EXPECT_NEAR(-theta_T, phi(T), 1e-5) << "omega_p/p " << wr << " A " << A;
            }
        }
    EXPECT_GT(judged, 100);
    EXPECT_GT(mode2, 10);
    EXPECT_LT(mode2, judged - 10);
}
