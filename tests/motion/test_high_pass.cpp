// The high-pass oscillator (motion/high_pass.hpp): the linear-acceleration method to rounding,
// and a motion whose velocity and displacement, read linear between its samples, come to rest.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "read_linear.hpp"
#include "rocksweep/motion/high_pass.hpp"

using namespace rocksweep;
using namespace rocksweep::motion;

namespace {

constexpr double dt = 0.02, fc = 0.2;

// A one-second burst, two cycles of a 2 Hz sine plus the positive half of a 1 Hz one (which
// leaves a net velocity), then 60 s of rest.
std::vector<double> burst() {
    std::vector<double> x(3051, 0.0);
    for (std::size_t k = 1; k <= 50; ++k)
        x[k] = std::sin(4.0 * M_PI * k * dt) + std::max(0.0, std::sin(2.0 * M_PI * k * dt));
    return x;
}

}  // namespace

// Newmark's linear-acceleration method (beta = 1/6, gamma = 1/2) written out: the same samples
// to 1e-14 of the peak.
TEST(HighPass, IsTheLinearAccelerationMethod) {
    std::vector<double> x = burst(), ref = x;
    HighPass(fc, dt).apply(x);
    const double w = 2.0 * M_PI * fc, denom = 1.0 + w * dt + w * w * dt * dt / 6.0;
    double u = 0.0, v = 0.0, a = 0.0, peak = 0.0;
    for (std::size_t k = 1; k < ref.size(); ++k) {
        const double a_new = (ref[k] - 2.0 * w * (v + 0.5 * dt * a) - w * w * (u + dt * v + dt * dt / 3.0 * a)) / denom;
        u += dt * v + dt * dt / 6.0 * (2.0 * a + a_new);
        v += 0.5 * dt * (a + a_new);
        a = a_new;
        ref[k] = a;
        peak = std::max(peak, std::abs(a));
    }
    for (std::size_t k = 0; k < x.size(); ++k) ASSERT_NEAR(x[k], ref[k], 1e-14 * peak) << k;
}

// The burst leaves the ground moving (residual 100 % of the peak velocity); filtered, the motion
// read linear ends at rest to 1e-9 of its peaks: its velocity and displacement are the
// oscillator's, which decay as (1 + w t) exp(-w t) over the 60 s of rest.
TEST(HighPass, TheMotionReadLinearComesToRest) {
    std::vector<double> x = burst();
    EXPECT_GT(rocksweep::testing::residual_over_peak(x, dt), 0.5);
    HighPass(fc, dt).apply(x);
    EXPECT_LT(rocksweep::testing::residual_over_peak(x, dt), 1e-9);
}

TEST(HighPass, RefusesACornerOrStepThatIsNotPositive) {
    EXPECT_THROW(HighPass(0.0, dt), std::invalid_argument);
    EXPECT_THROW(HighPass(fc, 0.0), std::invalid_argument);
    EXPECT_THROW(HighPass(fc, NAN), std::invalid_argument);
}

// The ring-down's energy in closed form: the burst cut after its second (the input held at 0
// from there) against the same burst followed explicitly through its 60 s of rest (w t = 75,
// far past the ring-down): the same sum of squares to 1e-12, and the same samples before the cut.
TEST(HighPass, RingDownEnergyIsTheExplicitSum) {
    const HighPass hp(fc, dt);
    std::vector<double> whole = burst();
    std::vector<double> cut(whole.begin(), whole.begin() + 51);
    hp.apply(whole);
    const double tail = hp.apply_and_ring_down(cut);
    double explicit_tail = 0.0;
    for (std::size_t k = 51; k < whole.size(); ++k) explicit_tail += whole[k] * whole[k];
    EXPECT_NEAR(tail, explicit_tail, 1e-12 * explicit_tail);
    EXPECT_GT(tail, 0.0);
    for (std::size_t k = 0; k < cut.size(); ++k) EXPECT_EQ(cut[k], whole[k]) << k;
    // Cut short after 20 and 300 samples of ring-down: the first samples of the explicit sum.
    for (const std::size_t samples : {std::size_t{20}, std::size_t{300}}) {
        const std::vector<double> input = burst();
        std::vector<double> again(input.begin(), input.begin() + 51);
        const double part = hp.apply_and_ring_down(again, samples);
        double explicit_part = 0.0;
        for (std::size_t k = 51; k < 51 + samples; ++k) explicit_part += whole[k] * whole[k];
        EXPECT_NEAR(part, explicit_part, 1e-12 * explicit_tail) << samples;
    }
}
