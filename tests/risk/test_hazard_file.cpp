// Hazard curve files: the plain CSV and OpenQuake's export read into the same curve (and the
// same lambda), units converted, and every malformed file refused with a line that says why.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "rocksweep/core/errors.hpp"
#include "rocksweep/risk/hazard_file.hpp"
#include "rocksweep/risk/risk_integral.hpp"

namespace rocksweep {
namespace {

namespace fs = std::filesystem;

class HazardFileTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("rocksweep_hazard_" + std::to_string(::getpid()) + "_" +
                                            ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    std::string write(const std::string& name, const std::string& text) {
        const std::string path = (dir_ / name).string();
        std::ofstream(path) << text;
        return path;
    }
    /// The message of the InputError reading `path` throws ("" if none).
    static std::string error_of(const std::string& path, int site = -1) {
        try {
            read_hazard_file("hazard", path, site);
        } catch (const InputError& e) {
            return cli_message(e);
        }
        return "";
    }
    fs::path dir_;
};

const double xs[] = {0.01, 0.02, 0.05, 0.1, 0.2, 0.3, 0.5, 0.75, 1.0, 1.5};
double power(double x) { return 2e-6 * std::pow(x, -2.3); }

/// OpenQuake's layout: the metadata comment, the header with poe-<iml>, one row per site.
std::string openquake_text(double years, int sites = 1) {
    char buf[256];
    std::snprintf(buf, sizeof buf, "#,,,,,\"generated_by='OpenQuake engine 3.18.0', start_date='2023-10-03T06:09:08', "
                                   "checksum=2107362341, kind='mean', investigation_time=%.1f, imt='PGA'\"\nlon,lat,depth", years);
    std::string s = buf;
    for (const double x : xs) {
        std::snprintf(buf, sizeof buf, ",poe-%.7f", x);
        s += buf;
    }
    for (int site = 0; site < sites; ++site) {
        std::snprintf(buf, sizeof buf, "\n%.5f,42.10000,-0.10000", 13.0 + site);
        s += buf;
        for (const double x : xs) {
            std::snprintf(buf, sizeof buf, ",%.12E", -std::expm1(-power(x) * (site + 1) * years));
            s += buf;
        }
    }
    return s + "\n";
}

std::string plain_text(const std::string& header, double factor = 1.0) {
    std::string s = "# an illustrative site\n" + header + "\n";
    char buf[64];
    for (const double x : xs) {
        std::snprintf(buf, sizeof buf, "%.10g,%.15g\n", x * factor, power(x));
        s += buf;
    }
    return s;
}

TEST_F(HazardFileTest, OpenQuakeAndPlainCurvesGiveTheSameRate) {
    const HazardFile oq = read_hazard_file("hazard", write("oq.csv", openquake_text(50)));
    const HazardFile plain = read_hazard_file("hazard", write("plain.csv", plain_text("PGA [g],annual_rate [1/yr]")));
    EXPECT_EQ(oq.format, "openquake");
    EXPECT_EQ(plain.format, "plain");
    EXPECT_DOUBLE_EQ(oq.investigation_time_years, 50.0);
    EXPECT_EQ(oq.site, "13.00000 42.10000 -0.10000");
    ASSERT_EQ(oq.curve.size(), plain.curve.size());
    for (std::size_t i = 0; i < oq.curve.size(); ++i) EXPECT_NEAR(oq.curve.rate()[i] / plain.curve.rate()[i], 1.0, 1e-10);
    const LognormalFragility f{0.35, 0.5};
    EXPECT_NEAR(annual_rate(oq.curve, f).rate / annual_rate(plain.curve, f).rate, 1.0, 1e-10);
    // The power law the points lie on gives the closed form.
    EXPECT_NEAR(annual_rate(plain.curve, f).rate / (2e-6 * std::pow(0.35, -2.3) * std::exp(2.3 * 2.3 * 0.25 / 2)), 1.0, 1e-6);
}

TEST_F(HazardFileTest, UnitsAreConvertedAndTheMeasureNamed) {
    const HazardFile g = read_hazard_file("hazard", write("g.csv", plain_text("PGA [g],annual_rate [1/yr]")));
    const HazardFile cm = read_hazard_file("hazard", write("cm.csv", plain_text("PGA [cm/s^2], rate [1/yr]", 980.665)));
    for (std::size_t i = 0; i < g.curve.size(); ++i) EXPECT_NEAR(cm.curve.intensity()[i] / g.curve.intensity()[i], 1.0, 1e-12);
    const HazardFile sa = read_hazard_file("hazard", write("sa.csv", plain_text("SA(0.5) [g],annual_rate [1/yr]")));
    EXPECT_EQ(sa.curve.measure(), HazardMeasure::sa);
    EXPECT_DOUBLE_EQ(sa.curve.period_s(), 0.5);
    const HazardFile pgv = read_hazard_file("hazard", write("pgv.csv", plain_text("PGV [cm/s],annual_rate [1/yr]", 100)));
    EXPECT_EQ(pgv.curve.measure(), HazardMeasure::pgv);
    EXPECT_NEAR(pgv.curve.intensity()[0], 0.01, 1e-15);
}

TEST_F(HazardFileTest, OpenQuakeZerosAndCertaintiesAreDroppedAndCounted) {
    // Probability 1 at the lowest level (an infinite rate), 0 at the two highest (no source
    // reaches them): left out, and counted.
    const std::string text = "#,,,,,\"kind='mean', investigation_time=1.0, imt='PGA'\"\n"
                             "lon,lat,depth,poe-0.01,poe-0.1,poe-0.2,poe-0.4,poe-0.8,poe-1.6\n"
                             "13.0,42.1,-0.1,1.000000E+00,4.5E-01,5.7E-02,6.3E-03,0.000000E+00,0.000000E+00\n";
    const HazardFile h = read_hazard_file("hazard", write("zeros.csv", text));
    EXPECT_EQ(h.dropped_low, 1u);
    EXPECT_EQ(h.dropped_high, 2u);
    ASSERT_EQ(h.curve.size(), 3u);
    EXPECT_DOUBLE_EQ(h.curve.intensity().front(), 0.1);
    EXPECT_NEAR(h.curve.rate().front(), -std::log(1 - 0.45), 1e-15);
    // A 0 followed by a positive probability is no end of the curve: refused.
    const std::string hole = "#,,,,,\"investigation_time=1.0, imt='PGA'\"\nlon,lat,poe-0.1,poe-0.2,poe-0.4\n1,2,0.4,0,0.01\n";
    EXPECT_THROW(read_hazard_file("hazard", write("hole.csv", hole)), InputError);
}

TEST_F(HazardFileTest, BadFilesAreRefusedWithTheReason) {
    struct Bad {
        const char* name;
        const char* text;
        std::vector<const char*> says;  ///< every one of these is in the message
    };
    const Bad cases[] = {
        {"no_time", "#,,,\"kind='mean', imt='PGA'\"\nlon,lat,depth,poe-0.1,poe-0.2\n1,2,0,0.5,0.1\n", {"line 1", "investigation_time"}},
        {"no_imt", "#,,,\"kind='mean', investigation_time=50.0\"\nlon,lat,depth,poe-0.1,poe-0.2\n1,2,0,0.5,0.1\n", {"imt="}},
        {"poe", "#,,,\"investigation_time=50.0, imt='PGA'\"\nlon,lat,depth,poe-0.1,poe-0.2\n1,2,0,1.5,0.1\n",
         {"poe-0.1 = 1.5", "probability of exceedance in [0, 1]"}},
        {"rising", "PGA [g],annual_rate [1/yr]\n0.1,1e-2\n0.2,2e-2\n0.3,1e-3\n", {"line 3", "does not rise"}},
        {"order", "PGA [g],annual_rate [1/yr]\n0.2,1e-2\n0.1,5e-3\n0.3,1e-3\n", {"line 3", "strictly increasing"}},
        {"negative", "PGA [g],annual_rate [1/yr]\n0.1,1e-2\n0.2,-1e-3\n", {"line 3", "rate -1e-3", ">= 0"}},
        {"unit_pgv", "PGV [g],annual_rate [1/yr]\n0.1,1e-2\n0.2,1e-3\n", {"unit g for PGV", "m/s or cm/s"}},
        {"unit_pga", "PGA [m/s],annual_rate [1/yr]\n0.1,1e-2\n0.2,1e-3\n", {"g, m/s^2 or cm/s^2"}},
        {"measure", "MMI [1],annual_rate [1/yr]\n5,1e-2\n6,1e-3\n", {"PGA, PGV or SA(T)"}},
        {"header", "pga,rate\n0.1,1e-2\n0.2,1e-3\n", {"PGA [g],annual_rate [1/yr]"}},
        {"one_point", "PGA [g],annual_rate [1/yr]\n0.1,1e-2\n", {"at least two points"}},
        {"text", "PGA [g],annual_rate [1/yr]\n0.1,1e-2\n0.2,abc\n", {"line 3", "two finite numbers"}},
    };
    for (const Bad& c : cases) {
        const std::string e = error_of(write(std::string(c.name) + ".csv", c.text));
        for (const char* part : c.says) EXPECT_NE(e.find(part), std::string::npos) << c.name << ": " << e;
    }
    std::string e;
    const std::string two = write("two.csv", openquake_text(50, 2));
    e = error_of(two);
    EXPECT_NE(e.find("--hazard-site"), std::string::npos) << e;
    EXPECT_NE(e.find("holds 2 sites"), std::string::npos) << e;
    EXPECT_NEAR(read_hazard_file("hazard", two, 1).curve.rate()[0] / read_hazard_file("hazard", two, 0).curve.rate()[0], 2.0, 1e-9);
    e = error_of(two, 2);
    EXPECT_NE(e.find("0 .. 1"), std::string::npos) << e;
}

}  // namespace
}  // namespace rocksweep
