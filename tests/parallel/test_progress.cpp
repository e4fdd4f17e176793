// The progress report of long runs: quiet, plain lines (count, rate, ETA) at an interval, or a
// bar redrawn in place.
#include "rocksweep/parallel/progress.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <regex>
#include <sstream>
#include <string>
#include <thread>

namespace rocksweep {
namespace {

TEST(Progress, QuietPrintsNothing) {
    std::ostringstream out;
    ProgressOptions options;
    options.plain_interval_s = 0.0;
    {
        Progress progress(100, true, out, options);
        progress.update(10);
        progress.update(100);
        progress.finish();
    }
    EXPECT_EQ(out.str(), "");
}

TEST(Progress, PlainLinesCarryCountRateAndEta) {
    std::ostringstream out;
    ProgressOptions options;
    options.plain_interval_s = 0.0;
    Progress progress(100, false, out, options);
    EXPECT_FALSE(progress.uses_bar()) << "a stringstream is not a terminal";
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    progress.update(50);
    EXPECT_TRUE(std::regex_search(out.str(), std::regex(R"(50/100 cells \(50\.0%\)  [0-9.]+ cells/s  ETA \S+\n)")))
        << out.str();
    progress.finish(100);
    EXPECT_TRUE(std::regex_search(out.str(), std::regex(R"(100/100 cells \(100\.0%\)  in \S+, mean [0-9.]+ cells/s\n$)")))
        << out.str();
}

TEST(Progress, PlainLinesAreSpacedByTheInterval) {
    std::ostringstream out;
    Progress progress(100, false, out);  // default: a line every 5 s
    progress.update(10);
    progress.update(20);
    EXPECT_EQ(out.str(), "");
    progress.finish();
    EXPECT_NE(out.str().find("20/100 cells"), std::string::npos) << out.str();
    EXPECT_NE(out.str().find("cells/s"), std::string::npos);
}

TEST(Progress, BarIsRedrawnInPlace) {
    std::ostringstream out;
    ProgressOptions options;
    options.style = ProgressOptions::Style::bar;
    options.bar_width = 10;
    options.bar_interval_s = 0.0;
    Progress progress(200, false, out, options);
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    progress.update(100);
    EXPECT_EQ(out.str().rfind("\r[#####.....] 100/200 cells  ", 0), 0u) << out.str();
    progress.finish(200);
    EXPECT_NE(out.str().find("\r[##########] 200/200 cells  in "), std::string::npos) << out.str();
    EXPECT_EQ(out.str().back(), '\n');
}

TEST(Progress, RateLeavesOutCellsDoneBeforeTheRun) {
    std::ostringstream out;
    ProgressOptions options;
    options.plain_interval_s = 0.0;
    options.already_done = 90;
    Progress progress(100, false, out, options);
    progress.update(90);  // nothing new yet: no rate to speak of
    EXPECT_NE(out.str().find("90/100 cells (90.0%)  -- cells/s  ETA --"), std::string::npos) << out.str();
}

TEST(Progress, FormatsDurationsAndRates) {
    EXPECT_EQ(Progress::format_duration(0.42), "0.4s");
    EXPECT_EQ(Progress::format_duration(42.0), "42s");
    EXPECT_EQ(Progress::format_duration(72.0), "1m12s");
    EXPECT_EQ(Progress::format_duration(7384.0), "2h03m");
    EXPECT_EQ(Progress::format_duration(200000.0), "2d07h");
    EXPECT_EQ(Progress::format_rate(0.5123), "0.512");
    EXPECT_EQ(Progress::format_rate(12.46), "12.5");
    EXPECT_EQ(Progress::format_rate(1234.4), "1234");
}

}  // namespace
}  // namespace rocksweep
