// Recorded ground motions: every shared record read in its own format and unit, the
// piecewise-linear ground, and the kernel's guarantees (mirror symmetry, batch = scalar) on a
// real record. Malformed files: test_record_malformed.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "test_support.hpp"
#include "rocksweep/physics/anchorage.hpp"
#include "rocksweep/core/errors.hpp"
#include "rocksweep/physics/history.hpp"
#include "rocksweep/physics/integrator.hpp"
#include "rocksweep/records/intensity.hpp"
#include "rocksweep/records/record.hpp"

using namespace rocksweep;
using rocksweep::testing::write_file;

namespace {

const Block kBlock = rectangular_block(0.30, 1.36, 3361.0);
const std::string kRecords = ROCKSWEEP_RECORDS_DIR;

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

namespace {

// The README's table (tests/data/README.md): samples, dt, unit and peak of each file. Peaks
// given to three figures must match within 0.5 %; the Mexico City peaks, given to two
// decimals (0.10, 0.17, 0.04 g), within half their last digit, 0.005 g.
struct Shared {
    const char* file;
    RecordFormat format;
    const char* units;
    int column;
    std::size_t npts;
    double dt_s, peak;  // peak in the file's unit
    double tolerance;   // of the peak: relative, or absolute in the file's unit
    bool relative;
};

const Shared kShared[] = {
    {"elcentro_1940_NS.dat", RecordFormat::time_accel, "g", 0, 2688, 0.02, 0.349, 0.005, true},
    {"northridge_1994_sylmar.dat", RecordFormat::time_accel, "m/s^2", 0, 3000, 0.02, 8.27, 0.005, true},
    {"cape_mendocino_1992.dat", RecordFormat::time_accel, "m/s^2", 0, 1500, 0.02, 10.19, 0.005, true},
    {"kocaeli_1999.dat", RecordFormat::time_accel, "m/s^2", 0, 3400, 0.02, 3.08, 0.005, true},
    {"loma_prieta_1989.dat", RecordFormat::time_accel, "m/s^2", 0, 1300, 0.02, 5.32, 0.005, true},
    {"san_fernando_1971.dat", RecordFormat::time_accel, "m/s^2", 0, 1500, 0.02, 2.65, 0.005, true},
    {"spitak_1988.dat", RecordFormat::time_accel, "m/s^2", 0, 906, 0.02, 1.88, 0.005, true},
    {"san_salvador_1986_gic090.txt", RecordFormat::time_accel, "m/s^2", 0, 1815, 0.005, 6.91, 0.005, true},
    {"cephalonia_2014_chv1_E.txt", RecordFormat::time_accel, "cm/s^2", 0, 13549, 0.005, 741, 0.005, true},
    {"mexico_city_1985_sct.txt", RecordFormat::time_accel, "g", 2, 8171, 0.02, 0.10, 0.005, false},
    {"mexico_city_1985_sct.txt", RecordFormat::time_accel, "g", 3, 8171, 0.02, 0.17, 0.005, false},
    {"mexico_city_1985_sct.txt", RecordFormat::time_accel, "g", 4, 8171, 0.02, 0.04, 0.005, false},
    {"RSN1044_northridge_1994_newhall_rot.AT2", RecordFormat::at2, "", 0, 2000, 0.02, 0.70, 0.005, true},
};

}  // namespace

TEST(Record, EverySharedRecordInItsUnitMatchesTheReadmeTable) {
    for (const Shared& e : kShared) {
        SCOPED_TRACE(std::string(e.file) + " column " + std::to_string(e.column));
        RecordSource s;
        s.path = kRecords + "/" + e.file;
        s.format = e.format;
        s.units = e.units;
        s.column = e.column;
        const Record r = read_record(s);
        EXPECT_EQ(r.npts, e.npts);
        EXPECT_NEAR(r.dt_s, e.dt_s, 1e-12 * e.dt_s);
        const double to_g = units_to_g("units", r.units);
        const double peak = intensity_measures(r).pga_g / to_g;  // back in the file's unit
        EXPECT_NEAR(peak, e.peak, e.relative ? e.tolerance * e.peak : e.tolerance);
        EXPECT_TRUE(r.ay_g.empty());
    }
}

TEST(Record, At2TakesUnitAndStepFromItsHeader) {
    RecordSource s;
    s.path = kRecords + "/RSN1044_northridge_1994_newhall_rot.AT2";
    s.format = RecordFormat::at2;
    const Record r = read_record(s);
    EXPECT_EQ(r.units, "g");
    EXPECT_EQ(r.npts, 2000u);
    EXPECT_EQ(r.ax_g.size(), 2000u);
    EXPECT_DOUBLE_EQ(r.dt_s, 0.02);
    EXPECT_DOUBLE_EQ(r.ax_g[0], -1.65951E-03);  // first sample, line 5
    EXPECT_DOUBLE_EQ(r.ax_g[7], 1.16242E-03);   // third of line 6: five a line
    EXPECT_DOUBLE_EQ(r.ax_g.back(), 5.52437E-05);
    s.units = "g";  // agreeing with the header is allowed
    EXPECT_EQ(read_record(s).npts, 2000u);
}

TEST(Record, MexicoCityStartsAtOneStepAndTheGroundIsAtRestBeforeIt) {
    RecordSource s;
    s.path = kRecords + "/mexico_city_1985_sct.txt";
    s.units = "g";
    s.column = 3;
    s.vertical = VerticalSource{"", 4};
    const Record r = read_record(s);
    EXPECT_TRUE(r.zero_prepended);
    EXPECT_EQ(r.npts, 8171u);
    ASSERT_EQ(r.ax_g.size(), 8172u);
    ASSERT_EQ(r.ay_g.size(), 8172u);
    EXPECT_EQ(r.ax_g[0], 0.0);
    EXPECT_EQ(r.ay_g[0], 0.0);
    EXPECT_DOUBLE_EQ(r.ax_g[1], -0.00314);  // t = 0.02 s, column 3
    EXPECT_DOUBLE_EQ(r.ay_g[1], 0.00018);   // column 4
    EXPECT_DOUBLE_EQ(r.ax_g.back(), -0.00305);
    EXPECT_NEAR(r.duration_s(), 163.42, 1e-9);
    EXPECT_EQ(r.vertical_path, s.path);
    EXPECT_EQ(r.vertical_column, 4);
    const Pulse p = to_pulse(r, 9.81);
    EXPECT_DOUBLE_EQ(p.end_time(), r.duration_s());
    EXPECT_DOUBLE_EQ(p.ax(0.01), 0.5 * -0.00314 * standard_gravity / 9.81);  // the ramp from rest
}

TEST(Record, AccelOnlyColumnsWithAGivenStepAndAVerticalSecondFile) {
    const std::string h = write_file("h.csv", "# two components, no time\n0.1, 7\n-0.2, 7\n0.3, 7\n");
    const std::string v = write_file("v.txt", "5 0.01\n5 0.02\n");  // shorter: padded with rest
    RecordSource s;
    s.path = h;
    s.format = RecordFormat::accel_only;
    s.units = "m/s^2";
    s.dt_s = 0.01;
    s.scale = -2.0;
    s.vertical = VerticalSource{v, 2};
    const Record r = read_record(s);
    EXPECT_FALSE(r.zero_prepended);
    EXPECT_DOUBLE_EQ(r.dt_s, 0.01);
    ASSERT_EQ(r.ax_g.size(), 3u);
    EXPECT_DOUBLE_EQ(r.ax_g[1], 0.4 / standard_gravity);
    ASSERT_EQ(r.ay_g.size(), 3u);
    EXPECT_DOUBLE_EQ(r.ay_g[1], -0.04 / standard_gravity);
    EXPECT_EQ(r.ay_g[2], 0.0);
    s.column = 2;
    s.vertical.reset();
    EXPECT_DOUBLE_EQ(read_record(s).ax_g[2], -14.0 / standard_gravity);
}

TEST(Record, HeaderLinesSkippedOnRequestAndGalsConverted) {
    const std::string path = write_file("header.csv", "time,acc\n0.0,100\n0.01,-50\n");
    RecordSource s;
    s.path = path;
    s.units = "cm/s^2";
    s.skip_lines = 1;
    const Record r = read_record(s);
    EXPECT_DOUBLE_EQ(r.ax_g[0], 1.0 / standard_gravity);
    EXPECT_DOUBLE_EQ(r.ax_g[1], -0.5 / standard_gravity);
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
