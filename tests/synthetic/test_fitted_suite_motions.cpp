// Motions fitted to each record of a suite (suite --synthetic-per-record): motion i of record k
// is the same bits whatever the number per record, is `synth`'s motion i of the record's
// derived seed, and differs between records and between suite seeds.
#include <gtest/gtest.h>

#include <vector>

#include "rocksweep/synthetic/fitted_suite_motions.hpp"

using namespace rocksweep;
using namespace rocksweep::synthetic;

namespace {

constexpr double dt = 0.01;

Generator model(double f_mid_hz) {
    const ModelParameters p{.arias_m_s = 0.4, .d595_s = 6.0, .tmid_s = 4.0, .f_mid_hz = f_mid_hz, .f_slope_hz_s = -0.1,
                            .zeta_f = 0.3};
    return Generator(p, dt, default_duration_s(p));
}

// Two records of the suite; `same` gives both the same model, so that only their seeds differ.
FittedSuiteMotions suite(std::uint64_t seed, std::size_t per_record, bool same = false) {
    std::vector<FittedRecord> records;
    records.push_back({"loma", model(4.0)});
    records.push_back({"spitak", model(same ? 4.0 : 3.0)});
    return FittedSuiteMotions(std::move(records), seed, per_record);
}

}  // namespace

TEST(FittedSuiteMotions, MotionOfARecordDoesNotDependOnTheCount) {
    const FittedSuiteMotions three = suite(7, 3), five = suite(7, 5);
    ASSERT_EQ(three.size(), 6u);
    ASSERT_EQ(five.size(), 10u);
    for (std::size_t k = 0; k < 2; ++k)
        for (std::size_t i = 0; i < 3; ++i) {
            const Record a = three.motion(k * 3 + i), b = five.motion(k * 5 + i);
            EXPECT_EQ(three.name(k * 3 + i), five.name(k * 5 + i));
            EXPECT_EQ(a.path, b.path);
            ASSERT_EQ(a.ax_g, b.ax_g) << "record " << k << ", motion " << i;  // bit for bit
        }
    EXPECT_EQ(five.name(6), "spitak_s000001");
    EXPECT_EQ(five.record_of(6), 1u);
}

TEST(FittedSuiteMotions, IsTheRecordsModelDrawnWithItsDerivedSeed) {
    const FittedSuiteMotions m = suite(7, 4);
    const Generator spitak = model(3.0);
    const std::uint64_t s1 = record_seed(7, 1);
    // What `synth --record <spitak> --seed s1` writes as motion 2.
    const Record expected = spitak.record(s1, 2), got = m.motion(4 + 2);
    EXPECT_EQ(got.ax_g, expected.ax_g);
    EXPECT_EQ(got.path, expected.path + ":spitak");
    EXPECT_EQ(got.path, "synthetic:" + std::to_string(s1) + ":2:spitak");
    // What a suite keeps of it without making it (MotionSource::described).
    const Record kept = m.described(4 + 2);
    EXPECT_TRUE(kept.ax_g.empty());
    EXPECT_EQ(kept.path, got.path);
    EXPECT_EQ(kept.units, got.units);
    EXPECT_EQ(kept.dt_s, got.dt_s);
    EXPECT_EQ(kept.npts, got.npts);
}

TEST(FittedSuiteMotions, DiffersBetweenRecordsAndSeeds) {
    // The same model for both records: motion 0 of each differs by its seed alone.
    const FittedSuiteMotions a = suite(7, 2, true), b = suite(8, 2, true);
    EXPECT_NE(a.motion(0).ax_g, a.motion(2).ax_g);
    EXPECT_NE(a.motion(0).ax_g, b.motion(0).ax_g);
    EXPECT_NE(a.motion(2).ax_g, b.motion(2).ax_g);
    EXPECT_NE(a.motion(0).ax_g, a.motion(1).ax_g);
    // seed + record would collide here: record 1 of seed 1 and record 0 of seed 2.
    EXPECT_NE(record_seed(1, 1), record_seed(2, 0));
    EXPECT_NE(record_seed(1, 0), record_seed(0, 1));
    // 62 bits: synth --seed takes every one.
    for (std::uint64_t s : {0ull, 1ull, 7ull, ~0ull})
        for (std::size_t k : {0u, 1u, 1000u}) EXPECT_LT(record_seed(s, k), 1ull << 62);
}
