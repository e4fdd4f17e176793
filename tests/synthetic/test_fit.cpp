// Fits to the shared records: the fitted envelope reproduces each record's I_a, D5-95 and t_mid,
// and motions of the fitted model do so on average; the fit recovers known parameters from
// motions of the model itself.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "rocksweep/core/errors.hpp"
#include "rocksweep/records/record.hpp"
#include "rocksweep/synthetic/fit.hpp"
#include "rocksweep/synthetic/generator.hpp"

using namespace rocksweep;
using namespace rocksweep::synthetic;

TEST(Fit, RecoversTheParametersOfTheModelsOwnMotion) {
    const ModelParameters p{.arias_m_s = 0.8, .d595_s = 14.0, .tmid_s = 10.0, .f_mid_hz = 3.0, .f_slope_hz_s = -0.08, .zeta_f = 0.25};
    const Generator gen(p, 0.01, default_duration_s(p));
    std::vector<double> a;
    gen.generate(99, 0, a);
    const FitResult fit = fit_model(a, 0.01);
    // One motion is one sample: its landmarks scatter by ~10 %, its crossing line by a few %.
    EXPECT_NEAR(fit.params.arias_m_s, p.arias_m_s, 0.2 * p.arias_m_s);
    EXPECT_NEAR(fit.params.d595_s, p.d595_s, 0.15 * p.d595_s);
    EXPECT_NEAR(fit.params.tmid_s, p.tmid_s, 0.1 * p.tmid_s);
    EXPECT_NEAR(fit.params.f_mid_hz, p.f_mid_hz, 0.1 * p.f_mid_hz);
    EXPECT_NEAR(fit.params.f_slope_hz_s, p.f_slope_hz_s, 0.04);
    EXPECT_NEAR(fit.params.zeta_f, p.zeta_f, 0.1);
}

// The envelope of the fitted parameters has the record's own landmarks, and the fit's damping
// gives the record's count of positive minima and negative maxima (to the bisection's step).
TEST(Fit, EnvelopeOfTheFitHasTheRecordsLandmarks) {
    RecordSource loma;
    loma.path = ROCKSWEEP_RECORDS_DIR "/loma_prieta_1989.dat";
    loma.units = "m/s^2";
    RecordSource newhall;
    newhall.path = ROCKSWEEP_RECORDS_DIR "/RSN1044_northridge_1994_newhall_rot.AT2";
    newhall.format = RecordFormat::at2;
    for (const RecordSource& source : {loma, newhall}) {
        const Record r = read_record(source);
        const FitResult fit = fit_model(r.ax_g, r.dt_s);
        const Modulation q = modulation(fit.params);
        const AriasTimes& m = fit.record;
        EXPECT_NEAR(q.arias_time(0.45), m.t45_s, 1e-9 * m.t45_s) << source.path;
        EXPECT_NEAR(q.arias_time(0.95) - q.arias_time(0.05), m.d595_s(), 1e-9 * m.d595_s()) << source.path;
        EXPECT_DOUBLE_EQ(fit.params.arias_m_s, m.arias_m_s) << source.path;
        EXPECT_NEAR(fit.simulated_extrema, static_cast<double>(fit.record_extrema), 0.05 * fit.record_extrema + 1.0)
            << source.path;
        EXPECT_GT(fit.params.zeta_f, 0.02);
        EXPECT_LT(fit.params.zeta_f, 0.95);
    }
}

// A record with a long quiet lead-in (Loma Prieta after 60 s of zeros, as a triggered record
// with pre-event memory or a record cut late): the same fit, shifted. The line run back over the
// lead-in would pass the sampling limit; bent to avoid that, it had given f' = -0.12 Hz/s
// instead of -0.35, and zeta_f = 0.95 from motions that were all zero.
TEST(Fit, AQuietLeadInShiftsTheFitAndBendsNothing) {
    RecordSource loma;
    loma.path = ROCKSWEEP_RECORDS_DIR "/loma_prieta_1989.dat";
    loma.units = "m/s^2";
    const Record r = read_record(loma);
    std::vector<double> padded(static_cast<std::size_t>(std::lround(60.0 / r.dt_s)), 0.0);
    padded.insert(padded.end(), r.ax_g.begin(), r.ax_g.end());
    const FitResult plain = fit_model(r.ax_g, r.dt_s), late = fit_model(padded, r.dt_s);
    EXPECT_NEAR(late.params.tmid_s, plain.params.tmid_s + 60.0, 1e-9 * late.params.tmid_s);
    EXPECT_NEAR(late.params.d595_s, plain.params.d595_s, 1e-9 * plain.params.d595_s);
    EXPECT_NEAR(late.params.f_mid_hz, plain.params.f_mid_hz, 1e-9 * plain.params.f_mid_hz);
    EXPECT_NEAR(late.params.f_slope_hz_s, plain.params.f_slope_hz_s, 1e-9);
    // The damping's bisection counts other noise (the envelope sits elsewhere): its own scatter.
    EXPECT_NEAR(late.params.zeta_f, plain.params.zeta_f, 0.05);
    EXPECT_NEAR(late.simulated_extrema, static_cast<double>(late.record_extrema), 0.05 * late.record_extrema + 1.0);
}

// A record no gamma envelope fits (its strong motion at once, then a long weak tail: D5-95 /
// t_mid far above 85) is refused naming --record and its landmarks, not the --d595 option the
// user never gave.
TEST(Fit, ARecordNoEnvelopeFitsIsRefusedAsTheRecord) {
    const double dt = 0.02;
    std::vector<double> a;
    for (int i = 0; i < 25; ++i) a.push_back(0.3 * std::sin(2.0 * M_PI * 4.0 * i * dt));
    for (int i = 0; i < 60000; ++i) a.push_back(0.002 * std::sin(2.0 * M_PI * 2.0 * i * dt));
    try {
        fit_model(a, dt);
        FAIL() << "fitted";
    } catch (const InputError& e) {
        EXPECT_EQ(e.field(), "record");
        EXPECT_NE(e.value().find("after t_mid"), std::string::npos) << e.value();
        EXPECT_NE(e.allowed().find("for a gamma envelope"), std::string::npos) << e.allowed();
    }
}
