// A suite's made motions measured in shares (records/made_measures.hpp), as `suite` measures
// them over its ranks: the writer ends with every measure and a worker with those it scales by,
// bitwise those of the eager path, and the worker's cells are bitwise the eager spec's.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <memory>

#include "rocksweep/records/made_measures.hpp"
#include "rocksweep/synthetic/model_motions.hpp"

using namespace rocksweep;

namespace {

const Block kBlock = rectangular_block(0.30, 1.36, 3361.0);  // S. Matteo
constexpr std::size_t kMotions = 7;

// Short motions (t_mid 3 s, 12 s long) on the ground and a two-mode floor.
SuiteMotions motions(SuiteMotions::Measures measures) {
    const synthetic::ModelParameters p{.arias_m_s = 0.3, .d595_s = 4.0, .tmid_s = 3.0, .f_mid_hz = 4.0,
                                       .f_slope_hz_s = -0.1, .zeta_f = 0.3};
    SuiteMotions m;
    m.floors = {motion::parse_floor("floor", "ground"), motion::parse_floor("floor", "f2: 0.5 0.05 1.3; 0.17 0.05 -0.4")};
    m.sa = motion::Oscillator{0.5, 0.05};
    m.made = std::make_shared<synthetic::ModelMotions>(synthetic::Generator(p, 0.02, 12.0), 3, kMotions);
    m.measures = measures;
    return m;
}

SuiteSpec spec(IntensityMeasure measure, SuiteMotions::Measures measures) {
    const double fu = 0.4 * kBlock.mass_kg * kBlock.gravity;
    const std::vector<Scenario> scenarios{{"free", free_anchorage(), 0.0, 1.0},
                                          {"constant_tf1", constant_anchorage(kBlock, fu, kBlock.alpha_rad), 1.0, 1.0}};
    return make_suite_spec("", kBlock, scenarios, measure, Axis{0.2, 0.6, 2}, {}, {}, motions(measures));
}

std::uint64_t bits(double x) { return std::bit_cast<std::uint64_t>(x); }

}  // namespace

TEST(MadeMeasures, SharesGatheredAreTheEagerMeasuresAndCellsBitForBit) {
    for (const IntensityMeasure m : {IntensityMeasure::pga_g, IntensityMeasure::pgv_m_s, IntensityMeasure::sa_g,
                                     IntensityMeasure::pfa_g}) {
        SCOPED_TRACE(to_string(m));
        const SuiteSpec eager = spec(m, SuiteMotions::Measures::all);
        // Two "ranks": the writer measures motions 0-2, the worker 3-6; the writer gathers the
        // worker's share, the worker receives the scaling measures of every motion.
        SuiteSpec writer = spec(m, SuiteMotions::Measures::none), worker = spec(m, SuiteMotions::Measures::none);
        measure_made_motions(writer, 0, 3);
        measure_made_motions(worker, 3, kMotions - 3);
        unpack_made_measures(writer, 3, pack_made_measures(worker, 3, kMotions - 3));
        unpack_scaling_measures(worker, pack_scaling_measures(writer));
        check_made_measures(writer);
        check_made_measures(worker);
        ASSERT_EQ(writer.records.size(), kMotions);
        for (std::size_t r = 0; r < kMotions; ++r) {
            SCOPED_TRACE(r);
            const SuiteMember &e = eager.records[r], &w = writer.records[r], &k = worker.records[r];
            EXPECT_EQ(w.record.path, e.record.path);
            EXPECT_EQ(w.record.units, e.record.units);
            EXPECT_EQ(bits(w.record.dt_s), bits(e.record.dt_s));
            EXPECT_EQ(w.record.npts, e.record.npts);
            EXPECT_EQ(w.record.ax_g.capacity(), 0u);  // the samples freed, not only cleared: ~12 KB a motion
            EXPECT_EQ(e.record.ax_g.capacity(), 0u);
            for (const IntensityField& f : intensity_fields)
                EXPECT_EQ(bits(w.measures.*f.value), bits(e.measures.*f.value)) << f.name;
            EXPECT_EQ(bits(w.sa_g), bits(e.sa_g));
            EXPECT_EQ(bits(k.sa_g), bits(e.sa_g));
            EXPECT_EQ(bits(k.measures.pga_g), bits(e.measures.pga_g));
            EXPECT_EQ(bits(k.measures.pgv_m_s), bits(e.measures.pgv_m_s));
            ASSERT_EQ(w.floors.size(), 2u);
            ASSERT_EQ(k.floors.size(), 2u);
            for (std::size_t f = 0; f < 2; ++f) {
                EXPECT_EQ(bits(w.floors[f].pfa_g), bits(e.floors[f].pfa_g));
                EXPECT_EQ(bits(k.floors[f].pfa_g), bits(e.floors[f].pfa_g));
                ASSERT_EQ(w.floors[f].spectrum_g.size(), e.floors[f].spectrum_g.size());
                for (std::size_t t = 0; t < e.floors[f].spectrum_g.size(); ++t)
                    EXPECT_EQ(bits(w.floors[f].spectrum_g[t]), bits(e.floors[f].spectrum_g[t]));
                EXPECT_TRUE(k.floors[f].spectrum_g.empty());  // a worker keeps no spectrum
            }
        }
        // Every cell of every floor, integrated from the worker's spec and the eager one.
        std::vector<CellResult> a(eager.cell_count()), b(a.size());
        compute_suite_cells(eager, IntegratorSettings{}, 0, a.size(), a.data());
        compute_suite_cells(worker, IntegratorSettings{}, 0, b.size(), b.data());
        for (std::size_t i = 0; i < a.size(); ++i) EXPECT_TRUE(bitwise_equal(a[i], b[i])) << "cell " << i;
    }
}

TEST(MadeMeasures, NumbersThatDoNotFitAreRefused) {
    SuiteSpec s = spec(IntensityMeasure::pga_g, SuiteMotions::Measures::none);
    EXPECT_THROW(unpack_scaling_measures(s, std::vector<double>(3)), std::invalid_argument);
    EXPECT_THROW(unpack_made_measures(s, 0, std::vector<double>(5)), std::invalid_argument);
    EXPECT_THROW(pack_made_measures(s, 0, 1), std::invalid_argument);  // not measured yet
}
