// A record's vertical component in the integrator (issue 9): the equation it enters (a constant
// vertical is a change of gravity), the uplift test it changes, free fall refused, and records as
// a vectorised family: one shared table, a scale per lane, the same bits alone and in every
// batch width. The Mexico City record's vertical through a suite cell: test_suite_sweep.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <memory>
#include <vector>

#include "test_support.hpp"
#include "rocksweep/core/errors.hpp"
#include "rocksweep/physics/anchorage.hpp"
#include "rocksweep/physics/history.hpp"
#include "rocksweep/physics/integrator.hpp"
#include "rocksweep/records/record.hpp"

using namespace rocksweep;

namespace {

const Block kBlock = rectangular_block(0.30, 1.36, 3361.0);  // S. Matteo, g = 9.81
const std::string kRecords = ROCKSWEEP_RECORDS_DIR;

using Table = std::shared_ptr<const std::vector<double>>;

Table table(std::vector<double> v) { return std::make_shared<const std::vector<double>>(std::move(v)); }

Pulse record_pulse(Table ax, Table ay, double dt_s, double scale = 1.0) {
    Pulse p;
    p.kind = PulseKind::record;
    p.record = std::move(ax);
    p.record_y = std::move(ay);
    p.record_dt_s = dt_s;
    p.record_scale = scale;
    return p;
}

/// El Centro N-S (in the block's g) times `factor`, cut to its first `seconds`.
std::vector<double> elcentro(double factor, double seconds) {
    const Pulse p = read_record(kRecords + "/elcentro_1940_NS.dat", "g", 1.0, kBlock.gravity);
    std::vector<double> a(p.record->begin(), p.record->begin() + static_cast<long>(seconds / p.record_dt_s) + 1);
    for (double& x : a) x *= factor;
    return a;
}

/// The time the block first leaves rest: the start of the first step with theta != 0.
double uplift_time(const CellModel& m) {
    IntegratorSettings s;
    s.t_end_s = m.pulse.end_time();
    double t_up = INFINITY;
    integrate_cell(m, s, [&](const StepRecord& r) {
        if (std::isinf(t_up) && r.theta1 != 0.0) t_up = r.t0;
    });
    return t_up;
}

}  // namespace

TEST(RecordVertical, AConstantVerticalIsTheSameMotionAsAStrongerGravity) {
    // theta'' = -p^2 [(1 + c) sin(s alpha - theta) + ax cos(s alpha - theta)]
    //         = -p^2 (1 + c) [sin(s alpha - theta) + ax / (1 + c) cos(s alpha - theta)]:
    // the block under g' = g (1 + c) (p'^2 = 3 g' / 4R = p^2 (1 + c)) and the horizontal
    // ground ax g / g' = ax / (1 + c) in units of g'. Uplift, |ax| > (1 + c) tan(alpha), is
    // |ax / (1 + c)| > tan(alpha); the step, sqrt(p^2 (1 + peak_ax + c)), is the same. Free
    // blocks only (a spring's kappa does not scale with g), over the record only (after it the
    // ground's vertical stops and the two blocks differ).
    for (const double c : {0.3, -0.3}) {
        SCOPED_TRACE(c);
        const double seconds = 12.0;
        const std::vector<double> ax = elcentro(2.0, seconds);
        const Pulse with_y = record_pulse(table(ax), table(std::vector<double>(ax.size(), c)), 0.02);
        std::vector<double> ax_heavier = ax;
        for (double& x : ax_heavier) x /= 1.0 + c;
        const Block heavier = rectangular_block(0.30, 1.36, 3361.0, kBlock.gravity * (1.0 + c));
        const CellModel a = make_cell_model(kBlock, free_anchorage(), with_y);
        const CellModel b = make_cell_model(heavier, free_anchorage(), record_pulse(table(ax_heavier), nullptr, 0.02));
        EXPECT_NEAR(b.p2, a.p2 * (1.0 + c), 1e-14 * b.p2);
        // c < 0 lowers peak_ay's share of the step size in a but not in b: steps that end at the
        // samples (0.02 s, shorter than either) make the two step sequences the same.
        IntegratorSettings s;
        s.steps_end_at_samples = true;
        const History ha = sample_history(a, s, 0.01, seconds), hb = sample_history(b, s, 0.01, seconds);
        ASSERT_EQ(ha.t.size(), hb.t.size());
        double worst = 0.0, largest = 0.0;
        for (std::size_t i = 0; i < ha.t.size(); ++i) {
            worst = std::max(worst, std::abs(ha.theta[i] - hb.theta[i]));
            largest = std::max(largest, std::abs(ha.theta[i]));
        }
        EXPECT_GT(largest, 0.1 * kBlock.alpha_rad);  // it rocks
        // The same equation rounded two ways: each located impact may land elsewhere within the
        // stepper's 1e-12 of a step, and the impacts carry that on (4e-12 rad seen for c = 0.3).
        EXPECT_LT(worst, 1e-10) << "largest |theta| " << largest;
        EXPECT_EQ(ha.result.impacts_total, hb.result.impacts_total);
    }
}

TEST(RecordSteps, StepsAcrossSamplesOnMomentNodesAreFourthOrder) {
    // El Centro at twice its scale with its copy as a vertical at 0.3 (both enter through the
    // moment nodes), free and with the constant anchorage theta_f = alpha: theta over 12 s,
    // sampled every 0.01 s, against steps that end at every sample (8192 per period). Steps of
    // 1/64 to 1/1024 of a period that cross the 0.02 s samples converge at a steady order (point
    // values of the ground at the nodes instead give 0.1-2 rad, benchmarks/RECORD_STEPS.md).
    const std::vector<double> ax = elcentro(2.0, 12.0);
    std::vector<double> ay = ax;
    for (double& x : ay) x *= 0.3;
    const Pulse p = record_pulse(table(ax), table(ay), 0.02);
    for (const Anchorage& a : {free_anchorage(), constant_anchorage(kBlock, 0.4 * kBlock.mass_kg * kBlock.gravity, kBlock.alpha_rad)}) {
        const CellModel m = make_cell_model(kBlock, a, p, Equations::nonlinear, 1e-9);
        IntegratorSettings ref;
        ref.steps_per_period = 8192;
        const History r = sample_history(m, ref, 0.01, 12.0);
        ASSERT_GE(r.result.impacts, 3);
        auto err = [&](double n) {
            // sample_history ends its steps at samples: integrate and sample the steps here.
            IntegratorSettings s;
            s.steps_per_period = n;
            s.steps_end_at_samples = false;
            s.t_end_s = 12.0;
            s.energy_stop = false;
            double e = 0.0;
            std::size_t k = 0;
            integrate_cell(m, s, [&](const StepRecord& st) {
                for (; k < r.t.size() && r.t[k] <= st.t1; ++k) {
                    double th, thd;
                    st.at(std::max(r.t[k], st.t0), th, thd);
                    e = std::max(e, std::abs(th - r.theta[k]));
                }
            });
            return e;
        };
        // Where the kinks fall inside the steps moves with the step: the error is a sawtooth
        // about h^4, so the order is fitted over five halvings (least squares in log-log).
        double sx = 0, sy = 0, sxx = 0, sxy = 0;
        const int n = 5;
        for (int i = 0; i < n; ++i) {
            const double x = std::log(64.0 * std::pow(2.0, i)), y = std::log(err(64.0 * std::pow(2.0, i)));
            sx += x, sy += y, sxx += x * x, sxy += x * y;
        }
        const double order = -(n * sxy - sx * sy) / (n * sxx - sx * sx);
        // Measured 3.04 (free) and 3.05 (constant), errors 3.4e-5 at 64 to 7.9e-9 at 1024:
        // third order here, not the fourth the prototype saw at its finer steps. Why is open
        // (issue 9); it is one reason steps end at samples by default.
        EXPECT_GT(order, 2.7);
        EXPECT_LT(order, 5.0);
        EXPECT_LT(err(64), 1e-4);
    }
}

TEST(RecordVertical, UpliftFromRestWhenTheHorizontalFirstExceedsOnePlusVerticalTimesTanAlpha) {
    // ax = tan(alpha) t (lifts at t = 1 s alone); ay = c0 + c1 t, linear as the samples are:
    // tan(alpha) t = (1 + c0 + c1 t) tan(alpha)  =>  t* = (1 + c0) / (1 - c1).
    const double ta = std::tan(kBlock.alpha_rad), dt = 0.01;
    std::vector<double> ax(301);
    for (std::size_t i = 0; i < ax.size(); ++i) ax[i] = ta * static_cast<double>(i) * dt;
    EXPECT_NEAR(uplift_time(make_cell_model(kBlock, free_anchorage(), record_pulse(table(ax), nullptr, dt))), 1.0, 1e-9);
    for (const auto& [c0, c1] : {std::pair{0.3, -0.1}, std::pair{-0.3, 0.1}}) {
        std::vector<double> ay(ax.size());
        for (std::size_t i = 0; i < ay.size(); ++i) ay[i] = c0 + c1 * static_cast<double>(i) * dt;
        const CellModel m = make_cell_model(kBlock, free_anchorage(), record_pulse(table(ax), table(ay), dt));
        const double t_star = (1.0 + c0) / (1.0 - c1);  // 1.1818 s, 0.7778 s
        EXPECT_NEAR(uplift_time(m), t_star, 1e-9) << c0;
        EXPECT_FALSE(m.uplifts(t_star - 1e-6));
        EXPECT_TRUE(m.uplifts(t_star + 1e-6));
        EXPECT_DOUBLE_EQ(m.pulse.peak_ay(), std::max(std::abs(c0), std::abs(c0 + c1 * 3.0)));
    }
}

TEST(RecordVertical, ScaleAppliesToBothComponentsAfterInterpolation) {
    const Table ax = table({0.0, 0.1, -0.2, 0.05}), ay = table({0.0, -0.05, 0.1, 0.02});
    const Pulse one = record_pulse(ax, ay, 0.02), scaled = record_pulse(ax, ay, 0.02, -2.5);
    for (const double t : {0.0, 0.013, 0.02, 0.031, 0.0599}) {
        EXPECT_EQ(scaled.ax(t), -2.5 * one.ax(t)) << t;  // bit for bit: f * (interpolated)
        EXPECT_EQ(scaled.ay(t), -2.5 * one.ay(t)) << t;
    }
    EXPECT_DOUBLE_EQ(one.ax(0.03), -0.05);
    EXPECT_DOUBLE_EQ(one.ay(0.03), 0.025);
    EXPECT_DOUBLE_EQ(scaled.peak_ax(), 0.5);
    EXPECT_DOUBLE_EQ(scaled.peak_ay(), 0.25);
    EXPECT_EQ(record_pulse(ax, nullptr, 0.02).ay(0.03), 0.0);
}

TEST(RecordVertical, AVerticalAtOrBelowMinusGIsRefusedAsFreeFall) {
    Record r;
    r.vertical_path = "quake_up.dat";
    r.dt_s = 0.01;
    r.ax_g = {0.0, 0.1, 0.0};
    r.ay_g = {0.0, -0.5, 0.0};
    EXPECT_NO_THROW(to_pulse(r, standard_gravity));
    r.ay_g[1] = -1.0;  // exactly -g in standard g
    EXPECT_EQ(rocksweep::testing::message_of([&] { to_pulse(r, standard_gravity); }),
              "--record-vertical = quake_up.dat is invalid: a vertical acceleration above -g at every "
              "sample (sample 1, t = 0.01 s, is -1 g: free fall, the block would leave the ground)");
}

TEST(RecordVertical, AVerticalScaledPastMinusGIsComputedAndFlaggedAsPivotUplift) {
    // docs/physics.md: a suite level may scale an accepted vertical below -g; the cell runs the
    // equation as written and says the model does not hold there (f_y <= 0).
    const std::vector<double> ax = elcentro(0.2, 10.0);
    const Pulse up = record_pulse(table(ax), table(std::vector<double>(ax.size(), -0.5)), 0.02);
    Pulse past = up;
    past.record_scale = 2.5;  // vertical -1.25 g
    const CellResult fine = integrate_cell(make_cell_model(kBlock, free_anchorage(), up), {});
    const CellResult flagged = integrate_cell(make_cell_model(kBlock, free_anchorage(), past), {});
    EXPECT_EQ(fine.pivot_uplift, 0);
    EXPECT_EQ(flagged.pivot_uplift, 1);
}

TEST(RecordVertical, LanesOfOneRecordAtManyScalesGiveTheSameBitsAloneAndInEveryBatchWidth) {
    // Cells as a suite orders them (one record, levels innermost), a second record, cells with
    // and without a vertical, all anchorages: whatever lanes a cell shares a batch with, and
    // whether the batch runs the vector loop or per lane, its bits are those of the cell alone.
    const Pulse sylmar = read_record(kRecords + "/northridge_1994_sylmar.dat", "m/s^2", 1.0, kBlock.gravity);
    const Table ec = table(elcentro(1.0, 20.0));
    std::vector<double> up(ec->size());
    for (std::size_t i = 0; i < up.size(); ++i) up[i] = 0.5 * (*ec)[(i * 7) % ec->size()];
    const Table ec_up = table(up);
    const double fu = 0.4 * kBlock.mass_kg * kBlock.gravity;
    std::vector<CellModel> cells;
    for (const Anchorage& a : {free_anchorage(), constant_anchorage(kBlock, fu, kBlock.alpha_rad / 2),
                               adaptive_anchorage(kBlock, fu, kBlock.alpha_rad, 0.1)}) {
        for (double f : {0.3, 0.7, 1.0, 1.6, 2.5}) cells.push_back(make_cell_model(kBlock, a, record_pulse(ec, ec_up, 0.02, f)));
        for (double f : {0.4, 0.9, 1.3}) cells.push_back(make_cell_model(kBlock, a, record_pulse(ec, nullptr, 0.02, f)));
        Pulse s = sylmar;
        for (double f : {0.5, 1.0, -0.8}) {
            s.record_scale = f;
            cells.push_back(make_cell_model(kBlock, a, s));
        }
    }
    // The events method with steps that end at samples and with steps that cross them (moment
    // nodes, set per lane outside the vector loop), and the paper's.
    for (int mode = 0; mode < 3; ++mode) {
        IntegratorSettings s;
        s.method = mode == 2 ? Method::paper : Method::events;
        s.steps_end_at_samples = mode != 1;
        SCOPED_TRACE(mode);
        std::vector<CellResult> scalar(cells.size());
        int rocked = 0;
        for (std::size_t i = 0; i < cells.size(); ++i) {
            scalar[i] = integrate_cell(cells[i], s);
            rocked += scalar[i].max_rotation > 0.05 ? 1 : 0;
        }
        EXPECT_GE(rocked, 20);  // most cells rock: the ground reaches the results
        for (int lanes : {1, 4, 8, 16}) {
            std::vector<CellResult> batch(cells.size());
            integrate_cells(cells, batch, s, lanes);
            for (std::size_t i = 0; i < cells.size(); ++i)
                ASSERT_TRUE(bitwise_equal(batch[i], scalar[i])) << "cell " << i << " lanes " << lanes;
        }
    }
}

TEST(RecordSteps, StepsAcrossSamplesTakeTheFrictionDemandAtTheSamplesTheyCross) {
    // |f_x / f_y| has a kink at each sample (the ground's slope jumps) and peaks at those where
    // the record turns as often as not: steps that cross samples take the demand there too, from
    // the step's interpolant, not only at their ends, and no parabola is fitted across such a
    // kink (it overshoots). El Centro at 0.7x and 0.9x, free and anchored, its first 30 s:
    // mu_required at 48 steps per period, crossing the samples and ending at each, against
    // steps that end at every sample, 1024 per period. Taken at the crossing steps' ends only it
    // was 2.1-2.7 % low in three of these four runs, now within 1.1e-4; with parabolas across
    // the kinks the default was 1.7-2.3e-3 high, now within 1.2e-8.
    for (const double factor : {0.7, 0.9}) {
        const Pulse p = record_pulse(table(elcentro(factor, 30.0)), nullptr, 0.02);
        for (const Anchorage& a :
             {free_anchorage(), constant_anchorage(kBlock, 0.4 * kBlock.mass_kg * kBlock.gravity, kBlock.alpha_rad)}) {
            SCOPED_TRACE(factor);
            const CellModel m = make_cell_model(kBlock, a, p);
            IntegratorSettings ref, cross;
            ref.steps_per_period = 1024;
            cross.steps_end_at_samples = false;
            const CellResult r = integrate_cell(m, ref), c = integrate_cell(m, cross);
            ASSERT_EQ(r.outcome, Outcome::safe);
            ASSERT_EQ(c.outcome, Outcome::safe);
            EXPECT_GT(r.mu_required, std::tan(kBlock.alpha_rad));  // it rocks
            EXPECT_NEAR(c.mu_required, r.mu_required, 5e-4 * r.mu_required);
            const double d = integrate_cell(m, {}).mu_required;  // the default: steps end at samples
            EXPECT_NEAR(d, r.mu_required, 1e-6 * r.mu_required);
        }
    }
}
