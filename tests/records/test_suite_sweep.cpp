// A sweep over a record suite (suite_sweep.hpp) and what is read off it (suite_products.hpp):
// each record reaches its level exactly, each block size keeps alpha and density, each
// anchorage keeps its ratios, and the overturning spectrum and the fragility stripes count
// what the outcomes say.
#include <gtest/gtest.h>

#include <cmath>

#include "rocksweep/core/errors.hpp"
#include "rocksweep/motion/response_spectrum.hpp"
#include "rocksweep/physics/integrator.hpp"
#include "rocksweep/records/suite_products.hpp"
#include "rocksweep/records/suite_sweep.hpp"

using namespace rocksweep;

namespace {

const Block kBlock = rectangular_block(0.30, 1.36, 3361.0);  // S. Matteo

std::vector<Scenario> scenarios() {
    const double fu = 0.4 * kBlock.mass_kg * kBlock.gravity;
    return {{"free", free_anchorage(), 0.0, 1.0},
            {"constant_tf1", constant_anchorage(kBlock, fu, kBlock.alpha_rad), 1.0, 1.0},
            {"adaptive_rho0.1", adaptive_anchorage(kBlock, fu, kBlock.alpha_rad, 0.1), 1.0, 0.1}};
}

SuiteSpec shipped(IntensityMeasure m, std::vector<double> radii = {}, std::vector<double> alphas = {},
                  SuiteMotions motions = {}) {
    return make_suite_spec(ROCKSWEEP_CONFIGS_DIR "/records_suite.csv", kBlock, scenarios(), m, Axis{0.1, 0.9, 5},
                           std::move(radii), std::move(alphas), std::move(motions));
}

SuiteMotions two_floors() {
    SuiteMotions m;
    m.floors = {motion::parse_floor("floor", "ground"), motion::parse_floor("floor", "f2: 0.5 0.05 1.3; 0.17 0.05 -0.4")};
    m.sa = motion::Oscillator{0.5, 0.05};
    return m;
}

/// A suite of `n` one-sample-pair records of PGA 0.5 g, for products on made-up outcomes.
SuiteSpec synthetic(std::size_t n, std::size_t levels) {
    SuiteSpec s;
    s.block = kBlock;
    s.scenarios = {scenarios().front()};
    s.intensity = Axis{0.1, 0.1 * static_cast<double>(levels), levels};
    s.radii_m = {kBlock.radius_m};
    s.alphas_rad = {kBlock.alpha_rad};
    for (std::size_t i = 0; i < n; ++i) {
        SuiteMember m;
        m.record.dt_s = 0.01;
        m.record.ax_g = {0.0, 0.5, 0.0};
        m.measures.pga_g = 0.5;
        s.records.push_back(m);
    }
    return s;
}

}  // namespace

TEST(SuiteSweep, EveryRecordIsScaledToTheLevelOfEachMeasure) {
    // Two slendernesses: PGA / (g tan alpha) is reached on each block's own alpha.
    const std::vector<double> alphas{0.1, kBlock.alpha_rad};
    for (const IntensityMeasure m : {IntensityMeasure::pga_g, IntensityMeasure::pgv_m_s, IntensityMeasure::pga_ratio}) {
        const SuiteSpec spec = shipped(m, {}, alphas);
        ASSERT_EQ(spec.records.size(), 12u);
        for (std::size_t r = 0; r < spec.records.size(); ++r)
            for (std::size_t a = 0; a < alphas.size(); ++a)
                for (std::size_t l = 0; l < spec.intensity.points; ++l) {
                    const IntensityMeasures& im = spec.records[r].measures;
                    const double f = spec.scale_factor(r, a, l);
                    const double reached = m == IntensityMeasure::pga_g     ? f * im.pga_g
                                           : m == IntensityMeasure::pgv_m_s ? f * im.pgv_m_s
                                                                            : pga_over_g_tan_alpha(f * im.pga_g, alphas[a], kBlock.gravity);
                    EXPECT_NEAR(reached, spec.intensity.at(l), 1e-14 * spec.intensity.at(l)) << to_string(m) << " record " << r;
                }
    }
    const SuiteSpec scale = shipped(IntensityMeasure::scale);
    EXPECT_EQ(scale.scale_factor(3, 0, 2), scale.intensity.at(2));
}

TEST(SuiteSweep, ACellCarriesItsRecordScaledAtItsLevelOnItsBlock) {
    const SuiteSpec spec = shipped(IntensityMeasure::pga_g, {0.5, 1.0, 2.0}, {0.15, kBlock.alpha_rad});
    ASSERT_EQ(spec.cell_count(), 3u * 12u * 2u * 3u * 5u);
    // scenario 1, record 4, alpha 1, radius 2, level 3: (((1 * 12 + 4) * 2 + 1) * 3 + 2) * 5 + 3
    const std::size_t index = (((1 * 12 + 4) * 2 + 1) * 3 + 2) * 5 + 3;
    const SuiteSpec::Coordinates at = spec.coordinates(index);
    EXPECT_EQ(at.scenario, 1u);
    EXPECT_EQ(at.record, 4u);
    EXPECT_EQ(at.alpha, 1u);
    EXPECT_EQ(at.radius, 2u);
    EXPECT_EQ(at.level, 3u);
    EXPECT_EQ(spec.index(at), index);
    const CellModel c = spec.cell(index);
    const Block b = spec.block_of(kBlock.alpha_rad, 2.0);
    EXPECT_DOUBLE_EQ(c.p(), b.p());
    EXPECT_DOUBLE_EQ(c.alpha, kBlock.alpha_rad);
    ASSERT_EQ(c.pulse.kind, PulseKind::record);
    // The ground in units of the block's g has the level's PGA in standard g.
    EXPECT_NEAR(c.pulse.peak_ax() * kBlock.gravity / standard_gravity, spec.intensity.at(3), 1e-12);
    // Scaled per cell, not copied: every cell of the record shares its samples.
    EXPECT_EQ(c.pulse.record.get(), spec.cell(spec.index({1, 4, 0, 0, 1})).pulse.record.get());
    EXPECT_EQ(c.pulse.record_scale, spec.scale_factor(4, 1, 3));
    EXPECT_EQ(c.anchorage, AnchorageKind::constant);
    // Same theta_f / alpha and F_u / (m g) on the larger block: the force reaches F_u at theta_f.
    EXPECT_DOUBLE_EQ(c.break_max, kBlock.alpha_rad);
    EXPECT_NEAR(c.force_max * std::tan(c.break_max / 2), 1.0, 1e-12);
}

TEST(SuiteSweep, ASlendernessKeepsRDensityAndTheShareOfHousnersE) {
    const SuiteSpec spec = shipped(IntensityMeasure::pga_ratio, {}, {0.1, kBlock.alpha_rad});
    const Block b = spec.block_of(0.1, kBlock.radius_m);
    // A rectangle of the same R and depth: b h = R^2 sin(2 alpha) / 2 sets the mass.
    const Block rect = rectangular_block(kBlock.radius_m * std::sin(0.1), kBlock.radius_m * std::cos(0.1),
                                         kBlock.mass_kg * std::sin(0.2) / std::sin(2 * kBlock.alpha_rad));
    EXPECT_NEAR(b.mass_kg, rect.mass_kg, 1e-12 * rect.mass_kg);
    EXPECT_NEAR(b.p(), rect.p(), 1e-12 * rect.p());  // same R: same p
    EXPECT_NEAR(b.e, 1.0 - 1.5 * std::sin(0.1) * std::sin(0.1), 1e-15);  // Housner's, as the configured block's
    // A cell on it: its own alpha, and PGA / (g tan alpha) at the level on that alpha.
    const CellModel c = spec.cell(spec.index({0, 2, 0, 0, 4}));
    EXPECT_DOUBLE_EQ(c.alpha, 0.1);
    const double pga = c.pulse.peak_ax() * kBlock.gravity / standard_gravity;
    EXPECT_NEAR(pga_over_g_tan_alpha(pga, 0.1, kBlock.gravity), spec.intensity.at(4), 1e-12);
    // A restitution below Housner's keeps its fraction of it.
    SuiteSpec damped = spec;
    damped.block = rectangular_block(0.30, 1.36, 3361.0, 9.81, 0.5 * kBlock.e);
    EXPECT_NEAR(damped.block_of(0.1, kBlock.radius_m).e, 0.5 * b.e, 1e-15);
    // The configured slenderness and size: the configured block, bit for bit.
    const Block same = spec.block_of(kBlock.alpha_rad, kBlock.radius_m);
    EXPECT_EQ(same.mass_kg, kBlock.mass_kg);
    EXPECT_EQ(same.e, kBlock.e);
}

TEST(SuiteSweep, TheMexicoCityVerticalReachesTheCellScaledLikeItsHorizontal) {
    // The shipped suite reads tests/data/mexico_city_1985_sct.txt's column 4 as the vertical
    // (0.04 g at scale 1) of its two horizontal components: a cell carries it at the level's
    // factor, and it changes the block's motion.
    const SuiteSpec spec = shipped(IntensityMeasure::pga_g);
    const std::size_t r = 10, level = 4;  // mexico_city_1985_sct_ns, 0.9 g
    ASSERT_EQ(spec.records[r].entry.name, "mexico_city_1985_sct_ns");
    const Pulse& one = spec.records[r].pulse;
    ASSERT_TRUE(one.record_y);
    EXPECT_NEAR(one.peak_ay() * kBlock.gravity / standard_gravity, 0.04, 0.005);
    const CellModel c = spec.cell((0 * 12 + r) * 5 + level);  // free, the block's own size
    const double f = spec.scale_factor(r, 0, level);
    EXPECT_NEAR(f, 0.9 / spec.records[r].measures.pga_g, 1e-12 * f);
    ASSERT_EQ(c.pulse.record_y.get(), one.record_y.get());
    for (const double t : {10.0, 41.37, 60.01, 100.0}) {
        EXPECT_EQ(c.pulse.ax(t), f * one.ax(t)) << t;
        EXPECT_EQ(c.pulse.ay(t), f * one.ay(t)) << t;
    }
    EXPECT_EQ(c.pulse.peak_ay(), one.peak_ay() * f);
    CellResult both, horizontal;
    compute_suite_cells(spec, {}, (0 * 12 + r) * 5 + level, 1, &both);
    CellModel h = c;
    h.pulse.record_y = nullptr;
    horizontal = integrate_cell(h, {});
    EXPECT_GT(both.max_rotation, 0.05);  // it rocks under the three components (overturns at 0.9 g)
    // ... and not as under the horizontal alone: where it falls, or how far it rocks
    const bool fell = both.outcome != Outcome::safe;
    EXPECT_NE(fell ? both.t_overturn_s : both.max_rotation, fell ? horizontal.t_overturn_s : horizontal.max_rotation);
    EXPECT_TRUE(bitwise_equal(both, integrate_cell(c, {})));
}

TEST(SuiteSweep, ABlockSizeKeepsAlphaAndDensity) {
    const SuiteSpec spec = shipped(IntensityMeasure::pga_g);
    const Block b = spec.block_of(kBlock.alpha_rad, 2.0 * kBlock.radius_m);
    EXPECT_DOUBLE_EQ(b.alpha_rad, kBlock.alpha_rad);
    EXPECT_NEAR(b.mass_kg, 8.0 * kBlock.mass_kg, 1e-9 * kBlock.mass_kg);
    EXPECT_NEAR(b.p(), kBlock.p() / std::sqrt(2.0), 1e-12);
    EXPECT_EQ(b.e, kBlock.e);
    // The configured size is the configured block, bit for bit.
    const Block same = spec.block_of(kBlock.alpha_rad, kBlock.radius_m);
    EXPECT_EQ(same.mass_kg, kBlock.mass_kg);
    EXPECT_EQ(same.p(), kBlock.p());
}

TEST(SuiteSweep, ARecordThatCannotBeScaledIsRefused) {
    const std::string dir = ::testing::TempDir();
    {
        std::FILE* f = std::fopen((dir + "zero.dat").c_str(), "w");
        std::fputs("0 0\n0.01 0\n0.02 0\n", f);
        std::fclose(f);
        f = std::fopen((dir + "zero.csv").c_str(), "w");
        std::fputs("name,file,format,units\nquiet,zero.dat,time_accel,g\n", f);
        std::fclose(f);
    }
    try {
        make_suite_spec(dir + "zero.csv", kBlock, scenarios(), IntensityMeasure::pga_g, Axis{0.1, 0.2, 2}, {});
        FAIL() << "accepted a record with no PGA";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("quiet has none"), std::string::npos) << e.what();
    }
}

TEST(SuiteProducts, FirstOverturningLevelAndSafeLevelsAboveIt) {
    const SuiteSpec spec = synthetic(3, 5);
    SweepResults r;
    r.resize(spec.cell_count());
    const std::uint8_t outcomes[3][5] = {{0, 0, 1, 0, 1},    // overturns at 0.3, stands at 0.4
                                         {0, 0, 0, 2, 1},    // from 0.4 on
                                         {0, 0, 0, 0, 0}};   // never
    for (std::size_t rec = 0; rec < 3; ++rec)
        for (std::size_t l = 0; l < 5; ++l) r.store(rec * 5 + l, CellResult{0.1, NAN, NAN, 0, 0, 0, 0, Outcome{outcomes[rec][l]}});
    const OverturningSpectrum o = overturning_spectrum(spec, r, 0);
    EXPECT_DOUBLE_EQ(o.first_intensity[0], spec.intensity.at(2));
    EXPECT_DOUBLE_EQ(o.below_intensity[0], spec.intensity.at(1));
    EXPECT_EQ(o.safe_above[0], 1);
    EXPECT_DOUBLE_EQ(o.first_pga_g[0], spec.intensity.at(2));  // PGA is the measure
    EXPECT_DOUBLE_EQ(o.first_intensity[1], spec.intensity.at(3));
    EXPECT_EQ(o.safe_above[1], 0);
    EXPECT_TRUE(std::isnan(o.first_intensity[2]));
    EXPECT_TRUE(std::isnan(o.first_pga_g[2]));
}

TEST(SuiteProducts, FragilityStripesCountTheRecordsAndLeaveOutUnconvergedRuns) {
    const SuiteSpec spec = synthetic(4, 3);
    SweepResults r;
    r.resize(spec.cell_count());
    // max rotation / alpha per record and level; 9: overturned; -1: not converged.
    const double rot[4][3] = {{0.05, 0.2, 9}, {0.2, 0.6, 9}, {0.01, 0.02, 0.4}, {0.05, -1, 9}};
    for (std::size_t rec = 0; rec < 4; ++rec)
        for (std::size_t l = 0; l < 3; ++l) {
            const double x = rot[rec][l];
            const Outcome o = x == 9 ? Outcome::overturned_impact : x < 0 ? Outcome::not_converged : Outcome::safe;
            r.store(rec * 3 + l, CellResult{x == 9 ? M_PI / 2 / kBlock.alpha_rad : x, NAN, NAN, 0, 0, 0, 0, o});
        }
    const SuiteFragility f = suite_fragility(spec, r, 0, {{0.1, false}, {0.0, true}});
    const std::vector<std::int32_t> exceed{1, 2, 4, 0, 0, 3}, total{4, 3, 4, 4, 3, 4};
    EXPECT_EQ(f.exceed, exceed);
    EXPECT_EQ(f.total, total);
    ASSERT_EQ(f.fits.size(), 2u);
    // Overturning: none, none, 3 of 4 at the top level: the median lies above the second level.
    EXPECT_GT(f.fits[1].curve.median, spec.intensity.at(1));
}

// Every record at every level: the fit's errors are the records' (docs/fragility.md, "Records
// as clusters"). 200 records whose capacities are lognormal quantiles (median 1.5, beta 0.5) at
// 30 levels 0.1..3: se(ln median) near beta / sqrt(200) = 0.035, what one capacity per record
// gives, and not the run-counting error of the same stripes, several times smaller.
TEST(SuiteProducts, FragilityErrorsAreThoseOfTheRecordsNotOfTheRuns) {
    const std::size_t n = 200, levels = 30;
    const SuiteSpec spec = synthetic(n, levels);
    SweepResults r;
    r.resize(spec.cell_count());
    for (std::size_t rec = 0; rec < n; ++rec) {
        // Phi^-1 of (rec + 0.5) / n by bisection: the standard library has erfc, not its inverse.
        double lo = -10, hi = 10;
        for (int k = 0; k < 200; ++k) ((normal_cdf(0.5 * (lo + hi)) < (rec + 0.5) / n) ? lo : hi) = 0.5 * (lo + hi);
        const double capacity = 1.5 * std::exp(0.5 * lo);
        for (std::size_t l = 0; l < levels; ++l) {
            const bool falls = spec.intensity.at(l) >= capacity;
            r.store(rec * levels + l, CellResult{falls ? 9.0 : 0.1, NAN, NAN, 0, 0, 0, 0,
                                                 falls ? Outcome::overturned_impact : Outcome::safe});
        }
    }
    const SuiteFragility f = suite_fragility(spec, r, 0, {{0.0, true}});
    ASSERT_EQ(f.fits.size(), 1u);
    const FragilityFit& fit = f.fits[0];
    ASSERT_EQ(fit.status, FitStatus::ok);
    EXPECT_NEAR(std::log(fit.curve.median), std::log(1.5), 0.05);
    EXPECT_NEAR(fit.se_ln_median / (0.5 / std::sqrt(200.0)), 1.0, 0.25) << fit.se_ln_median;
    std::vector<Stripe> stripes;
    for (std::size_t l = 0; l < levels; ++l) stripes.push_back({spec.intensity.at(l), f.exceed[l], f.total[l]});
    EXPECT_GT(fit.se_ln_median, 2.0 * fit_stripes(stripes).se_ln_median);
    EXPECT_LT(fit.median_lo, fit.curve.median * std::exp(-1.9 * fit.se_ln_median));  // the intervals follow
}

TEST(SuiteSweep, EveryScenarioStandsOnEveryFloorAndACellReadsItsFloorsMotion) {
    const SuiteSpec ground = shipped(IntensityMeasure::pga_g);
    EXPECT_EQ(ground.scenarios[0].name, "free");  // the ground alone: names as before floors
    const SuiteSpec spec = shipped(IntensityMeasure::pga_g, {}, {}, two_floors());
    ASSERT_EQ(spec.scenarios.size(), 6u);
    EXPECT_EQ(spec.scenarios[0].name, "free@ground");
    EXPECT_EQ(spec.scenarios[5].name, "adaptive_rho0.1@f2");
    EXPECT_EQ(spec.floor_of(4), 1u);
    // scenario 4 (constant on f2), record 3, level 2
    const CellModel c = spec.cell(spec.index({4, 3, 0, 0, 2}));
    const Record floor = on_floor(spec.records[3].record, spec.floors[1]);
    const int m = motion::floor_oversampling(spec.floors[1], spec.records[3].record.dt_s);
    EXPECT_EQ(m, 9);  // T = 0.17 s at dt = 0.02 s: h <= T / 70
    ASSERT_EQ(c.pulse.record->size(), (spec.records[3].record.ax_g.size() - 1) * m + 1);
    EXPECT_DOUBLE_EQ(c.pulse.record_dt_s, spec.records[3].record.dt_s / m);
    EXPECT_EQ((*c.pulse.record)[777], floor.ax_g[777] * standard_gravity / kBlock.gravity);
    EXPECT_EQ(c.pulse.record_scale, spec.scale_factor(3, 0, 2, 1));
    EXPECT_EQ(c.anchorage, AnchorageKind::constant);
    double pfa = 0.0;
    for (double x : floor.ax_g) pfa = std::max(pfa, std::abs(x));
    EXPECT_EQ(spec.records[3].floors[1].pfa_g, pfa);
    EXPECT_EQ(spec.records[3].floors[0].pfa_g, spec.records[3].measures.pga_g);
    EXPECT_EQ(spec.records[3].floors[1].spectrum_g.size(), motion::floor_spectrum_periods().size());
}

TEST(SuiteSweep, SaOfTheGroundAndPfaOfTheScenariosFloorReachEachLevel) {
    const SuiteSpec sa = shipped(IntensityMeasure::sa_g, {}, {}, two_floors());
    const SuiteSpec pfa = shipped(IntensityMeasure::pfa_g, {}, {}, two_floors());
    for (std::size_t r = 0; r < sa.records.size(); ++r) {
        SCOPED_TRACE(r);
        EXPECT_EQ(sa.records[r].sa_g, motion::spectral_acceleration(sa.records[r].record.ax_g, sa.records[r].record.dt_s, {0.5, 0.05}));
        for (std::size_t l = 0; l < sa.intensity.points; ++l) {
            // Sa is linear in the ground, so on every floor the factor is the ground's.
            EXPECT_NEAR(sa.scale_factor(r, 0, l, 1) * sa.records[r].sa_g, sa.intensity.at(l), 1e-12);
            for (std::size_t f = 0; f < 2; ++f) {
                const CellModel c = pfa.cell(pfa.index({3 * f, r, 0, 0, l}));
                EXPECT_NEAR(c.pulse.peak_ax() * kBlock.gravity / standard_gravity, pfa.intensity.at(l), 1e-12);
            }
        }
    }
}

namespace {

/// Made motions that are the shipped suite's records: a made motion must reach every floor, be
/// measured there and be integrated exactly as the same motion read from its file.
class RecordsAsMade : public MotionSource {
public:
    explicit RecordsAsMade(std::vector<Record> records) : records_(std::move(records)) {}
    std::size_t size() const override { return records_.size(); }
    std::string name(std::size_t i) const override { return "made_" + std::to_string(i); }
    Record motion(std::size_t i) const override { return records_.at(i); }
    std::string describe() const override { return "the shipped records"; }

private:
    std::vector<Record> records_;
};

}  // namespace

TEST(SuiteSweep, AMadeMotionOnAFloorIsMeasuredAndIntegratedAsTheSameMotionRead) {
    const SuiteSpec read = shipped(IntensityMeasure::pfa_g, {}, {}, two_floors());
    std::vector<Record> records;
    for (const SuiteMember& m : read.records) records.push_back(m.record);
    SuiteMotions motions = two_floors();
    motions.made = std::make_shared<RecordsAsMade>(records);
    const SuiteSpec made = make_suite_spec("", kBlock, scenarios(), IntensityMeasure::pfa_g, Axis{0.1, 0.9, 5}, {}, {},
                                           std::move(motions));
    ASSERT_EQ(made.records.size(), read.records.size());
    ASSERT_EQ(made.scenarios.size(), read.scenarios.size());
    for (std::size_t r = 0; r < read.records.size(); ++r) {
        SCOPED_TRACE(r);
        const SuiteMember &a = read.records[r], &b = made.records[r];
        EXPECT_EQ(b.motion, static_cast<std::ptrdiff_t>(r));
        EXPECT_TRUE(b.record.ax_g.empty());  // its samples dropped once measured
        EXPECT_EQ(b.measures.pga_g, a.measures.pga_g);
        EXPECT_EQ(b.sa_g, a.sa_g);
        ASSERT_EQ(b.floors.size(), 2u);
        for (std::size_t f = 0; f < 2; ++f) {
            EXPECT_FALSE(b.floors[f].pulse.record);
            EXPECT_EQ(b.floors[f].pfa_g, a.floors[f].pfa_g);
            EXPECT_EQ(b.floors[f].spectrum_g, a.floors[f].spectrum_g);
        }
    }
    EXPECT_THROW(made.cell(0), std::logic_error);  // a made motion's cell needs its motion
    // The last three records on the ground's last scenario and the first three on f2's first (the
    // floor changes inside the range), in one batch and cell by cell (any chunking, any rank count).
    const std::size_t first = made.index({2, 9, 0, 0, 0}), count = made.index({3, 3, 0, 0, 0}) - first;
    std::vector<CellResult> a(count), batch(count), single(count);
    compute_suite_cells(read, IntegratorSettings{}, first, count, a.data());
    compute_suite_cells(made, IntegratorSettings{}, first, count, batch.data());
    for (std::size_t i = 0; i < count; ++i) compute_suite_cells(made, IntegratorSettings{}, first + i, 1, &single[i]);
    std::size_t overturned = 0;
    for (std::size_t i = 0; i < count; ++i) {
        EXPECT_TRUE(bitwise_equal(batch[i], a[i])) << "cell " << first + i;
        EXPECT_TRUE(bitwise_equal(single[i], a[i])) << "cell " << first + i;
        overturned += a[i].outcome != Outcome::safe;
    }
    EXPECT_GT(overturned, 0u);  // the floors' motions did something to compare
}
