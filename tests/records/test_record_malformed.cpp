// Malformed and physically absurd record files (issues 7 and 9): each refused with one message
// naming the option, the file and line, and what was expected. The files are written here, into
// the test's temporary directory.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "test_support.hpp"
#include "rocksweep/core/errors.hpp"
#include "rocksweep/records/record.hpp"

using namespace rocksweep;
using rocksweep::testing::write_file;

namespace {

RecordSource time_accel(const std::string& path, const std::string& units = "g") {
    RecordSource s;
    s.path = path;
    s.units = units;
    return s;
}

// The message the command line would print, or "accepted".
std::string message(const RecordSource& s) {
    return rocksweep::testing::message_of([&] { read_record(s); });
}

const std::string kTimes = " (times must increase evenly)";

}  // namespace

TEST(RecordMalformed, TimesThatGoBackOrStandStillNameTheLine) {
    const std::string p = write_file("back.dat", "0 0\n0.02 1\n# a comment line counts\n0.04 2\n0.03 1\n");
    EXPECT_EQ(message(time_accel(p)),
              "--record = " + p + " line 5 is invalid: time 0.03 s is not after the previous 0.04 s" + kTimes);
    // issue 7: all times 0 used to give dt = 0, an empty history, then a segfault
    const std::string z = write_file("zero.dat", "0 0\n0 1\n0 2\n");
    EXPECT_EQ(message(time_accel(z)), "--record = " + z + " line 2 is invalid: time 0 s is not after the previous 0 s" + kTimes);
}

TEST(RecordMalformed, UnevenTimesNameTheLineWhereTheGridBreaks) {
    const std::string p = write_file("gap.dat", "0 0\n0.02 1\n0.05 1\n0.07 1\n");
    EXPECT_EQ(message(time_accel(p)),
              "--record = " + p +
                  " line 3 is invalid: time 0.05 s is 0.03 s after the previous 0.02 s where the first step is 0.02 s" + kTimes);
    // every step within 1 % of the first (0.5 % long, then 0.5 % short), but by the fourth
    // step 0.0003 s (1.5 % of dt) off the grid of their mean step 0.02 s
    std::string drift = "0 0\n0.02 0\n";
    for (int i = 1; i <= 40; ++i)
        drift += std::to_string(0.02 + 0.0201 * std::min(i, 20) + 0.0199 * std::max(i - 20, 0)) + " 0\n";
    const std::string d = write_file("drift.dat", drift);
    EXPECT_EQ(message(time_accel(d)),
              "--record = " + d + " line 5 is invalid: time 0.0803 s has drifted off the grid of step 0.02 s" + kTimes);
    const std::string late = write_file("late.dat", "0.5 0\n0.52 1\n0.54 1\n");
    EXPECT_EQ(message(time_accel(late)), "--record = " + late +
                                             " line 1 is invalid: the first time 0.5 s is neither 0 nor the step 0.02 s (a "
                                             "record starts with the ground at rest)");
}

TEST(RecordMalformed, WrongColumnCountTextAndNonFiniteNumbers) {
    const std::string cols = write_file("cols.dat", "0 0\n0.02 1 7\n");
    EXPECT_EQ(message(time_accel(cols)),
              "--record = " + cols + " line 2 is invalid: 3 columns where line 1 has 2 (every line needs the same columns)");
    const std::string text = write_file("text.dat", "0 0\n0.02 1.5x\n");
    EXPECT_EQ(message(time_accel(text)), "--record = " + text + " line 2 is invalid: '1.5x' (column 2) is not a number");
    const std::string nan = write_file("nan.dat", "0 0\n0.02 nan\n");
    EXPECT_EQ(message(time_accel(nan)), "--record = " + nan + " line 2 is invalid: 'nan' (column 2) is not a finite number");
    const std::string gap = write_file("gapcell.csv", "0,0\n0.02,,1\n");
    EXPECT_EQ(message(time_accel(gap)),
              "--record = " + gap + " line 2 is invalid: 3 columns where line 1 has 2 (every line needs the same columns)");
    const std::string empty_cell = write_file("emptycell.csv", "0,0\n0.02,\n");
    EXPECT_EQ(message(time_accel(empty_cell)),
              "--record = " + empty_cell + " line 2 is invalid: column 2 is empty (a number was expected)");
}

TEST(RecordMalformed, EmptyOrSingleSampleFilesAndUnreadablePaths) {
    const std::string e = write_file("empty.dat", "");
    EXPECT_EQ(message(time_accel(e)), "--record = " + e + " is invalid: at least two samples (found 0)");
    const std::string one = write_file("one.dat", "# header only\n0 0.1\n");
    EXPECT_EQ(message(time_accel(one)), "--record = " + one + " is invalid: at least two samples (found 1)");
    const std::string none = rocksweep::testing::temp_dir() + "no_such_record.dat";
    EXPECT_EQ(message(time_accel(none)), "--record = " + none + " is invalid: a readable record file (it cannot be opened)");
}

TEST(RecordMalformed, SamplingIntervalOutsideTheSaneRange) {
    const std::string allowed = " is outside 1e-05 s <= dt <= 1 s (strong-motion records are sampled at 1 Hz to 100 kHz)";
    // issue 7: dt = 1e6 s used to allocate until bad_alloc
    const std::string slow = write_file("slow.dat", "0 0\n1e6 1\n2e6 0\n");
    EXPECT_EQ(message(time_accel(slow)), "--record = " + slow + " is invalid: a sampling interval of 1000000 s" + allowed);
    const std::string fast = write_file("fast.dat", "0 0\n1e-7 1\n2e-7 0\n");
    EXPECT_EQ(message(time_accel(fast)), "--record = " + fast + " is invalid: a sampling interval of 1e-07 s" + allowed);
    RecordSource s = time_accel(write_file("accel.dat", "0.1\n0.2\n"));
    s.format = RecordFormat::accel_only;
    EXPECT_EQ(message(s), "--record-dt = (missing) is invalid: the sampling interval [s] of " + s.path +
                              " (an accel_only file has no time column)");
    s.dt_s = 1e6;
    EXPECT_EQ(message(s), "--record-dt = 1000000 is invalid: a sampling interval of 1000000 s" + allowed);
    s.dt_s = 0.01;
    EXPECT_EQ(message(s), "accepted");
    RecordSource timed = time_accel(write_file("timed.dat", "0 0\n0.02 1\n"));
    timed.dt_s = 0.01;  // a given dt must agree with the time column
    EXPECT_EQ(message(timed),
              "--record-dt = 0.01 is invalid: the step of " + timed.path + "'s time column, 0.02 s (or not given)");
}

TEST(RecordMalformed, AbsurdAmplitudesAreRefusedWithTheirLine) {
    // issue 7: 1e300 g samples were accepted with exit 0
    const std::string huge = write_file("huge.dat", "0 0\n0.02 1e300\n");
    EXPECT_EQ(message(time_accel(huge)), "--record = " + huge +
                                             " line 2 is invalid: sample 1e+300 g (scale 1) is 1e+300 g, beyond the physical "
                                             "bound |a| <= 20 g (wrong unit or column?)");
    // cm/s^2 read as g is 100 times too strong: 741 gal as "g" is caught
    RecordSource gal = time_accel(write_file("gal.dat", "0 0\n0.005 741\n"), "g");
    EXPECT_NE(message(gal).find("line 2 is invalid: sample 741 g (scale 1) is 741 g, beyond"), std::string::npos) << message(gal);
    gal.units = "cm/s^2";
    EXPECT_EQ(message(gal), "accepted");
    RecordSource scaled = time_accel(write_file("scaled.dat", "0 0\n0.02 -0.5\n"));
    scaled.scale = 50.0;
    EXPECT_EQ(message(scaled), "--record = " + scaled.path +
                                   " line 2 is invalid: sample -0.5 g (scale 50) is -25 g, beyond the physical bound |a| <= 20 g "
                                   "(wrong unit or column?)");
    scaled.scale = 0.0;
    EXPECT_EQ(message(scaled), "--record-scale = 0 is invalid: a finite, non-zero factor");
}

TEST(RecordMalformed, UnitsAreNeverGuessed) {
    const std::string p = write_file("units.dat", "0 0\n0.02 0.1\n");
    EXPECT_EQ(message(time_accel(p, "")),
              "--record-units = (missing) is invalid: g, m/s^2 or cm/s^2 (the unit of the record's samples; never guessed)");
    EXPECT_EQ(message(time_accel(p, "gal")),
              "--record-units = gal is invalid: g, m/s^2 or cm/s^2 (the unit of the record's samples; never guessed)");
}

TEST(RecordMalformed, CommaSeparatedFilesAreAccepted) {
    const std::string p = write_file("commas.csv", "0,0.0\n0.02 , 0.5\r\n0.04,+1e-1\n");
    const Record r = read_record(time_accel(p));
    ASSERT_EQ(r.ax_g.size(), 3u);
    EXPECT_DOUBLE_EQ(r.ax_g[1], 0.5);
    EXPECT_DOUBLE_EQ(r.ax_g[2], 0.1);
}

TEST(RecordMalformed, ColumnsThatTheFileDoesNotHave) {
    RecordSource s = time_accel(write_file("two.dat", "0 0\n0.02 0.1\n"));
    s.column = 5;
    EXPECT_EQ(message(s), "--record-column = 5 is invalid: a column of " + s.path + ", 1 to 2 (line 1 has 2)");
    s.column = 1;
    EXPECT_EQ(message(s), "--record-column = 1 is invalid: 2 or more: column 1 of a time_accel file is the time");
    s.column = 0;
    s.vertical = VerticalSource{"", 3};
    EXPECT_EQ(message(s), "--record-vertical-column = 3 is invalid: a column of " + s.path + ", 1 to 2 (line 1 has 2)");
    s.vertical = VerticalSource{"", 0};
    EXPECT_EQ(message(s),
              "--record-vertical-column = (missing) is invalid: the column of " + s.path + " holding the vertical component");
    s.vertical = VerticalSource{"", 2};  // column 0 is the default, 2: one column cannot be both components
    EXPECT_EQ(message(s), "--record-vertical-column = 2 is invalid: a column other than the horizontal component's (2) of " +
                              s.path);
    s.vertical = VerticalSource{write_file("v_other_step.dat", "0 0\n0.01 0.1\n0.02 0\n"), 0};
    EXPECT_EQ(message(s), "--record-vertical = " + s.vertical->path +
                              " is invalid: a component on the horizontal's grid (dt 0.02 s from t = 0 s)");
}

namespace {

std::string at2(const std::string& kind, const std::string& sizes, const std::string& samples) {
    return "PEER NGA STRONG MOTION DATABASE RECORD\nTEST, 1 JAN 2000\n" + kind + "\n" + sizes + "\n" + samples;
}

RecordSource at2_source(const std::string& path) {
    RecordSource s;
    s.path = path;
    s.format = RecordFormat::at2;
    return s;
}

}  // namespace

TEST(RecordMalformed, At2HeadersAndSampleCounts) {
    const std::string kind = "ACCELERATION TIME SERIES IN UNITS OF G";
    const std::string six = "1.0E-02 2.0E-02 3.0E-02 4.0E-02 5.0E-02\n6.0E-02\n";
    const std::string short_file = write_file("short.AT2", at2(kind, "NPTS=     7, DT=   .0100 SEC", six));
    EXPECT_EQ(message(at2_source(short_file)),
              "--record = " + short_file + " is invalid: 6 samples after the header where line 4 says NPTS = 7");
    // the older NGA header: "NPTS, DT" after the numbers
    const std::string old = write_file("old.AT2", at2(kind, "     6    0.0100    NPTS, DT", six));
    const Record r = read_record(at2_source(old));
    EXPECT_DOUBLE_EQ(r.dt_s, 0.01);
    EXPECT_DOUBLE_EQ(r.ax_g[5], 0.06);
    const std::string gal =
        write_file("gal.AT2", at2("ACCELERATION TIME SERIES IN UNITS OF CM/S/S", "NPTS= 6, DT= 0.01 SEC", six));
    EXPECT_EQ(read_record(at2_source(gal)).units, "cm/s^2");
    const std::string vel = write_file("vel.VT2", at2("VELOCITY TIME SERIES IN UNITS OF CM/S", "NPTS= 6, DT= 0.01 SEC", six));
    EXPECT_EQ(message(at2_source(vel)), "--record = " + vel +
                                            " line 3 is invalid: 'VELOCITY TIME SERIES IN UNITS OF CM/S' does not state an "
                                            "acceleration unit (a PEER .AT2 says 'ACCELERATION TIME SERIES IN UNITS OF G')");
    const std::string no_sizes = write_file("nosizes.AT2", at2(kind, "DT= 0.01 SEC", six));
    EXPECT_EQ(message(at2_source(no_sizes)),
              "--record = " + no_sizes +
                  " line 4 is invalid: 'DT= 0.01 SEC' does not give NPTS and DT (e.g. 'NPTS=  2000, DT=   0.020 SEC')");
    const std::string text =
        write_file("text.AT2", at2(kind, "NPTS= 6, DT= 0.01 SEC", "1.0E-02 2.0E-02 3.0E-02 4.0E-02 5.0E-02\n6.0E-O2\n"));
    EXPECT_EQ(message(at2_source(text)), "--record = " + text + " line 6 is invalid: '6.0E-O2' (column 1) is not a number");
    const std::string slow = write_file("slow.AT2", at2(kind, "NPTS= 6, DT= 5.0 SEC", six));
    EXPECT_EQ(message(at2_source(slow)), "--record = " + slow +
                                             " line 4 is invalid: a sampling interval of 5 s is outside 1e-05 s <= dt <= 1 s "
                                             "(strong-motion records are sampled at 1 Hz to 100 kHz)");
    RecordSource conflict = at2_source(old);
    conflict.units = "m/s^2";
    EXPECT_EQ(message(conflict),
              "--record-units = m/s^2 is invalid: the unit " + old + " states, g (or none: an .AT2 gives its own)");
    // a vertical .AT2 beside it: same step, padded with rest if shorter; its unit must agree
    RecordSource with_vertical = at2_source(old);
    with_vertical.vertical = VerticalSource{write_file("up.AT2", at2(kind, "NPTS= 2, DT= 0.01 SEC", "0.5 -0.5\n")), 0};
    const Record both = read_record(with_vertical);
    ASSERT_EQ(both.ay_g.size(), 6u);
    EXPECT_DOUBLE_EQ(both.ay_g[1], -0.5);
    EXPECT_EQ(both.ay_g[2], 0.0);
    with_vertical.vertical = VerticalSource{gal, 0};
    EXPECT_EQ(message(with_vertical),
              "--record-vertical = " + gal + " is invalid: an .AT2 in g like the horizontal component (it states cm/s^2)");
    with_vertical.vertical = VerticalSource{"", 2};
    EXPECT_EQ(message(with_vertical), "--record-vertical = (a column) is invalid: a second .AT2 file, without a column");
    const std::string truncated = write_file("truncated.AT2", "PEER NGA\nTEST\n");
    EXPECT_EQ(
        message(at2_source(truncated)),
        "--record = " + truncated + " is invalid: a PEER .AT2 file: four header lines, then the samples (it ends on line 2)");
}
