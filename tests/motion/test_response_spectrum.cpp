// Sa(T, zeta) (motion/response_spectrum.hpp) of the shared records against a brute-force peer:
// the same ground (linear between samples) sampled 64 times finer, an oscillator stepped in
// closed form by complex arithmetic, the largest |u| over the fine samples.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "motion_test_support.hpp"
#include "rocksweep/motion/response_spectrum.hpp"

using namespace rocksweep;
using namespace rocksweep::motion;

namespace {

// w^2 max |u| over t = i dt / m, and the bound of what it can miss: between fine samples h
// apart, |u| falls below its peak by at most h^2 max|u''| / 8 (a parabola through the peak).
struct Brute {
    double sa, missed;  // both in Sa's unit
};
Brute brute_force(const Record& r, double period, double zeta, int m) {
    rocksweep::testing::ComplexOscillator o{2.0 * M_PI / period, zeta};
    const double h = r.dt_s / m;
    double peak = 0.0, curvature = 0.0;
    for (std::size_t i = 0; i + 1 < r.ax_g.size(); ++i) {
        const double a0 = r.ax_g[i], slope = (r.ax_g[i + 1] - a0) / r.dt_s;
        const rocksweep::testing::ComplexOscillator::Segment s = o.segment(a0, slope);
        for (int j = 1; j <= m; ++j) {
            const double t = j * h, u = s.u(t);
            peak = std::max(peak, std::abs(u));
            curvature = std::max(curvature, std::abs(a0 + slope * t + 2.0 * zeta * o.w * s.v(t) + o.w * o.w * u));
        }
        o.step(r.ax_g[i], r.ax_g[i + 1], r.dt_s);
    }
    return {o.w * o.w * peak, o.w * o.w * h * h * curvature / 8.0};
}

}  // namespace

TEST(ResponseSpectrum, SaOfEverySharedRecordMatchesABruteForcePeerWithinWhatItsSamplingCanMiss) {
    for (const Record& r : rocksweep::testing::shared_records()) {
        for (const auto& [period, zeta] : {std::pair{0.02, 0.05}, std::pair{0.1, 0.05}, std::pair{0.5, 0.02}, std::pair{1.0, 0.05},
                                           std::pair{3.0, 0.2}}) {
            SCOPED_TRACE(r.path + " T " + std::to_string(period) + " zeta " + std::to_string(zeta));
            const double sa = spectral_acceleration(r.ax_g, r.dt_s, Oscillator{period, zeta});
            const Brute b = brute_force(r, period, zeta, 64);
            // Sa is the exact peak: never below the peer's, above it by no more than the peer can miss.
            // (1e-9: the two step thousands of samples with different rounding)
            EXPECT_GE(sa, b.sa * (1.0 - 1e-9));
            EXPECT_LE(sa, b.sa * (1.0 + 1e-9) + b.missed);
            EXPECT_LT(b.missed, 1e-3 * sa);  // the peer is sharp enough to mean something
        }
    }
}

TEST(ResponseSpectrum, AVeryStiffOscillatorFollowsTheGroundSoSaIsThePga) {
    // T = 1 ms: w^2 u = -a but for the damping's lag, 2 zeta a' / w, and the ring each kink of
    // the piecewise-linear ground starts, of acceleration |slope change| / w at most.
    for (const Record& r : rocksweep::testing::shared_records()) {
        SCOPED_TRACE(r.path);
        double pga = 0.0, slope = 0.0, kink = 0.0;
        for (std::size_t i = 0; i + 1 < r.ax_g.size(); ++i) {
            pga = std::max(pga, std::abs(r.ax_g[i]));
            const double s = (r.ax_g[i + 1] - r.ax_g[i]) / r.dt_s;
            kink = std::max(kink, std::abs(s - (i ? (r.ax_g[i] - r.ax_g[i - 1]) / r.dt_s : 0.0)));
            slope = std::max(slope, std::abs(s));
        }
        const double w = 2.0 * M_PI / 1e-3, bound = (2.0 * 0.05 * slope + kink) / w;
        EXPECT_LT(bound, 0.02 * pga);  // the test means something: Sa within 2 % of the PGA
        EXPECT_NEAR(spectral_acceleration(r.ax_g, r.dt_s, Oscillator{1e-3, 0.05}), pga, bound);
    }
}

TEST(ResponseSpectrum, TheSpectrumIsSaAtEachPeriodAndItsPeriodsSpanTwoHundredthsToFiveSeconds) {
    const Record r = rocksweep::testing::shared_records().front();
    const std::vector<double> t = floor_spectrum_periods();
    ASSERT_EQ(t.size(), 60u);
    EXPECT_DOUBLE_EQ(t.front(), 0.02);
    EXPECT_NEAR(t.back(), 5.0, 1e-12);
    const std::vector<double> sa = response_spectrum(r.ax_g, r.dt_s, t, 0.05);
    for (std::size_t i : {0u, 30u, 59u}) EXPECT_EQ(sa[i], spectral_acceleration(r.ax_g, r.dt_s, Oscillator{t[i], 0.05}));
    EXPECT_THROW(spectral_acceleration(r.ax_g, r.dt_s, Oscillator{1.0, 1.0}), std::invalid_argument);
}
