// The whole shared suite as one rank computes it, per integrator setting: the sweep default,
// the same with steps crossing the samples, and the paper's method (benchmarks/README.md,
// "Peers on the whole suite"). The records peers benchmark times twelve chosen runs; this one
// times every cell a fragility study computes (8640), most of them short or barely rocking,
// on records sampled at 50-200 Hz.
//   suite_peers --setting events48|events48_cross|paper [--lanes W] [--levels N] [--radii N]
//               [--records-csv FILE] [--cells FILE] [--tolerance TOL] [--paper-dt S]
// Prints one line: setting, lanes, cells, seconds of the cell computation (records are read
// before the clock starts), cells/s and the RK4 steps of all cells (trial steps of event
// searches included). --cells FILE writes one line per cell: index, record, outcome code,
// max |theta| / alpha, steps.
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "rocksweep/app/options.hpp"
#include "rocksweep/physics/integrator.hpp"
#include "rocksweep/records/suite_sweep.hpp"
#include "suite_smatteo.hpp"

using namespace rocksweep;

int main(int argc, char** argv) {
    std::string csv = "configs/records_suite.csv", setting, cells_path;
    std::size_t levels = 30, radii = 8;
    int lanes = 8;
    double tolerance = Options{}.numerics.tolerance;
    double paper_dt_s = IntegratorSettings{}.paper_dt_s;  // the paper's 0.0025 s unless given
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string k = argv[i], v = argv[i + 1];
        if (k == "--setting") setting = v;
        else if (k == "--records-csv") csv = v;
        else if (k == "--levels") levels = std::stoul(v);
        else if (k == "--radii") radii = std::stoul(v);
        else if (k == "--lanes") lanes = std::stoi(v);
        else if (k == "--cells") cells_path = v;
        else if (k == "--tolerance") tolerance = std::stod(v);
        else if (k == "--paper-dt") paper_dt_s = std::stod(v);
        else { std::fprintf(stderr, "suite_peers: unknown option %s\n", k.c_str()); return 2; }
    }
    IntegratorSettings is;  // the sweep's defaults: events, 48 steps per period, samples end steps
    if (setting == "paper") {
        is.method = Method::paper;
        is.paper_dt_s = paper_dt_s;
    }
    else if (setting == "events48_cross") is.steps_end_at_samples = false;
    else if (setting == "tolerance") is.tolerance = tolerance;  // the sweep's default since issue 22 unless given
    else if (setting != "events48") {
        std::fprintf(stderr, "suite_peers: --setting must be events48, events48_cross, tolerance or paper\n");
        return 2;
    }
    const SuiteSpec spec = bench::smatteo_suite(csv, levels, radii);
    const std::size_t n = spec.cell_count(), chunk = 64;  // as `rocksweep suite` hands cells to a rank
    std::vector<CellResult> out(n);
    const auto t0 = std::chrono::steady_clock::now();
    for (std::size_t first = 0; first < n; first += chunk)
        compute_suite_cells(spec, is, first, std::min(chunk, n - first), out.data() + first, lanes);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    long long steps = 0;
    for (const CellResult& c : out) steps += c.steps;
    std::printf("setting %s lanes %d cells %zu seconds %.4f cells_per_s %.1f steps %lld\n", setting.c_str(), lanes, n, s,
                static_cast<double>(n) / s, steps);
    if (!cells_path.empty()) {
        std::FILE* f = std::fopen(cells_path.c_str(), "w");
        if (!f) {
            std::fprintf(stderr, "suite_peers: cannot write %s\n", cells_path.c_str());
            return 1;
        }
        const std::size_t per_record = spec.radii_m.size() * spec.intensity.points;
        for (std::size_t i = 0; i < n; ++i)
            std::fprintf(f, "%zu %s %d %.17g %lld\n", i, spec.records[(i % spec.cells_per_scenario()) / per_record].entry.name.c_str(),
                         static_cast<int>(out[i].outcome), out[i].max_rotation, static_cast<long long>(out[i].steps));
        std::fclose(f);
    }
    return 0;
}
