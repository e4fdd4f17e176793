// Fits to the shared records: the fitted envelope reproduces each record's I_a, D5-95 and t_mid,
// and motions of the fitted model do so on average; the fit recovers known parameters from
// motions of the model itself.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

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
