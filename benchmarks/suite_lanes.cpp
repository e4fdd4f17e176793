// The cells of a record suite, timed: configs/suite_smatteo.toml's suite (S. Matteo, the shared
// records, 30 PGA levels 0.05-1.5 g, 8 block sizes, free / constant theta_f = alpha / adaptive
// rho = 0.1) computed in chunks of 64 cells as `rocksweep suite` hands them to a rank, on one
// thread. Prints one line: cells, wall seconds of the cell computation only (records are read
// before the clock starts), cells/s, and a hash of every result bit (equal hashes: the same
// results). Written against the API that main and records-lanes share, so that
// benchmarks/suite_lanes.sh builds it in both trees.
// --outcomes FILE writes one line per cell: index, record, outcome code, max |theta| / alpha.
//   suite_lanes [--records-csv FILE] [--levels N] [--radii N] [--lanes W] [--chunk N] [--outcomes FILE]
#include <algorithm>
#include <bit>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "rocksweep/physics/integrator.hpp"
#include "rocksweep/records/suite_sweep.hpp"
#include "suite_smatteo.hpp"

using namespace rocksweep;

namespace {

std::uint64_t mix(std::uint64_t h, std::uint64_t x) { return (h ^ x) * 1099511628211ull; }  // FNV-1a step

std::uint64_t hash(const std::vector<CellResult>& r) {
    std::uint64_t h = 14695981039346656037ull;
    for (const CellResult& c : r) {
        for (double x : {c.max_rotation, c.t_overturn_s, c.peak_force_ratio, c.mu_required})
            h = mix(h, std::bit_cast<std::uint64_t>(x));
        for (std::int64_t x : {std::int64_t{c.impacts}, std::int64_t{c.impacts_total}, c.steps,
                               std::int64_t(c.outcome), std::int64_t{c.broken}, std::int64_t{c.pivot_uplift}})
            h = mix(h, static_cast<std::uint64_t>(x));
    }
    return h;
}

}  // namespace

int main(int argc, char** argv) {
    std::string csv = "configs/records_suite.csv", outcomes;
    std::size_t levels = 30, radii = 8, chunk = 64;
    int lanes = 8;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string k = argv[i], v = argv[i + 1];
        if (k == "--records-csv") csv = v;
        else if (k == "--levels") levels = std::stoul(v);
        else if (k == "--radii") radii = std::stoul(v);
        else if (k == "--lanes") lanes = std::stoi(v);
        else if (k == "--chunk") chunk = std::stoul(v);
        else if (k == "--outcomes") outcomes = v;
        else { std::fprintf(stderr, "suite_lanes: unknown option %s\n", k.c_str()); return 2; }
    }
    const SuiteSpec spec = bench::smatteo_suite(csv, levels, radii);
    const std::size_t n = spec.cell_count();
    std::vector<CellResult> out(n);
    const auto t0 = std::chrono::steady_clock::now();
    for (std::size_t first = 0; first < n; first += chunk)
        compute_suite_cells(spec, IntegratorSettings{}, first, std::min(chunk, n - first), out.data() + first, lanes);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("cells %zu seconds %.4f cells_per_s %.1f hash %016llx\n", n, s, static_cast<double>(n) / s,
                static_cast<unsigned long long>(hash(out)));
    if (!outcomes.empty()) {
        std::FILE* f = std::fopen(outcomes.c_str(), "w");
        const std::size_t per_record = spec.radii_m.size() * spec.intensity.points;
        for (std::size_t i = 0; i < n; ++i)
            std::fprintf(f, "%zu %s %d %.17g\n", i, spec.records[(i % spec.cells_per_scenario()) / per_record].entry.name.c_str(),
                         static_cast<int>(out[i].outcome), out[i].max_rotation);
        std::fclose(f);
    }
    return 0;
}
