// The envelope fixed by (I_a, D5-95, t_mid): its landmarks are the targets, its square
// integrates to I_a, and parameters out of range are refused by name.
#include <gtest/gtest.h>

#include <cmath>

#include "rocksweep/core/errors.hpp"
#include "rocksweep/records/record.hpp"
#include "rocksweep/synthetic/ground_model.hpp"
#include "rocksweep/synthetic/normal_stream.hpp"

using namespace rocksweep;
using namespace rocksweep::synthetic;

namespace {

ModelParameters example() {
    return ModelParameters{.arias_m_s = 0.5, .d595_s = 12.0, .tmid_s = 9.0, .f_mid_hz = 4.0, .f_slope_hz_s = -0.1,
                           .zeta_f = 0.3};
}

}  // namespace

TEST(GroundModel, EnvelopeLandmarksAreTheTargets) {
    for (const double ratio : {0.3, 1.0, 1.333, 2.5, 4.0}) {
        ModelParameters p = example();
        p.d595_s = ratio * p.tmid_s;
        const Modulation q = modulation(p);
        EXPECT_NEAR(q.arias_time(0.45), p.tmid_s, 1e-9 * p.tmid_s) << ratio;
        EXPECT_NEAR(q.arias_time(0.95) - q.arias_time(0.05), p.d595_s, 1e-9 * p.d595_s) << ratio;
        EXPECT_GT(q.alpha2, 0.5);
    }
}

TEST(GroundModel, SquareOfTheEnvelopeIntegratesToTheAriasIntensity) {
    const ModelParameters p = example();
    const Modulation q = modulation(p);
    // Simpson over [0, 200 s]: the envelope is below 1e-30 of its peak at the end.
    const int n = 200000;
    const double h = 200.0 / n;
    double sum = 0.0;
    for (int i = 0; i <= n; ++i) {
        const double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
        sum += w * q(i * h) * q(i * h);
    }
    const double arias = M_PI / (2.0 * standard_gravity) * sum * h / 3.0;
    EXPECT_NEAR(arias, p.arias_m_s, 1e-6 * p.arias_m_s);
    // The cumulative fraction is the same integral's running share.
    EXPECT_NEAR(q.arias_fraction(p.tmid_s), 0.45, 1e-12);
}

TEST(GroundModel, OutOfRangeParametersAreRefusedByName) {
    ModelParameters p = example();
    p.zeta_f = 1.0;
    try {
        check(p);
        FAIL() << "zeta_f = 1 accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(e.field(), "zeta");
    }
    p = example();
    p.tmid_s = 1.0;
    p.d595_s = 200.0;  // D5-95 / t_mid = 200: beyond any gamma envelope
    try {
        modulation(p);
        FAIL() << "D5-95 / t_mid = 200 accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(e.field(), "d595");
    }
}

TEST(NormalStream, StandardNormalMoments) {
    // 2e5 draws: mean 0 +- 4.5/sqrt(n), variance 1 +- 4.5 sqrt(2/n), fourth moment 3 +- 0.1.
    NormalStream s(7, 3);
    const int n = 200000;
    double m1 = 0, m2 = 0, m4 = 0;
    for (int i = 0; i < n; ++i) {
        const double z = s.next();
        m1 += z;
        m2 += z * z;
        m4 += z * z * z * z;
    }
    EXPECT_NEAR(m1 / n, 0.0, 4.5 / std::sqrt(n));
    EXPECT_NEAR(m2 / n, 1.0, 4.5 * std::sqrt(2.0 / n));
    EXPECT_NEAR(m4 / n, 3.0, 0.1);
}

TEST(NormalStream, NeighbouringIndicesAreUncorrelated) {
    NormalStream a(1, 0), b(1, 1), c(2, 0);
    const int n = 100000;
    double ab = 0, ac = 0;
    for (int i = 0; i < n; ++i) {
        const double x = a.next();
        ab += x * b.next();
        ac += x * c.next();
    }
    EXPECT_NEAR(ab / n, 0.0, 4.5 / std::sqrt(n));
    EXPECT_NEAR(ac / n, 0.0, 4.5 / std::sqrt(n));
}
