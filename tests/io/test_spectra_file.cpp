// Round trips of the spectra file: exact values back, axes as dimension scales, the layout
// and attributes readers rely on, nothing partial left behind on failure. The HDF5 layer it is
// built on has its own tests (test_hdf5_*.cpp).
#include <gtest/gtest.h>

#include <bit>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include <unistd.h>

#include "rocksweep/physics/anchorage.hpp"
#include "rocksweep/physics/block.hpp"
#include "rocksweep/core/errors.hpp"
#include "rocksweep/io/hdf5.hpp"
#include "rocksweep/io/spectra_file.hpp"
#include "spectra_test_support.hpp"
#include "test_support.hpp"

namespace fs = std::filesystem;
using namespace rocksweep;
using rocksweep::testing::bits;
using rocksweep::testing::TempDir;
using rocksweep::testing::expect_same_results;
using rocksweep::testing::small_spec;

namespace {

/// Values that make an index mix-up visible: every cell differs in every column, NaNs where
/// the real writer puts them, and a few cells not done.
SweepResults known_results(const SweepSpec& spec, bool all_done = false) {
    SweepResults r;
    r.resize(spec.cell_count());
    const std::uint8_t codes[] = {0, 1, 2, 255};
    for (std::size_t i = 0; i < r.size(); ++i) {
        const bool free = i < spec.cells_per_scenario();
        r.outcome[i] = codes[i % 4];
        r.max_rotation[i] = 1.0 / 3.0 + 0.1 * static_cast<double>(i);
        r.impacts[i] = static_cast<std::int32_t>(7 * i) - 5;
        r.impacts_total[i] = static_cast<std::int32_t>(7 * i) + 1;
        r.t_overturn[i] = (r.outcome[i] == 1 || r.outcome[i] == 2) ? 1.5 + std::ldexp(1.0, -40) * i : NAN;
        r.peak_force_ratio[i] = free ? NAN : 0.01 * static_cast<double>(i);
        r.broken[i] = static_cast<std::uint8_t>(i % 4);
        r.mu_required[i] = 0.2 + 0.001 * static_cast<double>(i);
        r.pivot_uplift[i] = static_cast<std::uint8_t>(i % 7 == 3);
        r.done[i] = (all_done || i % 5 != 0) ? 1 : 0;
    }
    return r;
}

Provenance some_provenance() {
    Provenance p;
    p.version = "0.1.0";
    p.config_text = "[sweep]\nomega-ratio = [1, 4]\n";
    p.created_utc = "2024-01-02T03:04:05Z";
    p.ranks = 3;
    p.wall_s = 12.5;
    return p;
}


}  // namespace

// ---------------------------------------------------------------------------------------
// Spectra file

TEST(SpectraFile, RoundTripIsExactAndLeavesNoTmp) {
    TempDir dir;
    const SweepSpec spec = small_spec();
    const SweepResults r = known_results(spec);
    const std::string path = dir.file("spectra.h5");
    write_spectra(path, spec, r, some_provenance(), IntegratorSettings{});

    EXPECT_TRUE(fs::exists(path));
    EXPECT_FALSE(fs::exists(path + ".tmp"));
    expect_same_results(read_spectra_results(path, spec, IntegratorSettings{}), r);
}

TEST(SpectraFile, LayoutAxesScalesAndAttributes) {
    TempDir dir;
    const SweepSpec spec = small_spec();
    const std::string path = dir.file("spectra.h5");
    write_spectra(path, spec, known_results(spec), some_provenance(), IntegratorSettings{});

    const h5::File f = h5::File::open_read_only(path);
    EXPECT_TRUE(f.exists("spectra/free/outcome"));
    EXPECT_FALSE(f.exists("spectra/nope/outcome"));  // a missing parent is "no", not an error
    EXPECT_EQ(f.children(), (std::vector<std::string>{"provenance", "spectra"}));

    {
        // Each scenario group holds its own axes, where netCDF-4 looks for dimensions.
        for (const char* group : {"spectra/free", "spectra/constant_alpha"}) {
            const h5::Group g = f.open_group(group);
            EXPECT_EQ(h5::read_1d<double>(g, "omega_ratio"), spec.omega_ratio.values()) << group;
            EXPECT_EQ(h5::read_1d<double>(g, "amplitude_ratio"), spec.amplitude_ratio.values()) << group;
        }
        const h5::Dataset omega = f.open_dataset("spectra/free/omega_ratio");
        const h5::Dataset amp = f.open_dataset("spectra/free/amplitude_ratio");
        EXPECT_EQ(h5::read_string_attribute(omega, "long_name"), "omega_p / p");
        EXPECT_EQ(h5::read_string_attribute(amp, "long_name"), "a_p0 / (alpha g)");
        EXPECT_EQ(h5::read_string_attribute(amp, "units"), "1");
        for (const char* name : {"outcome", "max_rotation", "impacts", "impacts_total", "t_overturn",
                                 "peak_force_ratio", "broken", "mu_required", "pivot_uplift", "done"}) {
            SCOPED_TRACE(name);
            const h5::Dataset ds = f.open_dataset(std::string("spectra/free/") + name);
            // Shape [n_amp, n_omega], amplitude on dimension 0.
            EXPECT_EQ(ds.dims(), (std::vector<hsize_t>{3, 4}));
            EXPECT_TRUE(h5::is_attached(ds, amp, 0));
            EXPECT_TRUE(h5::is_attached(ds, omega, 1));
            EXPECT_FALSE(h5::is_attached(ds, omega, 0));
            EXPECT_EQ(h5::read_string_attribute(ds, "dimensions"), "amplitude_ratio, omega_ratio");
            // No HDF5 dimension labels: they are variable-length strings, which Octave's
            // netcdf package cannot read.
            EXPECT_FALSE(ds.has_attribute("DIMENSION_LABELS"));
        }
        // Explicit little-endian file types.
        const h5::Dataset outcome = f.open_dataset("spectra/free/outcome");
        EXPECT_GT(H5Tequal(outcome.type().id(), H5T_STD_U8LE), 0);
        EXPECT_GT(H5Tequal(f.open_dataset("spectra/free/impacts").type().id(), H5T_STD_I32LE), 0);
        EXPECT_GT(H5Tequal(f.open_dataset("spectra/free/t_overturn").type().id(), H5T_IEEE_F64LE), 0);
        EXPECT_EQ(h5::read_string_attribute(outcome, "flag_meanings"),
                  "safe overturned_with_impact overturned_without_impact not_converged");
        // flag_values is a uint8 array [0, 1, 2, 255].
        const hid_t a = H5Aopen(outcome.id(), "flag_values", H5P_DEFAULT);
        ASSERT_GE(a, 0);
        std::uint8_t values[4] = {};
        EXPECT_GE(H5Aread(a, H5T_NATIVE_UINT8, values), 0);
        H5Aclose(a);
        EXPECT_EQ(std::vector<std::uint8_t>(values, values + 4), (std::vector<std::uint8_t>{0, 1, 2, 255}));
    }

    // Root: block and pulse parameters, completeness.
    EXPECT_DOUBLE_EQ(h5::read_double_attribute(f, "half_width_m"), 0.3);
    EXPECT_DOUBLE_EQ(h5::read_double_attribute(f, "half_height_m"), 1.36);
    EXPECT_EQ(h5::read_double_attribute(f, "alpha_rad"), spec.block.alpha_rad);
    EXPECT_EQ(h5::read_double_attribute(f, "phase_rad"), 0.25);
    EXPECT_EQ(h5::read_string_attribute(f, "equations"), "nonlinear");
    EXPECT_EQ(h5::read_int64_attribute(f, "n_cells"), 24);
    EXPECT_EQ(h5::read_int64_attribute(f, "n_done"), 24 - 5);  // i % 5 == 0 are pending
    EXPECT_EQ(h5::read_int64_attribute(f, "complete"), 0);

    {
        const h5::Group g = f.open_group("spectra/constant_alpha");
        EXPECT_EQ(h5::read_string_attribute(g, "anchorage"), "constant");
        EXPECT_EQ(h5::read_double_attribute(g, "strength_N"), 0.4 * 3361 * 9.81);
        EXPECT_EQ(h5::read_double_attribute(g, "theta_f_rad"), spec.block.alpha_rad);
        EXPECT_EQ(h5::read_double_attribute(g, "k_max_N_per_m"), spec.scenarios[1].anchorage.k_max);
        EXPECT_EQ(h5::read_int64_attribute(g, "index"), 1);
        EXPECT_EQ(h5::read_string_attribute(f.open_group("spectra/free"), "anchorage"), "free");
    }
    {
        const h5::Group p = f.open_group("provenance");
        EXPECT_EQ(h5::read_string_attribute(p, "config"), "[sweep]\nomega-ratio = [1, 4]\n");
        EXPECT_EQ(h5::read_int64_attribute(p, "ranks"), 3);
        EXPECT_EQ(h5::read_double_attribute(p, "wall_s"), 12.5);
        EXPECT_EQ(h5::read_string_attribute(p, "created_utc"), "2024-01-02T03:04:05Z");
    }
    // Run-dependent values live only under /provenance.
    EXPECT_FALSE(f.has_attribute("ranks"));
    EXPECT_FALSE(f.has_attribute("wall_s"));
    EXPECT_FALSE(f.has_attribute("created_utc"));
}

TEST(SpectraFile, SameInputsGiveByteIdenticalFiles) {
    // No object timestamps, nothing run-dependent outside /provenance: two writes of the same
    // results and provenance are the same bytes (so h5diff of two runs differs only there).
    TempDir dir;
    const SweepSpec spec = small_spec();
    const SweepResults r = known_results(spec);
    write_spectra(dir.file("a.h5"), spec, r, some_provenance(), IntegratorSettings{});
    write_spectra(dir.file("b.h5"), spec, r, some_provenance(), IntegratorSettings{});
    auto slurp = [](const std::string& p) {
        std::ifstream in(p, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(in), {});
    };
    EXPECT_EQ(slurp(dir.file("a.h5")), slurp(dir.file("b.h5")));

    const h5::File f = h5::File::open_read_only(dir.file("a.h5"));
    for (const char* name : {"/", "/spectra/free", "/spectra/free/outcome", "/spectra/free/omega_ratio"}) {
        H5O_info_t info{};
        ASSERT_GE(H5Oget_info_by_name2(f.id(), name, &info, H5O_INFO_TIME, H5P_DEFAULT), 0);
        EXPECT_EQ(info.ctime, 0) << name;
        EXPECT_EQ(info.mtime, 0) << name;
    }
}

TEST(SpectraFile, CompleteWhenEveryCellIsDone) {
    TempDir dir;
    const SweepSpec spec = small_spec();
    const std::string path = dir.file("spectra.h5");
    write_spectra(path, spec, known_results(spec, true), some_provenance(), IntegratorSettings{});
    const h5::File f = h5::File::open_read_only(path);
    EXPECT_EQ(h5::read_int64_attribute(f, "complete"), 1);
    EXPECT_EQ(h5::read_int64_attribute(f, "n_done"), 24);
}

TEST(SpectraFile, MissingDirectoryThrowsAndLeavesNoFile) {
    TempDir dir;
    const SweepSpec spec = small_spec();
    const std::string path = dir.file("no_such_dir/spectra.h5");
    try {
        write_spectra(path, spec, known_results(spec), some_provenance(), IntegratorSettings{});
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_EQ(e.field(), "output");
        EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
    EXPECT_FALSE(fs::exists(path));
    EXPECT_FALSE(fs::exists(path + ".tmp"));
}

TEST(SpectraFile, FailedRenameIsAnInputErrorAndLeavesNoTmp) {
    // A directory where the file should go: the tmp file is written, the rename fails.
    TempDir dir;
    const SweepSpec spec = small_spec();
    const std::string path = dir.file("taken.h5");
    fs::create_directory(path);
    try {
        write_spectra(path, spec, known_results(spec), some_provenance(), IntegratorSettings{});
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_EQ(e.field(), "output");
        EXPECT_NE(std::string(e.what()).find("writable"), std::string::npos) << e.what();
    }
    EXPECT_TRUE(fs::is_directory(path));
    EXPECT_FALSE(fs::exists(path + ".tmp"));
}

TEST(SpectraFile, FailureMidWriteKeepsThePreviousFile) {
    TempDir dir;
    const SweepSpec spec = small_spec();
    const std::string path = dir.file("spectra.h5");
    const SweepResults first = known_results(spec);
    write_spectra(path, spec, first, some_provenance(), IntegratorSettings{});

    // A NUL inside the config text cannot go into a C string attribute: the writer fails
    // after the tmp file has been created and most of it written.
    Provenance bad = some_provenance();
    bad.config_text = std::string("a\0b", 3);
    EXPECT_THROW(write_spectra(path, spec, known_results(spec, true), bad, IntegratorSettings{}), std::runtime_error);
    EXPECT_FALSE(fs::exists(path + ".tmp"));
    expect_same_results(read_spectra_results(path, spec, IntegratorSettings{}), first);
}

TEST(SpectraFile, RejectsMismatchedColumnsAndBadNames) {
    TempDir dir;
    SweepSpec spec = small_spec();
    SweepResults r = known_results(spec);
    r.impacts.pop_back();
    EXPECT_THROW(write_spectra(dir.file("a.h5"), spec, r, some_provenance(), IntegratorSettings{}), std::invalid_argument);

    spec.scenarios[1].name = "free";  // a repeated group name
    EXPECT_THROW(write_spectra(dir.file("a.h5"), spec, known_results(spec), some_provenance(), IntegratorSettings{}),
                 InputError);
    spec.scenarios[1].name = "a/b";
    EXPECT_THROW(write_spectra(dir.file("a.h5"), spec, known_results(spec), some_provenance(), IntegratorSettings{}),
                 InputError);
    EXPECT_FALSE(fs::exists(dir.file("a.h5")));
}

TEST(SpectraFile, ReadRejectsADifferentSweep) {
    TempDir dir;
    const SweepSpec spec = small_spec();
    const std::string path = dir.file("spectra.h5");
    write_spectra(path, spec, known_results(spec), some_provenance(), IntegratorSettings{});

    auto expect_rejected = [&](const SweepSpec& other, const std::string& mentions) {
        try {
            read_spectra_results(path, other, IntegratorSettings{});
            ADD_FAILURE() << "expected InputError mentioning " << mentions;
        } catch (const InputError& e) {
            const std::string what = e.what();
            EXPECT_NE(what.find(path), std::string::npos) << what;
            EXPECT_NE(what.find(mentions), std::string::npos) << what;
        }
    };
    SweepSpec more_points = spec;
    more_points.omega_ratio.points = 5;
    expect_rejected(more_points, "omega_ratio");

    SweepSpec other_range = spec;
    other_range.amplitude_ratio.hi = 3.5;
    expect_rejected(other_range, "amplitude_ratio");

    SweepSpec other_scenarios = spec;
    other_scenarios.scenarios[1].name = "constant_half";
    expect_rejected(other_scenarios, "scenarios");

    SweepSpec other_anchorage = spec;
    other_anchorage.scenarios[1].anchorage =
        constant_anchorage(spec.block, 0.4 * 3361 * 9.81, spec.block.alpha_rad / 2);
    expect_rejected(other_anchorage, "constant_alpha");

    SweepSpec other_block = spec;
    other_block.block = rectangular_block(0.3, 1.5, 3361);
    expect_rejected(other_block, "half_height_m");

    SweepSpec other_equations = spec;
    other_equations.equations = Equations::linearised;
    expect_rejected(other_equations, "equations");
}

TEST(SpectraFile, ReadOfMissingFileIsAnInputError) {
    TempDir dir;
    EXPECT_THROW(read_spectra_results(dir.file("absent.h5"), small_spec(), IntegratorSettings{}), InputError);
}

TEST(SpectraFile, ResumeOfTheOldLayoutIsRefusedInOneLine) {
    // Format version 1 kept the axes in /axes, beside /spectra: what such a file holds at the
    // points the reader looks at first.
    TempDir dir;
    const std::string path = dir.file("old.h5");
    {
        h5::File f = h5::File::create(path);
        h5::write_attribute(f, "format_version", std::int64_t{1});
        const std::vector<double> omega = small_spec().omega_ratio.values();
        h5::write_1d<double>(f.create_group("axes"), "omega_ratio", omega);
        f.create_group("spectra");
        f.close();
    }
    try {
        read_spectra_results(path, small_spec(), IntegratorSettings{});
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        const std::string what = cli_message(e);
        EXPECT_EQ(what, "--output = " + path + " is invalid: a spectra file of format version 2 to resume; it is of "
                        "version 1 (an older layout, axes in /axes), which this rocksweep does not continue: sweep "
                        "again with --overwrite");
    }
}
