// Recorded ground motions: reading, units, the piecewise-linear ground, and the kernel's
// guarantees (mirror symmetry, batch = scalar) on a real record.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "rocksweep/anchorage.hpp"
#include "rocksweep/errors.hpp"
#include "rocksweep/history.hpp"
#include "rocksweep/integrator.hpp"
#include "rocksweep/record.hpp"

using namespace rocksweep;

namespace {

const Block kBlock = rectangular_block(0.30, 1.36, 3361.0);
const std::string kRecords = ROCKSWEEP_RECORDS_DIR;

std::string write_file(const std::string& name, const std::string& text) {
    const std::string path = ::testing::TempDir() + name;
    std::ofstream(path) << text;
    return path;
}

}  // namespace

TEST(Record, ElCentroInGAndSylmarInMetresPerSecondSquared) {
    const Pulse ec = read_record(kRecords + "/elcentro_1940_NS.dat", "g", 1.0, 9.81);
    ASSERT_EQ(ec.record->size(), 2688u);
    EXPECT_DOUBLE_EQ(ec.record_dt_s, 0.02);
    EXPECT_NEAR(ec.peak_ax(), 0.349 * 9.80665 / 9.81, 2e-3);  // README: peak 0.349 g
    const Pulse nr = read_record(kRecords + "/northridge_1994_sylmar.dat", "m/s^2", 1.0, 9.81);
    EXPECT_EQ(nr.record->size(), 3000u);
    EXPECT_NEAR(nr.peak_ax(), 8.27 / 9.81, 2e-3);  // README: peak 8.27 m/s^2
}

TEST(Record, LinearBetweenSamplesWithZerosAndSamplesAsTimeEvents) {
    const std::string path = write_file("ramp.dat", "0 0\n0.5 1\n1.0 -1\n1.5 -1\n");
    const Pulse p = read_record(path, "m/s^2", 2.0, 10.0);  // scaled by 2, over g = 10
    EXPECT_DOUBLE_EQ(p.end_time(), 1.5);
    EXPECT_DOUBLE_EQ(p.ax(0.25), 0.1);
    EXPECT_DOUBLE_EQ(p.ax(0.75), 0.0);
    EXPECT_DOUBLE_EQ(p.next_ax_zero(0.1), 0.75);
    EXPECT_EQ(p.next_ax_zero(0.8), INFINITY);
    EXPECT_DOUBLE_EQ(p.next_sample(0.5), 1.0);
    EXPECT_DOUBLE_EQ(p.next_sample(0.49), 0.5);
}

TEST(Record, BadFilesNameTheFileAndLine) {
    EXPECT_THROW(read_record(write_file("bad1.dat", "0 0\n0.02 x\n"), "g", 1, 9.81), InputError);
    EXPECT_THROW(read_record(write_file("bad2.dat", "0 0\n0.02 1\n0.05 1\n"), "g", 1, 9.81), InputError);
    EXPECT_THROW(read_record(write_file("bad3.dat", "0.1 0\n0.2 1\n"), "g", 1, 9.81), InputError);
    EXPECT_THROW(read_record(write_file("bad4.dat", "0 0\n"), "g", 1, 9.81), InputError);
    EXPECT_THROW(read_record(kRecords + "/elcentro_1940_NS.dat", "gal", 1, 9.81), InputError);
    try {
        read_record(write_file("bad5.dat", "0 0\n0.02 1 7\n"), "g", 1, 9.81);
        FAIL();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("line 2"), std::string::npos) << e.what();
    }
}

TEST(Record, MirroredRecordGivesMirroredMotionAndBatchEqualsScalar) {
    const Pulse ec = read_record(kRecords + "/northridge_1994_sylmar.dat", "m/s^2", 0.5, 9.81);
    Pulse neg = ec;
    std::vector<double> flipped(*ec.record);
    for (double& a : flipped) a = -a;
    neg.record = std::make_shared<const std::vector<double>>(flipped);
    const double fu = 0.4 * kBlock.mass_kg * kBlock.gravity;
    std::vector<CellModel> cells;
    for (const Anchorage& a : {free_anchorage(), constant_anchorage(kBlock, fu, kBlock.alpha_rad / 2),
                               adaptive_anchorage(kBlock, fu, kBlock.alpha_rad, 0.1)}) {
        const CellModel m = make_cell_model(kBlock, a, ec), n = make_cell_model(kBlock, a, neg);
        const History h = sample_history(m, {}, 0.01, 30.0), g = sample_history(n, {}, 0.01, 30.0);
        ASSERT_EQ(h.t.size(), g.t.size());
        for (std::size_t i = 0; i < h.t.size(); ++i) ASSERT_EQ(h.theta[i], -g.theta[i]) << "t = " << h.t[i];
        EXPECT_GT(h.result.max_rotation, 0.01);  // it rocks
        cells.push_back(m);
        Pulse sine;
        sine.omega = 3 * kBlock.p();
        sine.ax_g = 2.5 * kBlock.alpha_rad;
        cells.push_back(make_cell_model(kBlock, a, sine));  // mixed with pulses in one batch
    }
    std::vector<CellResult> batch(cells.size());
    integrate_cells(cells, batch, {}, 8);
    for (std::size_t i = 0; i < cells.size(); ++i) EXPECT_TRUE(bitwise_equal(batch[i], integrate_cell(cells[i], {}))) << i;
}
