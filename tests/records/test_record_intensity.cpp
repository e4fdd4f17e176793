// Intensity measures against closed forms: a sampled sine (PGV = 2 A / omega, second-order
// convergence in dt), a triangle whose velocity peaks between samples, a constant push (Arias
// intensity and D5-95 exact). The README peaks of the shared records: test_record.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <iterator>
#include <set>
#include <string>
#include <vector>

#include "rocksweep/records/intensity.hpp"

using namespace rocksweep;

namespace {

Record samples(std::vector<double> a_g, double dt_s) {
    Record r;
    r.ax_g = std::move(a_g);
    r.dt_s = dt_s;
    r.npts = r.ax_g.size();
    return r;
}

// One period T of A sin(2 pi t / T), sampled n times a period.
Record sine(double amplitude_g, double period_s, int n) {
    std::vector<double> a(n + 1);
    for (int i = 0; i <= n; ++i) a[i] = amplitude_g * std::sin(2.0 * M_PI * i / n);
    a[n] = 0.0;  // sin(2 pi) rounds to -2.4e-16 g
    return samples(a, period_s / n);
}

}  // namespace

TEST(Intensity, SineRecordHasTheClosedFormPeakVelocityToSecondOrder) {
    const double A = 0.3, T = 1.0, omega = 2.0 * M_PI / T, g = standard_gravity;
    const double pgv = 2.0 * A * g / omega;  // v = (A g / omega)(1 - cos omega t), peak at T/2
    const IntensityMeasures m = intensity_measures(sine(A, T, 1000));
    EXPECT_NEAR(m.pgv_m_s, pgv, 1e-5 * pgv);  // linear between samples: error ~ (omega dt)^2 / 12
    EXPECT_NEAR(m.pgv_time_s, T / 2, 1e-12);
    EXPECT_NEAR(m.residual_velocity_m_s, 0.0, 1e-12);
    EXPECT_NEAR(m.pga_g, A, 1e-12);
    EXPECT_NEAR(m.pga_time_s, T / 4, 1e-12);
    EXPECT_NEAR(m.arias_m_s, M_PI / (2 * g) * (A * g) * (A * g) * T / 2, 1e-5 * m.arias_m_s);
    EXPECT_DOUBLE_EQ(m.duration_s, T);
    EXPECT_TRUE(std::isnan(m.pga_vertical_g));
    // order of convergence: halving dt quarters the error
    const double e1 = std::abs(intensity_measures(sine(A, T, 50)).pgv_m_s - pgv);
    const double e2 = std::abs(intensity_measures(sine(A, T, 100)).pgv_m_s - pgv);
    EXPECT_NEAR(e1 / e2, 4.0, 0.1);
}

TEST(Intensity, VelocityPeakBetweenSamplesIsFound) {
    // a: 0, 1, -1, 0 g at dt = 1 s. v = 0, g/2, g/2, 0 at the samples, but a crosses 0 at
    // t = 1.5 s where v = g/2 + (1 g)(0.5 s)/2 = 0.75 g m/s.
    const IntensityMeasures m = intensity_measures(samples({0.0, 1.0, -1.0, 0.0}, 1.0));
    EXPECT_NEAR(m.pgv_m_s, 0.75 * standard_gravity, 1e-12);
    EXPECT_DOUBLE_EQ(m.pgv_time_s, 1.5);
    EXPECT_NEAR(m.residual_velocity_m_s, 0.0, 1e-12);
    EXPECT_DOUBLE_EQ(m.pga_g, 1.0);
    EXPECT_DOUBLE_EQ(m.pga_time_s, 1.0);
}

TEST(Intensity, ConstantPushGivesExactAriasAndSignificantDuration) {
    const double c = 0.2, T = 10.0, g = standard_gravity;
    Record r = samples(std::vector<double>(1001, c), T / 1000);
    r.ay_g = std::vector<double>(1001, -0.05);
    const IntensityMeasures m = intensity_measures(r);
    EXPECT_NEAR(m.arias_m_s, M_PI / (2 * g) * (c * g) * (c * g) * T, 1e-12 * m.arias_m_s);
    EXPECT_NEAR(m.significant_duration_s, 0.9 * T, 1e-9);  // from 5 % of T to 95 % of T
    EXPECT_NEAR(m.pgv_m_s, c * g * T, 1e-12 * c * g * T);  // no baseline correction: it keeps growing
    EXPECT_NEAR(m.residual_velocity_m_s, c * g * T, 1e-12 * c * g * T);
    EXPECT_DOUBLE_EQ(m.pga_vertical_g, 0.05);
}

TEST(Intensity, PgaOverGTanAlphaUsesTheBlocksGravity) {
    // tan alpha = 0.25: 0.2 g of standard gravity is 0.8 of the uplift threshold under 9.80665
    EXPECT_NEAR(pga_over_g_tan_alpha(0.2, std::atan(0.25), standard_gravity), 0.8, 1e-14);
    EXPECT_NEAR(pga_over_g_tan_alpha(0.2, std::atan(0.25), 9.81), 0.8 * standard_gravity / 9.81, 1e-14);
}

TEST(Intensity, FieldTableNamesEveryMeasureOnce) {
    // a writer loops over intensity_fields: every member of IntensityMeasures (all doubles) must
    // be there once, under its own name
    constexpr std::size_t members = sizeof(IntensityMeasures) / sizeof(double);
    ASSERT_EQ(std::size(intensity_fields), members);
    std::set<std::string> names;
    for (std::size_t i = 0; i < members; ++i) {
        names.insert(intensity_fields[i].name);
        for (std::size_t j = 0; j < i; ++j) EXPECT_FALSE(intensity_fields[i].value == intensity_fields[j].value) << i << " " << j;
    }
    EXPECT_EQ(names.size(), members);
    IntensityMeasures m;
    m.pgv_m_s = 42.0;
    EXPECT_EQ(m.*(intensity_fields[2].value), 42.0);
    EXPECT_EQ(std::string(intensity_fields[2].name), "pgv_m_s");
}
