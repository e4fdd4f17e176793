// The streaming suite writer: the finished file it writes a slab of records at a time holds the
// cells it was given, bitwise, and the products a whole-memory computation gives; finishing
// holds a slab, not the results.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <memory>
#include <iostream>
#include <string>
#include <vector>

#include "rocksweep/io/hdf5.hpp"
#include "rocksweep/io/suite_file.hpp"
#include "rocksweep/io/suite_stream.hpp"
#include "rocksweep/physics/integrator.hpp"
#include "spectra_test_support.hpp"
#include "test_support.hpp"

using namespace rocksweep;
using rocksweep::testing::bits;
using rocksweep::testing::expect_same_results;
using rocksweep::testing::TempDir;

namespace {

const Block kBlock = rectangular_block(0.30, 1.36, 3361.0);  // S. Matteo

/// The shipped twelve records, `radii` sizes x `levels` levels each, free and anchored.
SuiteSpec spec_of(std::size_t radii, std::size_t levels, bool sensitive) {
    std::vector<double> r;
    for (std::size_t k = 0; k < radii; ++k) r.push_back(0.5 + 0.1 * static_cast<double>(k));
    const double fu = 0.4 * kBlock.mass_kg * kBlock.gravity;
    SuiteSpec spec = make_suite_spec(ROCKSWEEP_CONFIGS_DIR "/records_suite.csv", kBlock,
                                     {{"free", free_anchorage(), 0.0, 1.0},
                                      {"constant_tf1", constant_anchorage(kBlock, fu, kBlock.alpha_rad), 1.0, 1.0}},
                                     IntensityMeasure::pga_g, Axis{0.05, 1.5, levels}, r);
    spec.sensitivity.on = sensitive;
    return spec;
}

/// Made-up results of cell i, rising with the level, some overturned, some not converged.
CellResult cell(const SuiteSpec& spec, std::size_t i) {
    const double u = static_cast<double>((i * 2654435761u) % 10007) / 10007.0;
    const double level = static_cast<double>(spec.coordinates(i).level + 1) / static_cast<double>(spec.intensity.points);
    CellResult c;
    c.max_rotation = 3.0 * u * level;
    c.outcome = u < 0.02 ? Outcome::not_converged : c.max_rotation > 1.5 ? Outcome::overturned_impact : Outcome::safe;
    c.t_overturn_s = c.outcome == Outcome::overturned_impact ? 1.0 + u : NAN;
    c.impacts = static_cast<std::int32_t>(i % 7);
    c.impacts_total = static_cast<std::int32_t>(i % 9);
    c.mu_required = 0.1 + u;
    c.sensitive = static_cast<std::uint8_t>(i % 17 == 0);
    return c;
}

/// A new file at `path` into which every cell of `spec` has been streamed (in `batches`
/// checkpoints, the last batch first), not finished; `whole` gets the same cells, if given.
std::unique_ptr<SuiteStream> stream_all(const std::string& path, const SuiteSpec& spec, const IntegratorSettings& settings,
                                        std::size_t batches, SweepResults* whole) {
    Provenance prov{"test", "", "2026-01-01T00:00:00Z", 1, 0.0};
    auto stream = std::make_unique<SuiteStream>(path, spec, settings, prov, false);
    if (whole) whole->resize(spec.cell_count());
    const std::size_t n = spec.cell_count(), step = (n + batches - 1) / batches;
    for (std::size_t b = batches; b-- > 0;) {
        const std::size_t first = b * step, count = std::min(step, n - std::min(n, first));
        std::vector<CellResult> cells;
        for (std::size_t i = first; i < first + count; ++i) {
            cells.push_back(cell(spec, i));
            if (whole) whole->store(i, cells.back());
        }
        stream->add(first, count, cells.data());
        stream->checkpoint();
    }
    return stream;
}

/// Resident memory of this process, now ("VmRSS:") or at its peak since the last
/// reset_peak() ("VmHWM:") [KiB].
long memory_kib(const char* which) {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line))
        if (line.rfind(which, 0) == 0) return std::stol(line.substr(std::string(which).size()));
    return -1;
}
/// Makes the peak the present (Linux >= 4.0: proc(5), /proc/PID/clear_refs).
void reset_peak() { std::ofstream("/proc/self/clear_refs") << "5"; }

}  // namespace

TEST(SuiteStream, FinishedFileHoldsTheCellsAndTheProductsOfAWholeComputation) {
    // 20 x 100 = 2000 cells a record: 8 records a chunk, so the 12 records take two slabs.
    const SuiteSpec spec = spec_of(20, 100, true);
    const IntegratorSettings settings;
    const std::vector<DamageState> states{{0.2, false}, {0.0, true}};
    TempDir dir;
    const std::string path = dir.file("suite.h5");
    SweepResults whole;
    const std::vector<SuiteFragility> returned = stream_all(path, spec, settings, 5, &whole)->finish(states, 1.0);
    EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));

    expect_same_results(read_suite_results(path, spec, settings), whole);
    EXPECT_EQ(read_suite_results(path, spec, settings).sensitive, whole.sensitive);
    const h5::File f = h5::File::open_read_only(path);
    EXPECT_EQ(h5::read_int64_attribute(f, "complete"), 1);
    ASSERT_EQ(returned.size(), spec.scenarios.size());
    for (std::size_t s = 0; s < spec.scenarios.size(); ++s) {
        const SuiteFragility fr = suite_fragility(spec, whole, s, states);
        const OverturningSpectrum o = overturning_spectrum(spec, whole, s);
        EXPECT_EQ(returned[s].exceed, fr.exceed);
        EXPECT_EQ(returned[s].sensitive, fr.sensitive);
        const h5::Group g = f.open_group("suite/" + spec.scenarios[s].name);
        EXPECT_EQ(h5::read_array<std::int32_t>(g.open_group("fragility"), "exceed").values, fr.exceed);
        EXPECT_EQ(h5::read_array<std::int32_t>(g.open_group("fragility"), "total").values, fr.total);
        EXPECT_EQ(h5::read_array<std::int32_t>(g.open_group("fragility"), "sensitive_runs").values, fr.sensitive);
        std::vector<double> medians;
        for (const FragilityFit& fit : fr.fits) medians.push_back(fit.curve.median);
        EXPECT_EQ(bits(h5::read_array<double>(g.open_group("fragility"), "median_intensity").values), bits(medians));
        EXPECT_EQ(bits(h5::read_array<double>(g.open_group("overturning"), "first_intensity").values), bits(o.first_intensity));
        EXPECT_EQ(bits(h5::read_array<double>(g.open_group("overturning"), "first_pga_g").values), bits(o.first_pga_g));
        EXPECT_EQ(h5::read_array<std::uint8_t>(g.open_group("overturning"), "safe_above").values, o.safe_above);
    }
}

TEST(SuiteStream, FinishingReadsASlabAtATimeNotTheResults) {
    // 2 scenarios x 12 records x 50 sizes x 2000 levels = 2.4e6 runs: 103 MiB of results held whole.
    const SuiteSpec spec = spec_of(50, 2000, false);
    const double whole_mib = static_cast<double>(spec.cell_count() * SweepResults::bytes_per_cell()) / (1 << 20);
    TempDir dir;
    const std::unique_ptr<SuiteStream> stream = stream_all(dir.file("big.h5"), spec, IntegratorSettings{}, 6, nullptr);
    reset_peak();
    const long before = memory_kib("VmRSS:");
    const auto t0 = std::chrono::steady_clock::now();
    ASSERT_EQ(stream->finish({{0.2, false}, {0.0, true}}, 1.0).size(), 2u);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double grown_mib = static_cast<double>(memory_kib("VmHWM:") - before) / 1024.0;
    // One slab of records (here one record, 1e5 runs: 4.5 MiB), HDF5's chunk caches (1 MiB a
    // dataset) and the products: measured 23-28 MiB.
    EXPECT_LT(grown_mib, 0.4 * whole_mib) << "finishing grew the peak memory by " << grown_mib << " MiB for "
                                         << whole_mib << " MiB of results";
    std::cout << "finishing " << spec.cell_count() << " runs took " << seconds << " s and grew the peak memory by "
              << grown_mib << " MiB\n";
}
