// History files: HDF5 and CSV round trips at full precision, refusals that leave nothing behind.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "rocksweep/core/errors.hpp"
#include "rocksweep/io/hdf5.hpp"
#include "rocksweep/io/history_file.hpp"
#include "test_support.hpp"

namespace fs = std::filesystem;
using namespace rocksweep;
using rocksweep::testing::bits;
using rocksweep::testing::TempDir;

namespace {

History known_history(std::size_t n) {
    History h;
    for (std::size_t i = 0; i < n; ++i) {
        const double t = 0.01 * static_cast<double>(i);
        h.t.push_back(t);
        h.theta.push_back(0.1 * std::sin(7.0 * t) / 3.0);
        h.theta_dot.push_back(0.7 * std::cos(7.0 * t) / 3.0);
        h.k_left.push_back(i < n / 2 ? 1.2345678901234567e6 : 0.0);
        h.k_right.push_back(9.87654321e5);
        h.ground_acc.push_back(-2.5 * std::sin(3.0 * t));
        h.w_excitation.push_back(1e-3 * t * t);
        h.w_anchorage.push_back(i == 3 ? NAN : -1e-4 * t);
    }
    h.result.outcome = Outcome::overturned_impact;
    h.result.impacts = 2;
    h.result.impacts_total = 5;
    h.result.t_overturn_s = 3.25;
    h.result.max_rotation = 7.0;
    h.result.peak_force_ratio = 0.875;
    h.result.broken = broken_left;
    return h;
}

}  // namespace


TEST(HistoryFile, H5RoundTrip) {
    TempDir dir;
    const History h = known_history(50);
    const std::string path = dir.file("history.h5");
    write_history_h5(path, h, {{"scenario", "constant_alpha"}}, {{"omega_ratio", 2.5}});
    EXPECT_FALSE(fs::exists(path + ".tmp"));

    const h5::File f = h5::File::open_read_only(path);
    EXPECT_EQ(bits(h5::read_1d<double>(f, "t")), bits(h.t));
    EXPECT_EQ(bits(h5::read_1d<double>(f, "theta")), bits(h.theta));
    EXPECT_EQ(bits(h5::read_1d<double>(f, "theta_dot")), bits(h.theta_dot));
    EXPECT_EQ(bits(h5::read_1d<double>(f, "k_left")), bits(h.k_left));
    EXPECT_EQ(bits(h5::read_1d<double>(f, "k_right")), bits(h.k_right));
    EXPECT_EQ(bits(h5::read_1d<double>(f, "ground_acc")), bits(h.ground_acc));
    EXPECT_EQ(bits(h5::read_1d<double>(f, "w_excitation")), bits(h.w_excitation));
    EXPECT_EQ(bits(h5::read_1d<double>(f, "w_anchorage")), bits(h.w_anchorage));
    {
        const h5::Dataset t = f.open_dataset("t");
        const h5::Dataset theta = f.open_dataset("theta");
        EXPECT_TRUE(h5::is_attached(theta, t, 0));
        EXPECT_TRUE(h5::is_attached(f.open_dataset("w_anchorage"), t, 0));
        EXPECT_EQ(h5::read_string_attribute(t, "units"), "s");
        EXPECT_EQ(h5::read_string_attribute(theta, "units"), "rad");
        EXPECT_EQ(h5::read_string_attribute(f.open_dataset("theta_dot"), "units"), "rad/s");
        EXPECT_EQ(h5::read_string_attribute(f.open_dataset("k_right"), "units"), "N/m");
        EXPECT_EQ(h5::read_string_attribute(f.open_dataset("ground_acc"), "units"), "m/s^2");
        EXPECT_EQ(h5::read_string_attribute(f.open_dataset("w_excitation"), "units"), "J");
    }
    EXPECT_EQ(h5::read_string_attribute(f, "outcome"), to_string(Outcome::overturned_impact));
    EXPECT_EQ(h5::read_int64_attribute(f, "outcome_code"), 1);
    EXPECT_EQ(h5::read_int64_attribute(f, "impacts"), 2);
    EXPECT_EQ(h5::read_int64_attribute(f, "impacts_total"), 5);
    EXPECT_EQ(h5::read_double_attribute(f, "t_overturn"), 3.25);
    EXPECT_EQ(h5::read_double_attribute(f, "max_rotation"), 7.0);
    EXPECT_EQ(h5::read_double_attribute(f, "peak_force_ratio"), 0.875);
    EXPECT_NE(h5::read_string_attribute(f, "work_sign_convention").find("negative"), std::string::npos);
    EXPECT_EQ(h5::read_string_attribute(f, "scenario"), "constant_alpha");
    EXPECT_EQ(h5::read_double_attribute(f, "omega_ratio"), 2.5);
}

TEST(HistoryFile, H5RejectsRaggedColumns) {
    TempDir dir;
    History h = known_history(10);
    h.k_left.pop_back();
    EXPECT_THROW(write_history_h5(dir.file("h.h5"), h, {}, {}), std::invalid_argument);
    EXPECT_FALSE(fs::exists(dir.file("h.h5")));
}

TEST(HistoryFile, CsvRoundTripAtFullPrecision) {
    TempDir dir;
    const History h = known_history(20);
    const std::string path = dir.file("history.csv");
    write_history_csv(path, h);
    EXPECT_FALSE(fs::exists(path + ".tmp"));

    std::ifstream in(path);
    std::string header;
    std::getline(in, header);
    EXPECT_EQ(header,
              "t_s,theta_rad,theta_dot_rad_s,k_left_N_m,k_right_N_m,ground_acc_m_s2,"
              "w_excitation_J,w_anchorage_J");
    const std::vector<const std::vector<double>*> cols = {
        &h.t, &h.theta, &h.theta_dot, &h.k_left, &h.k_right, &h.ground_acc, &h.w_excitation,
        &h.w_anchorage};
    std::string line;
    std::size_t row = 0;
    while (std::getline(in, line)) {
        ASSERT_LT(row, h.t.size());
        std::stringstream ss(line);
        std::string cell;
        for (std::size_t c = 0; c < cols.size(); ++c) {
            ASSERT_TRUE(std::getline(ss, cell, ',')) << "row " << row;
            const double x = std::strtod(cell.c_str(), nullptr);
            EXPECT_EQ(std::bit_cast<std::uint64_t>(x), std::bit_cast<std::uint64_t>((*cols[c])[row]))
                << "row " << row << " column " << c << ": " << cell;
        }
        EXPECT_FALSE(std::getline(ss, cell, ',')) << "extra column in row " << row;
        ++row;
    }
    EXPECT_EQ(row, h.t.size());
}

TEST(HistoryFile, CsvInMissingDirectoryThrows) {
    TempDir dir;
    const std::string path = dir.file("nope/history.csv");
    EXPECT_THROW(write_history_csv(path, known_history(3)), InputError);
    EXPECT_FALSE(fs::exists(path));
    EXPECT_FALSE(fs::exists(path + ".tmp"));
}
