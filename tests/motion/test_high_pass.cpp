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
