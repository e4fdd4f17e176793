// The accuracy defaults of a single history (kHistoryDefaults, physics_kernel.md, "Numerics"): a default
// history overlays a tight reference to 1e-8 rad, where the sweep's defaults do not.
#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <string>

#include "rocksweep/physics/anchorage.hpp"
#include "rocksweep/physics/history.hpp"
#include "rocksweep/records/record.hpp"

using namespace rocksweep;

namespace {

const Block kBlock = rectangular_block(0.30, 1.36, 3361.0);
const std::string kRecords = ROCKSWEEP_RECORDS_DIR;

/// Largest |theta - theta_ref| over the samples of two histories of `pulse` every 0.01 s to
/// the end of the pulse plus ten rocking periods (simulate's default length).
double history_error(const Pulse& pulse, double steps, double threshold) {
    const Anchorage a = adaptive_anchorage(kBlock, 0.4 * kBlock.mass_kg * kBlock.gravity, kBlock.alpha_rad, 0.5);
    const double t_end = pulse.end_time() + 10.0 * 2.0 * M_PI / kBlock.p();
    IntegratorSettings ref, run;
    ref.steps_per_period = 4096;
    run.steps_per_period = steps;
    const History r = sample_history(make_cell_model(kBlock, a, pulse, Equations::nonlinear, 1e-9), ref, 0.01, t_end);
    const History h = sample_history(make_cell_model(kBlock, a, pulse, Equations::nonlinear, threshold), run, 0.01, t_end);
    EXPECT_EQ(h.result.outcome, r.result.outcome);
    EXPECT_EQ(h.t.size(), r.t.size());
    double err = 0.0;
    for (std::size_t i = 0; i < std::min(h.t.size(), r.t.size()); ++i) err = std::max(err, std::abs(h.theta[i] - r.theta[i]));
    return err;
}

}  // namespace

TEST(HistoryDefaults, ADefaultHistoryIsWithin1e8RadOfATightReference) {
    Pulse sample;  // the paper's sample case, omega_p / p = 4, a_p0 / (alpha g) = 2.7
    sample.omega = 4.0 * kBlock.p();
    sample.ax_g = 2.7 * kBlock.alpha_rad;
    const Pulse elcentro = read_record(kRecords + "/elcentro_1940_NS.dat", "g", 1.0, kBlock.gravity);
    for (const Pulse* p : std::initializer_list<const Pulse*>{&sample, &elcentro}) {
        const double err = history_error(*p, kHistoryDefaults.steps_per_period, kHistoryDefaults.impact_threshold);
        EXPECT_LE(err, 1e-8);
        EXPECT_GT(err, 0.0);  // a different run, not the reference itself
    }
    // The sweep's defaults (48 steps, 1e-3) are not enough for an overlay on the record.
    EXPECT_GT(history_error(elcentro, 48.0, 1e-3), 1e-7);
}
