// The streaming spectra writer: what it leaves on disk at each step, and that a file it filled
// in place reads back exactly as the cells it was given.
#include <fcntl.h>
#include <unistd.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "rocksweep/grid/refine.hpp"
#include "rocksweep/io/hdf5.hpp"
#include "rocksweep/io/spectra_stream.hpp"
#include "spectra_test_support.hpp"
#include "test_support.hpp"

namespace fs = std::filesystem;
using namespace rocksweep;
using rocksweep::testing::expect_same_results;
using rocksweep::testing::TempDir;

namespace {

/// small_spec() on a 5 x 7 grid: 70 cells, so that chunks can straddle the two scenarios.
SweepSpec two_scenarios() {
    SweepSpec spec = rocksweep::testing::small_spec();
    spec.omega_ratio = Axis{1.0, 5.0, 7};
    spec.amplitude_ratio = Axis{1.0, 2.0, 5};
    return spec;
}

/// A cell whose every field says which cell it is.
CellResult cell(std::size_t i) {
    CellResult r;
    r.max_rotation = 0.5 + 0.01 * static_cast<double>(i);
    r.t_overturn_s = i % 3 ? NAN : 2.0 + static_cast<double>(i);
    r.peak_force_ratio = 0.001 * static_cast<double>(i);
    r.mu_required = 0.3 + std::ldexp(1.0, -30) * static_cast<double>(i);
    r.impacts = static_cast<std::int32_t>(i % 11);
    r.impacts_total = static_cast<std::int32_t>(i % 13);
    r.outcome = static_cast<Outcome>(i % 3);
    r.broken = static_cast<std::uint8_t>(i % 4);
    r.pivot_uplift = static_cast<std::uint8_t>(i % 5 == 1);
    return r;
}

std::vector<CellResult> cells(std::size_t first, std::size_t count) {
    std::vector<CellResult> v;
    for (std::size_t i = first; i < first + count; ++i) v.push_back(cell(i));
    return v;
}

void add(SpectraStream& s, std::size_t first, std::size_t count) { s.add(first, count, cells(first, count).data()); }

/// What the old whole-file writer would have held for cells [0, n) done.
SweepResults expected(const SweepSpec& spec, std::size_t n) {
    SweepResults r;
    r.resize(spec.cell_count());
    for (std::size_t i = 0; i < n; ++i) r.store(i, cell(i));
    return r;
}

std::int64_t root_int(const std::string& path, const char* name) {
    return h5::read_int64_attribute(h5::File::open_read_only(path), name);
}

/// A sweep of two scenarios and the output path, in a directory of its own.
class Stream : public ::testing::Test {
protected:
    TempDir dir;
    const SweepSpec spec = two_scenarios();
    const IntegratorSettings settings;
    const std::string out = dir.file("s.h5");
};

}  // namespace

TEST_F(Stream, CellsInAnyOrderOverSeveralCheckpointsReadBackExactly) {
    SpectraStream s(out, spec, settings, Provenance{}, false);
    const std::size_t n = spec.cell_count();  // 70: chunks straddle the two scenarios
    add(s, 40, 30);
    add(s, 3, 10);
    s.checkpoint();
    EXPECT_EQ(root_int(out, "n_done"), 40);
    add(s, 13, 27);
    add(s, 0, 3);
    s.finish(1.5);
    EXPECT_EQ(s.done_count(), n);
    EXPECT_EQ(root_int(out, "complete"), 1);
    expect_same_results(read_spectra_results(out, spec, settings), expected(spec, n));
    EXPECT_FALSE(fs::exists(out + ".tmp"));
    EXPECT_EQ(s.stats().cells, n);
}

TEST_F(Stream, PathIsUntouchedUntilTheFirstCheckpoint) {
    std::ofstream(out) << "the previous file";
    {
        SpectraStream s(out, spec, settings, Provenance{}, false);
        EXPECT_TRUE(fs::exists(out + ".tmp"));
        add(s, 0, 5);
        EXPECT_EQ(fs::file_size(out), 17u);
    }  // never checkpointed: the skeleton goes, the previous file stays
    EXPECT_FALSE(fs::exists(out + ".tmp"));
    EXPECT_EQ(fs::file_size(out), 17u);
    SpectraStream s(out, spec, settings, Provenance{}, false);
    s.checkpoint();
    EXPECT_FALSE(fs::exists(out + ".tmp"));
    EXPECT_EQ(root_int(out, "n_done"), 0);
}

TEST_F(Stream, ResumeSeesWhatWasSavedAndEndsWithTheWhole) {
    {
        SpectraStream s(out, spec, settings, Provenance{}, false);
        add(s, 0, 20);
        s.checkpoint();
        add(s, 20, 10);  // lost, as to a kill: never checkpointed
    }
    SpectraStream s(out, spec, settings, Provenance{}, true);
    EXPECT_EQ(s.done_count(), 20u);
    std::vector<std::uint8_t> done(spec.cell_count());
    s.read_column("done", 0, done.size(), done.data());
    for (std::size_t i = 0; i < done.size(); ++i) EXPECT_EQ(done[i], i < 20 ? 1 : 0) << i;
    add(s, 20, spec.cell_count() - 20);
    s.finish(1.0);
    expect_same_results(read_spectra_results(out, spec, settings), expected(spec, spec.cell_count()));
}

TEST_F(Stream, AFileKilledBeforeItsCloseOutIsNotClosedOut) {
    // The moment CI's kill test once hit: every cell checkpointed, then killed before finish().
    {
        SpectraStream s(out, spec, settings, Provenance{}, false);
        add(s, 0, spec.cell_count());
        s.checkpoint();
    }
    {
        SpectraStream s(out, spec, settings, Provenance{}, true);
        EXPECT_EQ(s.done_count(), spec.cell_count());
        EXPECT_FALSE(s.closed_out());  // every cell, but neither `complete` nor the checksums
        EXPECT_EQ(root_int(out, "complete"), 0);
        s.finish(1.0);
    }
    EXPECT_EQ(root_int(out, "complete"), 1);
    SpectraStream s(out, spec, settings, Provenance{}, true);
    EXPECT_TRUE(s.closed_out());
}

TEST_F(Stream, ResumeOfAFileWrittenWholeRewritesItInPlaceLayout) {
    write_spectra(out, spec, expected(spec, 33), Provenance{}, settings);  // as merge writes
    SpectraStream s(out, spec, settings, Provenance{}, true);
    EXPECT_EQ(s.done_count(), 33u);
    add(s, 33, spec.cell_count() - 33);
    s.finish(1.0);
    expect_same_results(read_spectra_results(out, spec, settings), expected(spec, spec.cell_count()));
}

TEST_F(Stream, InferredCellsTakeTheirOutcomeAndEmptyValues) {
    SpectraStream s(out, spec, settings, Provenance{}, false);
    const std::size_t per = spec.cells_per_scenario();
    add(s, per, per);  // the second scenario computed; the first inferred where marked
    s.checkpoint();
    std::vector<std::uint8_t> outcome(per, 2), before(per, 0), after(per, 0);
    for (std::size_t i = 3; i < 9; ++i) after[i] = cell_inferred;
    s.add_inferred(0, 0, 12, outcome.data(), before.data(), after.data());
    // A plane further on: its cells are counted from `first`, its arrays from 0.
    std::vector<std::uint8_t> later(4, 0), later_after(4, cell_inferred), later_outcome(4, 1);
    later_after[0] = 0;
    s.add_inferred(0, 20, 4, later_outcome.data(), later.data(), later_after.data());
    s.finish(1.0);
    const SweepResults r = read_spectra_results(out, spec, settings);
    EXPECT_EQ(r.done[2], 0);
    EXPECT_EQ(r.done[3], cell_inferred);
    EXPECT_EQ(r.outcome[8], 2);
    EXPECT_TRUE(std::isnan(r.max_rotation[5]));
    EXPECT_EQ(r.impacts[5], 0);
    EXPECT_EQ(r.done[20], 0);
    EXPECT_EQ(r.done[21], cell_inferred);
    EXPECT_EQ(r.outcome[23], 1);
    EXPECT_EQ(r.done[24], 0);
    EXPECT_EQ(s.done_count(), per + 6 + 3);
    EXPECT_EQ(root_int(out, "n_done"), static_cast<std::int64_t>(per + 6 + 3));
}

TEST(Hdf5InPlace, FixedDatasetTakesBytesWrittenAtItsOffset) {
    TempDir dir;
    const std::string path = dir.file("f.h5");
    const hsize_t dims[1] = {1000};
    std::uint64_t offset = 0;
    {
        h5::File f = h5::File::create(path);
        h5::write_attribute(f, "count", std::int64_t{1});
        const h5::Dataset ds = h5::create_fixed_dataset<double>(f, "x", dims);
        const h5::RawPlacement p = h5::raw_placement(ds);
        EXPECT_EQ(p.element_bytes, sizeof(double));
        offset = p.offset;
        // Compressed or chunked data has no single place to write into.
        const hsize_t big[1] = {4096};
        const h5::Dataset packed = h5::write_dataset<double>(f, "y", std::vector<double>(4096, 1.0), big);
        EXPECT_THROW(h5::raw_placement(packed), Hdf5Error);
    }
    const double values[3] = {0.25, -1.0, NAN};
    const int fd = ::open(path.c_str(), O_WRONLY);
    ASSERT_GE(fd, 0);
    ASSERT_EQ(::pwrite(fd, values, sizeof values, static_cast<off_t>(offset + 10 * sizeof(double))), 24);
    ::close(fd);
    {
        h5::File f = h5::File::open_for_update(path);
        h5::update_attribute(f, "count", std::int64_t{42});
        f.close();
    }
    const h5::File f = h5::File::open_read_only(path);
    const std::vector<double> x = h5::read_1d<double>(f, "x");
    EXPECT_EQ(x[0], 0.0);  // never written: a hole
    EXPECT_EQ(x[10], 0.25);
    EXPECT_EQ(x[11], -1.0);
    EXPECT_TRUE(std::isnan(x[12]));
    EXPECT_EQ(h5::read_int64_attribute(f, "count"), 42);
}
