// The floor filter (motion/floor_filter.hpp) against what does not share its method: the
// oscillator in closed form on the shared records, resonance and transfer functions of long
// sines, and a chain against its stages applied to a finer sampling of the same ground.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>

#include "motion_test_support.hpp"
#include "rocksweep/core/errors.hpp"
#include "rocksweep/motion/floor_filter.hpp"
#include "test_support.hpp"

using namespace rocksweep;
using namespace rocksweep::motion;

namespace {

double peak(const std::vector<double>& y) {
    double m = 0.0;
    for (double x : y) m = std::max(m, std::abs(x));
    return m;
}

std::vector<double> sine(double w, double dt, std::size_t n) {
    std::vector<double> a(n);
    for (std::size_t i = 0; i < n; ++i) a[i] = std::sin(w * i * dt);
    return a;
}

// Floor acceleration / ground of a steady sine of angular frequency w:
// 1 + sum Gamma w^2 / (w_n^2 - w^2 + 2 i zeta_n w_n w), each stage's factor multiplied.
std::complex<double> transfer(const Floor& f, double w) {
    std::complex<double> h = 1.0;
    for (const FloorFilter& stage : f.stages) {
        std::complex<double> s = 1.0;
        for (const Mode& m : stage.modes) {
            const double wn = m.oscillator.omega();
            s += m.participation * w * w / std::complex<double>(wn * wn - w * w, 2.0 * m.oscillator.damping * wn * w);
        }
        h *= s;
    }
    return h;
}

}  // namespace

TEST(FloorFilter, OneModeMatchesTheOscillatorInClosedFormOnEverySharedRecord) {
    for (const Record& r : rocksweep::testing::shared_records()) {
        for (const auto& [period, zeta] : {std::pair{0.3, 0.05}, std::pair{1.2, 0.02}, std::pair{0.05, 0.3}, std::pair{4.0, 0.1}}) {
            SCOPED_TRACE(r.path + " T " + std::to_string(period) + " zeta " + std::to_string(zeta));
            const std::vector<double> floor = filter_motion({{Mode{{period, zeta}, 1.0}}}, r.ax_g, r.dt_s);
            rocksweep::testing::ComplexOscillator ref{2.0 * M_PI / period, zeta};
            ASSERT_EQ(floor.size(), r.ax_g.size());
            const double tol = 1e-9 * peak(floor);
            EXPECT_NEAR(floor[0], 0.0, tol);
            double worst = 0.0;
            for (std::size_t i = 1; i < r.ax_g.size(); ++i) {
                ref.step(r.ax_g[i - 1], r.ax_g[i], r.dt_s);
                worst = std::max(worst, std::abs(floor[i] - ref.absolute_acceleration()));
            }
            EXPECT_LE(worst, tol);
        }
    }
}

TEST(FloorFilter, ResonanceOfALongSineAmplifiesBySqrtOnePlusFourZetaSquaredOverTwoZeta) {
    for (double zeta : {0.02, 0.05, 0.2}) {
        SCOPED_TRACE(zeta);
        const double period = 0.5, w = 2.0 * M_PI / period, dt = period / 200.0;
        // 1/(zeta w) is the decay time of the start's transient: 40 of them leave e^-40 of it.
        const std::size_t per_period = 200, periods = static_cast<std::size_t>(std::ceil(40.0 / (2.0 * M_PI * zeta))) + 10;
        const std::vector<double> floor = filter_motion({{Mode{{period, zeta}, 1.0}}}, sine(w, dt, per_period * periods), dt);
        const double amplitude = rocksweep::testing::sine_amplitude(floor, dt, w, per_period * (periods - 5), per_period * 5);
        // The filter sees the sine as the engine reads it, linear between samples, whose
        // component at w is sinc^2(w dt / 2) of the sine (its harmonics near 2 pi k / dt are
        // filtered to ~1e-8 of it).
        const double x = w * dt / 2.0, hold = std::pow(std::sin(x) / x, 2);
        EXPECT_NEAR(amplitude, hold * std::sqrt(1.0 + 4.0 * zeta * zeta) / (2.0 * zeta), 1e-7 * amplitude);
    }
}

TEST(FloorFilter, ModesAndAChainedPlinthFollowTheirTransferFunctionForASteadySine) {
    // A building's floor by two modes (participations 1.3 and -0.35), a plinth on it.
    const Floor f = parse_floor("floor", "plinth4: 0.6 0.05 1.3; 0.2 0.05 -0.35 > 2.5 0.15 1");
    ASSERT_EQ(f.stages.size(), 2u);
    for (double wg : {2.0 * M_PI / 0.6, 2.0 * M_PI / 2.5, 7.0}) {
        SCOPED_TRACE(wg);
        // 1/(zeta w) of the slowest mode, 2.5 s / (2 pi 0.15) = 2.7 s: 60 s of sine leave e^-20.
        const double dt = 0.002;
        const std::size_t per_period = 1000, periods = static_cast<std::size_t>(std::ceil(80.0 * wg / (2.0 * M_PI)));
        const double w = 2.0 * M_PI / (per_period * dt) * std::round(wg * per_period * dt / (2.0 * M_PI));
        const std::vector<double> y = floor_motion(f, sine(w, dt, per_period * periods), dt);
        const double amplitude = rocksweep::testing::sine_amplitude(y, dt, w, per_period * (periods - 3), per_period * 3);
        // The input is linear between samples, not a sine: its error, (w dt)^2 / 12, bounds the tolerance.
        EXPECT_NEAR(amplitude, std::abs(transfer(f, w)), (w * dt) * (w * dt) / 6.0 * std::abs(transfer(f, w)));
    }
}

TEST(FloorFilter, AChainIsItsStagesAppliedToAFinerSamplingOfTheSameGround) {
    // The chain is one system discretised exactly; its stages applied one after the other treat
    // the building's output as linear between samples, an error of order dt^2 that vanishes as
    // the same ground (linear between its samples) is sampled finer.
    const Record r = rocksweep::testing::shared_records().front();
    const Floor chain = parse_floor("floor", "top: 0.4 0.05 1.2 > 1.5 0.1 1");
    const std::vector<double> exact = floor_motion(chain, r.ax_g, r.dt_s);
    double previous = INFINITY;
    for (int m : {4, 16, 64}) {
        std::vector<double> fine;
        for (std::size_t i = 0; i + 1 < r.ax_g.size(); ++i)
            for (int j = 0; j < m; ++j) fine.push_back(r.ax_g[i] + (r.ax_g[i + 1] - r.ax_g[i]) * j / m);
        fine.push_back(r.ax_g.back());
        const double h = r.dt_s / m;
        const std::vector<double> y = filter_motion(chain.stages[1], filter_motion(chain.stages[0], fine, h), h);
        double worst = 0.0;
        for (std::size_t i = 0; i < exact.size(); ++i) worst = std::max(worst, std::abs(y[i * m] - exact[i]));
        SCOPED_TRACE(m);
        EXPECT_LT(worst, previous / 10.0);  // ~1/m^2: 16x per step of 4
        previous = worst;
    }
    EXPECT_LT(previous, 1e-6 * peak(exact));
}

TEST(FloorFilter, TheGroundAndTextsRoundTrip) {
    const std::vector<double> a{0.0, 0.1, -0.2, 0.05};
    EXPECT_EQ(floor_motion(parse_floor("floor", "ground"), a, 0.01), a);
    const Floor f = parse_floor("floor", " f2 : 0.5 0.05 1.3;0.17 0.05 -0.4 > 2 0.2 1 ");
    EXPECT_EQ(f.name, "f2");
    EXPECT_EQ(to_string(f), "f2: 0.5 0.05 1.3; 0.17 0.05 -0.4 > 2 0.2 1");
    EXPECT_EQ(to_string(parse_floor("floor", to_string(f))), to_string(f));
}

TEST(FloorFilter, BadFloorsAreRefusedNamingTheOptionAndTheRange) {
    auto msg = [](const std::string& text) { return rocksweep::testing::message_of([&] { parse_floor("floor", text); }); };
    EXPECT_NE(msg("f2").find("modes after the name"), std::string::npos);
    EXPECT_NE(msg("ground: 1 0.05 1").find("'ground' is the unfiltered"), std::string::npos);
    EXPECT_NE(msg("f2: 0 0.05 1").find("periods 0.001 s <= T <= 100 s"), std::string::npos);
    EXPECT_NE(msg("f2: 1 1 1").find("damping ratios 0 <= zeta < 1"), std::string::npos);
    EXPECT_NE(msg("f2: 1 0.05 11").find("|Gamma phi| <= 10"), std::string::npos);
    EXPECT_NE(msg("f2: 1 0.05").find("three numbers per mode"), std::string::npos);
    EXPECT_NE(msg("f 2: 1 0.05 1").find("letters, digits"), std::string::npos);
    EXPECT_EQ(msg("f2: 1 0.05 x").rfind("--floor = f2: 1 0.05 x is invalid: ", 0), 0u);
}
