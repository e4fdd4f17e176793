// rocksweep's side of the records peer benchmark (benchmarks/README.md, "Peers on recorded
// ground motions"): the S. Matteo block under the records of a suite file at the scales of its
// `scales` column, free and with the constant anchorage theta_f = alpha, F_u = 0.4 m g.
//
//   records_peers histories --suite S --out DIR   theta at every record sample, per setting
//   records_peers time --suite S [--min-seconds T] [--lanes W] [--only LABEL]   timed passes of each setting
//
// `histories` writes DIR/records_peers_<label>.csv (run, t, theta, one row per record sample up
// to the record's end or the overturning) and DIR/records_peers_<label>_outcomes.csv for the
// timed settings and for the two tight settings that make the reference. `time` integrates
// every run as a sweep would (integrate_cells, one thread, no observer), each setting repeated
// until it has taken T seconds, and prints one line per setting: label, runs per pass, passes,
// wall s, CPU s. One lane by default: with 12 runs a pass at 8 lanes ends with idle lanes that
// still compute (measured slower than 1 lane, for rocksweep's settings and the paper's alike).
// benchmarks/records_peers.sh calls both, interleaved with the scipy peer, and
// benchmarks/records_peers_table.py makes the table.
#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <exception>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "rocksweep/physics/anchorage.hpp"
#include "rocksweep/physics/block.hpp"
#include "rocksweep/physics/integrator.hpp"
#include "rocksweep/records/intensity.hpp"
#include "rocksweep/physics/model.hpp"
#include "rocksweep/records/record.hpp"
#include "rocksweep/records/record_suite.hpp"

using namespace rocksweep;

namespace {

/// One integrator setting: the method, its step knob and the settling threshold (/ p alpha).
struct Setting {
    std::string label;
    Method method;
    double steps_per_period;  ///< events
    double impact_threshold;
    bool timed;               ///< false: only histories (the reference pair)
    bool steps_end_at_samples = true;  ///< events: every record sample ends a step (else they cross)
    double tolerance = 0.0;  ///< events: > 0, steps chosen from the error (IntegratorSettings::tolerance)
    double paper_dt_s = 0.0025;  ///< paper: its fixed step
};

// The reference pair: two tight settings that differ in both knobs and in how a step meets the
// record's samples (the reference's steps end at each, its check's cross them on moment nodes).
// A run on which they disagree is sensitive to perturbations of that size (chaotic), and is
// excluded from the theta error claim. The timed settings: the sweep's default (48, 1e-3), simulate's (384,
// 1e-4, include/rocksweep/physics/history.hpp) and the paper's method (dt 0.0025 s, threshold 1e-3).
const std::vector<Setting> kSettings = {
    {"reference", Method::events, 4096, 1e-8, false, true},
    {"reference_check", Method::events, 2048, 1e-7, false, false},
    {"events48", Method::events, 48, 1e-3, true, true},
    {"events48_cross", Method::events, 48, 1e-3, true, false},
    {"events96_cross", Method::events, 96, 1e-3, true, false},
    {"events384", Method::events, 384, 1e-4, true, true},
    // Error-controlled steps (issue 22): the sweep's default and simulate's.
    // Looser tolerances, for the work-precision records panel (benchmarks/records_panel.sh).
    {"tol1e-6", Method::events, 48, 1e-3, true, true, 1e-6},
    {"tol1e-7", Method::events, 48, 1e-3, true, true, 1e-7},
    {"tol1e-8", Method::events, 48, 1e-3, true, true, 1e-8},
    {"tol1e-9", Method::events, 384, 1e-4, true, true, 1e-9},
    {"tol1e-10", Method::events, 384, 1e-4, true, true, 1e-10},
    {"paper", Method::paper, 0, 1e-3, true},
    // The paper's method at finer steps: first order, its error halves with dt (issue 22's
    // work-precision comparison at equal error).
    {"paper_dt1.3e-3", Method::paper, 0, 1e-3, true, true, 0.0, 0.0025 / 2},
    {"paper_dt6.3e-4", Method::paper, 0, 1e-3, true, true, 0.0, 0.0025 / 4},
    {"paper_dt3.1e-4", Method::paper, 0, 1e-3, true, true, 0.0, 0.0025 / 8},
    {"paper_dt1.6e-4", Method::paper, 0, 1e-3, true, true, 0.0, 0.0025 / 16},
};

/// One run: a record at a scale, with one anchorage.
struct Run {
    std::string name, record, anchorage;
    double scale = 1.0, dt_s = 0.0, pga_over_g_tan_alpha = 0.0;
    std::size_t samples = 0;
    Pulse pulse;
    Anchorage anch;
};

/// The S. Matteo block of configs/smatteo.toml (b = 0.30 m, h = 1.36 m, m = 3361 kg).
Block smatteo() { return rectangular_block(0.30, 1.36, 3361.0, 9.81); }

std::vector<double> parse_scales(const std::string& text, const std::string& record) {
    std::vector<double> v;
    std::istringstream in(text);
    for (double s; in >> s;) v.push_back(s);
    if (v.empty() || !in.eof()) throw std::runtime_error("record " + record + ": column scales must hold numbers, got '" + text + "'");
    return v;
}

/// Every (record, scale, anchorage) of the suite, in suite order, scales ascending as written.
std::vector<Run> read_runs(const std::string& suite_path) {
    const RecordSuite suite = read_record_suite(suite_path);
    std::size_t scales_col = suite.metadata_columns.size();
    for (std::size_t i = 0; i < suite.metadata_columns.size(); ++i)
        if (suite.metadata_columns[i] == "scales") scales_col = i;
    if (scales_col == suite.metadata_columns.size()) throw std::runtime_error(suite_path + ": no column 'scales'");
    const Block block = smatteo();
    const double strength = 0.4 * block.mass_kg * block.gravity;
    std::vector<Run> runs;
    for (const SuiteRecord& sr : suite.records) {
        for (double scale : parse_scales(sr.metadata[scales_col], sr.name)) {
            RecordSource src = sr.source;
            src.scale = scale;
            const Record rec = read_record(src);
            for (const char* anch : {"free", "constant"}) {
                Run r;
                r.record = sr.name;
                r.anchorage = anch;
                r.scale = scale;
                char buf[64];
                std::snprintf(buf, sizeof buf, "_x%g_", scale);
                r.name = sr.name + buf + anch;
                r.dt_s = rec.dt_s;
                r.samples = rec.ax_g.size();
                r.pga_over_g_tan_alpha = pga_over_g_tan_alpha(intensity_measures(rec).pga_g, block.alpha_rad, block.gravity);
                r.pulse = to_pulse(rec, block.gravity);
                r.anch = std::string(anch) == "free" ? free_anchorage() : constant_anchorage(block, strength, block.alpha_rad);
                runs.push_back(std::move(r));
            }
        }
    }
    return runs;
}

std::vector<CellModel> models(const std::vector<Run>& runs, const Setting& s) {
    std::vector<CellModel> m;
    for (const Run& r : runs) m.push_back(make_cell_model(smatteo(), r.anch, r.pulse, Equations::nonlinear, s.impact_threshold));
    return m;
}

IntegratorSettings integrator(const Setting& s) {
    IntegratorSettings is;
    is.method = s.method;
    if (s.method == Method::events) is.steps_per_period = s.steps_per_period;
    is.steps_end_at_samples = s.steps_end_at_samples;
    is.tolerance = s.tolerance;
    is.paper_dt_s = s.paper_dt_s;
    return is;
}

/// theta at the record's sample times k dt, from the cubic Hermite interpolant of each step
/// (exact at step ends; inside a step as accurate as its ends, benchmarks/RECORD_STEPS.md), until
/// the record ends or the block overturns.
std::vector<double> sampled_history(const Run& r, const CellModel& m, const Setting& s, CellResult& result) {
    std::vector<double> theta;
    std::size_t k = 0;
    result = integrate_cell(m, integrator(s), [&](const StepRecord& step) {
        for (; k < r.samples; ++k) {
            const double t = static_cast<double>(k) * r.dt_s;
            if (t > step.t1) break;
            double th, thd;
            step.at(std::max(t, step.t0), th, thd);
            theta.push_back(th);
        }
    });
    return theta;
}

void write_histories(const std::vector<Run>& runs, const Setting& s, const std::filesystem::path& dir) {
    const std::vector<CellModel> m = models(runs, s);
    const std::filesystem::path hist = dir / ("records_peers_" + s.label + ".csv");
    const std::filesystem::path outc = dir / ("records_peers_" + s.label + "_outcomes.csv");
    std::ofstream h(hist), o(outc);
    h << "run,t,theta\n";
    o << "run,record,scale,anchorage,pga_over_g_tan_alpha,duration_s,outcome,t_overturn_s,max_rotation,impacts,steps\n";
    char buf[400];
    for (std::size_t i = 0; i < runs.size(); ++i) {
        CellResult res;
        const std::vector<double> th = sampled_history(runs[i], m[i], s, res);
        for (std::size_t k = 0; k < th.size(); ++k) {
            std::snprintf(buf, sizeof buf, "%s,%.17g,%.17g\n", runs[i].name.c_str(), static_cast<double>(k) * runs[i].dt_s, th[k]);
            h << buf;
        }
        std::snprintf(buf, sizeof buf, "%s,%s,%g,%s,%.6g,%.17g,%s,%.17g,%.17g,%d,%lld\n", runs[i].name.c_str(),
                      runs[i].record.c_str(), runs[i].scale, runs[i].anchorage.c_str(), runs[i].pga_over_g_tan_alpha,
                      static_cast<double>(runs[i].samples - 1) * runs[i].dt_s, to_string(res.outcome).c_str(),
                      res.t_overturn_s, res.max_rotation, res.impacts, static_cast<long long>(res.steps));
        o << buf;
    }
    if (!h || !o) throw std::runtime_error("cannot write " + hist.string() + " or " + outc.string());
    std::fprintf(stderr, "[records_peers] wrote %s\n", hist.c_str());
}

double cpu_seconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

/// Passes over all runs until `min_seconds` of wall time: (passes, wall s, CPU s).
struct Timed {
    long passes = 0;
    double wall = 0.0, cpu = 0.0;
};

Timed time_setting(const std::vector<CellModel>& cells, const Setting& s, int lanes, double min_seconds) {
    const IntegratorSettings is = integrator(s);
    std::vector<CellResult> out(cells.size());
    Timed t;
    const auto w0 = std::chrono::steady_clock::now();
    const double c0 = cpu_seconds();
    do {
        integrate_cells(cells, out, is, lanes);
        ++t.passes;
        t.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count();
    } while (t.wall < min_seconds);
    t.cpu = cpu_seconds() - c0;
    return t;
}

int run(const std::string& mode, const std::string& suite, const std::string& out, int lanes, double min_seconds,
        const std::string& only) {
    const std::vector<Run> runs = read_runs(suite);
    if (mode == "histories") {
        std::filesystem::create_directories(out);
        for (const Setting& s : kSettings) write_histories(runs, s, out);
        return 0;
    }
    // time: every timed setting once, in order; the shell script alternates with the scipy peer.
    for (const Setting& s : kSettings) {
        if (!s.timed || (!only.empty() && s.label != only)) continue;
        const Timed t = time_setting(models(runs, s), s, lanes, min_seconds);
        std::printf("%s,%zu,%ld,%.6f,%.6f\n", s.label.c_str(), runs.size(), t.passes, t.wall, t.cpu);
        std::fflush(stdout);
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"rocksweep's side of the records peer benchmark (benchmarks/README.md)"};
    std::string mode, suite = "benchmarks/records_peers.csv", out = "benchmarks/results";
    double min_seconds = 0.5;
    int lanes = 1;
    std::string only;
    app.add_option("mode", mode, "histories | time")->required()->check(CLI::IsMember({"histories", "time"}));
    app.add_option("--suite", suite, "record suite with a 'scales' column")->check(CLI::ExistingFile)->capture_default_str();
    app.add_option("--out", out, "folder for the histories")->capture_default_str();
    app.add_option("--min-seconds", min_seconds, "time: wall seconds per setting, at least")->check(CLI::Range(0.0, 600.0))->capture_default_str();
    app.add_option("--lanes", lanes, "time: lanes of integrate_cells")->check(CLI::IsMember({1, 4, 8, 16}))->capture_default_str();
    app.add_option("--only", only, "time: this setting alone (for a profiler)")
        ->check(CLI::IsMember({"events48", "events48_cross", "events96_cross", "events384", "tol1e-6", "tol1e-7", "tol1e-8",
                               "tol1e-9", "tol1e-10", "paper", "paper_dt1.3e-3", "paper_dt6.3e-4", "paper_dt3.1e-4",
                               "paper_dt1.6e-4"}));
    CLI11_PARSE(app, argc, argv);
    try {
        return run(mode, suite, out, lanes, min_seconds, only);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "records_peers: %s\n", e.what());
        return 1;
    }
}
