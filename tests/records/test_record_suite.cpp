// Suite files (docs/records.md): the shipped configs/records_suite.csv reads every shared record,
// and each malformed suite is refused with one message naming the file and line.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "test_support.hpp"
#include "rocksweep/core/errors.hpp"
#include "rocksweep/records/record_suite.hpp"

using namespace rocksweep;
using rocksweep::testing::write_file;

namespace {

const std::string kDir = rocksweep::testing::temp_dir();

// The message the command line would print, or "accepted".
std::string message(const std::string& suite_text) {
    write_file("quake.dat", "0 0\n0.01 0.1\n0.02 0\n");
    const std::string path = write_file("suite.csv", suite_text);
    return rocksweep::testing::message_of([&] { read_record_suite(path); });
}

const std::string kHeader = "name,file,format,units,dt\n";

std::string at_line(int n) { return "--suite = " + kDir + "suite.csv line " + std::to_string(n) + " is invalid: "; }

}  // namespace

TEST(RecordSuite, ShippedSuiteReadsEverySharedRecordWithItsMetadata) {
    const RecordSuite suite = read_record_suite(ROCKSWEEP_CONFIGS_DIR "/records_suite.csv");
    ASSERT_EQ(suite.records.size(), 12u);  // 11 files, Mexico City's two horizontal components
    EXPECT_EQ(suite.metadata_columns, (std::vector<std::string>{"event", "station", "component"}));
    for (const SuiteRecord& r : suite.records) {
        SCOPED_TRACE(r.name);
        ASSERT_EQ(r.metadata.size(), 3u);
        EXPECT_FALSE(r.metadata[0].empty());
        const Record rec = read_record(r.source);
        EXPECT_GE(rec.duration_s(), 9.0);  // the shortest, San Salvador, is 9.07 s
        EXPECT_EQ(rec.ay_g.empty(), r.name.rfind("mexico", 0) != 0);
    }
    const SuiteRecord& newhall = suite.records[2];
    EXPECT_EQ(newhall.name, "newhall_1994_rot");
    EXPECT_EQ(newhall.source.format, RecordFormat::at2);
    EXPECT_EQ(newhall.metadata[2], "rotated 68.8 deg, clockwise from NWH090");  // a quoted comma
    EXPECT_EQ(read_record(newhall.source).units, "g");
    const SuiteRecord& mexico = suite.records[11];
    EXPECT_EQ(mexico.source.column, 3);
    EXPECT_EQ(mexico.source.vertical->column, 4);
    EXPECT_EQ(mexico.line, 16);
    EXPECT_TRUE(std::filesystem::equivalent(mexico.source.path, ROCKSWEEP_RECORDS_DIR "/mexico_city_1985_sct.txt"));
}

TEST(RecordSuite, SpreadsheetExportsAreRead) {
    // Excel's UTF-8 mark and CRLF, quotes with "" inside, blanks around cells, defaults for
    // empty cells, an absolute path
    write_file("quake.dat", "0 0\n0.01 0.1\n");
    const std::string abs = write_file("abs.dat", "0,0\n0.01,1\n");
    const std::string path = write_file("sheet.csv",
                                        "\xEF\xBB\xBFname, file ,format,units,scale,magnitude,note\r\n"
                                        "a,quake.dat,time_accel,g,,6.5,\"the \"\"main\"\" shock, N\"\r\n"
                                        "b," +
                                            abs + ",time_accel,cm/s^2,-2,,\r\n");
    const RecordSuite s = read_record_suite(path);
    ASSERT_EQ(s.records.size(), 2u);
    EXPECT_EQ(s.metadata_columns, (std::vector<std::string>{"magnitude", "note"}));
    EXPECT_EQ(s.records[0].metadata, (std::vector<std::string>{"6.5", "the \"main\" shock, N"}));
    EXPECT_EQ(s.records[0].source.scale, 1.0);
    EXPECT_EQ(s.records[0].source.path, kDir + "quake.dat");
    EXPECT_EQ(s.records[1].source.scale, -2.0);
    EXPECT_EQ(s.records[1].source.path, abs);
    EXPECT_EQ(s.records[1].metadata, (std::vector<std::string>{"", ""}));
}

TEST(RecordSuite, RowsThatCannotBeReadAreRefusedNamingTheLine) {
    EXPECT_EQ(message(kHeader + "a,quake.dat,time_accel,g,\na,quake.dat,time_accel,g,\n"),
              at_line(3) + "name 'a' is already used on an earlier line");
    EXPECT_EQ(message(kHeader + "a,nope.dat,time_accel,g,\n"),
              at_line(2) + "file 'nope.dat' does not exist (looked for " + kDir + "nope.dat)");
    EXPECT_EQ(message(kHeader + "a,,time_accel,g,\n"),
              at_line(2) + "file is empty (the record's file, relative to the suite file)");
    EXPECT_EQ(message(kHeader + "a,quake.dat,time_accel,gal,\n"),
              at_line(2) + "units 'gal' is not g, m/s^2 or cm/s^2 (only an at2 file may leave it empty)");
    EXPECT_EQ(message(kHeader + "a,quake.dat,time_accel,,\n"),
              at_line(2) + "units '' is not g, m/s^2 or cm/s^2 (only an at2 file may leave it empty)");
    EXPECT_EQ(message(kHeader + "a,quake.dat,peer,g,\n"), at_line(2) + "format 'peer' is not time_accel, accel_only or at2");
    EXPECT_EQ(message(kHeader + "a,quake.dat,accel_only,g,\n"),
              at_line(2) + "dt is needed for an accel_only record (it has no time column)");
    EXPECT_EQ(message(kHeader + "a,quake.dat,accel_only,g,0.0x\n"), at_line(2) + "dt '0.0x' is not a finite number");
    EXPECT_EQ(message(kHeader + "a,quake.dat,accel_only,g,1e6\n"), at_line(2) + "dt 1000000 s is outside 1e-05 to 1 s");
    EXPECT_EQ(message(kHeader + "a/b,quake.dat,time_accel,g,\n"),
              at_line(2) + "name 'a/b' must be letters, digits, '_', '-' or '.' (it names the record in the output)");
    EXPECT_EQ(message("name,file,format,units,column\na,quake.dat,time_accel,g,2.5\n"),
              at_line(2) + "column '2.5' is not a whole number >= 1");
    EXPECT_EQ(message("name,file,format,units,column\na,quake.dat,time_accel,g,0\n"),
              at_line(2) + "column '0' is not a whole number >= 1");  // columns count from 1; empty is the default
    EXPECT_EQ(message(kHeader + "a,quake.dat,time_accel,g\n"), at_line(2) + "4 cells where the header has 5");
    EXPECT_EQ(message(kHeader + "a,quake.dat,time_accel,\"g,\n"),
              at_line(2) + "a quote that is not closed (cells cannot span lines)");
    EXPECT_EQ(message(kHeader + "a,quake.dat,time_accel,\"g\"x,\n"), at_line(2) + "text after the closing quote of cell 4");
    EXPECT_EQ(message(kHeader + "a,quake.dat,time_accel,g,\n"), "accepted");
}

TEST(RecordSuite, HeadersMustNameTheReadingColumnsOnce) {
    EXPECT_EQ(message("# only a comment\nname,file,units\na,quake.dat,g\n"),
              at_line(2) + "a header with a 'format' column (see docs/records.md)");
    EXPECT_EQ(message("name,file,format,event,event\n"), at_line(1) + "column 'event' appears twice in the header");
    EXPECT_EQ(message("name,file,format,,event\n"), at_line(1) + "column 4 of the header has no name");
    EXPECT_EQ(message(""), "--suite = " + kDir + "suite.csv is invalid: a header row naming the columns (the file has none)");
    EXPECT_EQ(message(kHeader), "--suite = " + kDir + "suite.csv is invalid: at least one record below the header");
}
