// Work-precision of rocksweep's integrators: wall time against error, for the event-located RK4
// (Method::events) at a range of steps_per_period and for the paper's fixed-step scheme
// (Method::paper) at a range of dt, each against a high-accuracy run of the events method.
//
//   work_precision [--grid N] [--out DIR] [--quick]
//
// (a) Single runs through several impacts (S. Matteo, F_u = 0.4 m g): error = max |theta(t) -
//     theta_ref(t)| over fixed times and cases; reference = events at 8192 steps per period,
//     its own error = its difference from 4096. Time = one run from rest to one of the fixed
//     times, without an observer, mean over all (case, time) runs.
// (b) Spectra over omega_p/p in [1, 10] x a_p0/(alpha g) in [1, 22], N x N cells, free and
//     adaptive (K_min = 0.1 K_max): error = fraction of cells whose outcome differs from the
//     reference (events at 1024; its own uncertainty = the cells where 512 disagrees with it).
//     Time = wall time per cell, one thread, 8 lanes, as the sweep computes them. Also, over the
//     cells safe in both, |max|theta|/alpha - reference| (max and 99th percentile): a continuous
//     error that keeps falling once the outcomes no longer change.
//
// Writes DIR/work_precision_single.csv, DIR/work_precision_spectra.csv and
// DIR/work_precision_mismatches.csv (every cell of (b) whose outcome differs from the
// reference). A benchmark, never run by ctest: see benchmarks/WORK_PRECISION.md.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <time.h>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "rocksweep/physics/anchorage.hpp"
#include "rocksweep/physics/block.hpp"
#include "rocksweep/physics/integrator.hpp"
#include "rocksweep/physics/model.hpp"
#include "rocksweep/grid/sweep.hpp"

using namespace rocksweep;
using Clock = std::chrono::steady_clock;

namespace {

constexpr double kMinTiming = 0.2;  // seconds of timing per batch, at least
constexpr int kSingleBatches = 2;    // single runs: the fastest of this many batches
constexpr double kCheapPass = 2.0;   // spectra: a second batch when one pass is shorter [s]

const std::vector<double> kSteps = {8, 12, 16, 24, 32, 48, 64, 96, 128, 256};
const std::vector<double> kPaperDt = {0.01, 0.005, 0.0025, 0.001, 0.0005, 0.00025};
constexpr double kSingleRef = 8192, kSingleRefCheck = 4096;
constexpr double kSpectraRef = 1024, kSpectraRefCheck = 512;
constexpr double kDefaultSteps = 48, kPaperDefaultDt = 0.0025;

double seconds_since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

double thread_cpu_seconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

/// Seconds per call of one unit of work: wall (steady_clock) and this thread's CPU time. On a
/// shared machine the CPU time shows how much of the wall time other processes took.
struct Timing {
    double wall = INFINITY, cpu = INFINITY;
};

/// Calls f() until at least kMinTiming seconds have passed (one batch), `batches` times; the
/// per-call times of the batch with the least wall time.
template <class F>
Timing time_per_call(F&& f, int batches) {
    Timing best;
    for (int b = 0; b < batches; ++b) {
        std::size_t reps = 1, total = 0;
        double elapsed = 0.0;
        const auto t0 = Clock::now();
        const double c0 = thread_cpu_seconds();
        while (true) {
            for (std::size_t i = 0; i < reps; ++i) f();
            total += reps;
            elapsed = seconds_since(t0);
            if (elapsed >= kMinTiming) break;
            // aim a little past the target with the next round
            const double per = elapsed / static_cast<double>(total);
            const double want = (1.2 * kMinTiming - elapsed) / std::max(per, 1e-9);
            reps = std::max<std::size_t>(1, static_cast<std::size_t>(want));
        }
        const double wall = elapsed / static_cast<double>(total);
        if (wall < best.wall) best = {wall, (thread_cpu_seconds() - c0) / static_cast<double>(total)};
    }
    return best;
}

std::string load_average() {
    std::ifstream f("/proc/loadavg");
    std::string a, b, c;
    f >> a >> b >> c;
    return f ? a + " " + b + " " + c : "?";
}

IntegratorSettings events(double steps_per_period) {
    IntegratorSettings s;
    s.method = Method::events;
    s.steps_per_period = steps_per_period;
    return s;
}

IntegratorSettings paper(double dt) {
    IntegratorSettings s;
    s.method = Method::paper;
    s.paper_dt_s = dt;
    return s;
}

std::string setting_label(const IntegratorSettings& s) {
    char buf[64];
    if (s.method == Method::events)
        std::snprintf(buf, sizeof buf, "%g", s.steps_per_period);
    else
        std::snprintf(buf, sizeof buf, "%g", s.paper_dt_s);
    return buf;
}

/// Flags rocksweep's default setting and the paper's step in the tables.
const char* marker(const std::string& method, const std::string& setting) {
    if (method == "events" && setting == setting_label(events(kDefaultSteps))) return "   <- rocksweep default";
    if (method == "paper" && setting == setting_label(paper(kPaperDefaultDt))) return "   <- the paper's dt";
    return "";
}

// ---------------------------------------------------------------------------------------------
// (a) single runs

struct Case {
    std::string name, short_name;
    CellModel model;
    std::vector<double> times;
};

/// theta at exactly t_end. A run that overturned earlier lies at +-pi/2 from then on; a block
/// that came to rest and stays there (the run ends early, safe) is at 0.
struct Probe {
    double theta = NAN;
    int impacts = 0;
    bool overturned = false;
};

Probe theta_at(const CellModel& m, IntegratorSettings s, double t_end) {
    s.t_end_s = t_end;
    s.energy_stop = false;
    double theta = NAN, t1 = NAN;
    const CellResult r = integrate_cell(m, s, [&](const StepRecord& rec) {
        theta = rec.theta1;
        t1 = rec.t1;
    });
    Probe p;
    p.impacts = r.impacts;
    if (r.outcome == Outcome::overturned_impact || r.outcome == Outcome::overturned_no_impact) {
        p.overturned = true;
        p.theta = std::copysign(M_PI / 2, theta);
    } else if (r.outcome == Outcome::not_converged) {
        p.theta = NAN;
    } else {
        p.theta = t1 == t_end ? theta : 0.0;  // finished before t_end: at rest
    }
    return p;
}

struct SingleRow {
    std::string method, setting;
    Timing per_run;
    double error = NAN;
    std::vector<double> case_error;  ///< max over each case's times
    bool any_overturned = false;
};

std::vector<Case> single_cases(const Block& block, double strength) {
    auto sine = [&](double w, double a) {
        Pulse p;
        p.omega = w * block.p();
        p.ax_g = a * block.alpha_rad;
        return p;
    };
    const double alpha = block.alpha_rad;
    return {
        {"free w/p=6 a=4", "free", make_cell_model(block, free_anchorage(), sine(6, 4)), {2, 3, 4}},
        {"adaptive Kmin=0.5 w/p=4 a=2.7", "adapt0.5",
         make_cell_model(block, adaptive_anchorage(block, strength, alpha, 0.5), sine(4, 2.7)), {3, 4, 5}},
        {"constant tf=alpha w/p=4 a=2.7", "const",
         make_cell_model(block, constant_anchorage(block, strength, alpha), sine(4, 2.7)), {3, 4, 5}},
        {"free linearised w/p=6 a=4", "free-lin",
         make_cell_model(block, free_anchorage(), sine(6, 4), Equations::linearised), {2, 3, 4}},
    };
}

/// Error of `s` against `ref` (theta at each case's times), and its time per run.
SingleRow measure_single(const std::vector<Case>& cases, const std::vector<std::vector<double>>& ref,
                         const IntegratorSettings& s, const std::string& method) {
    SingleRow row;
    row.method = method;
    row.setting = setting_label(s);
    row.error = 0.0;
    row.case_error.assign(cases.size(), 0.0);
    for (std::size_t c = 0; c < cases.size(); ++c) {
        for (std::size_t k = 0; k < cases[c].times.size(); ++k) {
            const Probe p = theta_at(cases[c].model, s, cases[c].times[k]);
            row.any_overturned |= p.overturned;
            double err = std::abs(p.theta - ref[c][k]);
            if (std::isnan(err)) err = INFINITY;  // not converged
            row.case_error[c] = std::max(row.case_error[c], err);
            row.error = std::max(row.error, err);
        }
    }
    // Timing: the same runs without an observer (what a sweep pays), mean over all runs.
    std::size_t runs = 0;
    for (const Case& c : cases) runs += c.times.size();
    volatile double sink = 0.0;
    const Timing per_set = time_per_call([&] {
        for (const Case& c : cases) {
            for (double t : c.times) {
                IntegratorSettings st = s;
                st.t_end_s = t;
                st.energy_stop = false;
                sink = sink + integrate_cell(c.model, st).max_rotation;
            }
        }
    }, kSingleBatches);
    row.per_run = {per_set.wall / static_cast<double>(runs), per_set.cpu / static_cast<double>(runs)};
    return row;
}

// ---------------------------------------------------------------------------------------------
// (b) spectra

struct Spectrum {
    std::vector<std::uint8_t> outcome;
    std::vector<double> max_rotation;  ///< max |theta| / alpha
};

struct SpectraRow {
    std::string method, setting, scenario;
    Timing per_cell;
    std::size_t mismatched = 0, cells = 0, not_converged = 0;
    /// |max_rotation - reference| over the cells safe in both: a continuous error that keeps
    /// falling after the outcomes have stopped changing. Maximum and 99th percentile.
    double rotation_err_max = 0.0, rotation_err_p99 = 0.0;
    double fraction() const { return static_cast<double>(mismatched) / static_cast<double>(cells); }
};

/// Outcomes of every cell of scenario `sc` of `spec`, and the time per cell: one pass over all
/// cells, repeated to kMinTiming; a cheap setting gets a second such batch and the faster counts.
Spectrum run_spectrum(const SweepSpec& spec, std::size_t sc, const IntegratorSettings& s, Timing* per_cell) {
    const std::size_t n = spec.cells_per_scenario(), first = sc * n;
    std::vector<CellResult> out(n);
    *per_cell = Timing{};
    for (int batch = 0; batch < 2; ++batch) {
        std::size_t passes = 0;
        const auto t0 = Clock::now();
        const double c0 = thread_cpu_seconds();
        do {
            compute_cells(spec, s, first, n, out.data(), 8);
            ++passes;
        } while (seconds_since(t0) < kMinTiming);
        const double wall = seconds_since(t0), cpu = thread_cpu_seconds() - c0;
        const double cells = static_cast<double>(passes * n);
        if (wall / cells < per_cell->wall) *per_cell = {wall / cells, cpu / cells};
        if (wall / static_cast<double>(passes) >= kCheapPass) break;
    }
    Spectrum o;
    o.outcome.resize(n);
    o.max_rotation.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        o.outcome[i] = static_cast<std::uint8_t>(out[i].outcome);
        o.max_rotation[i] = out[i].max_rotation;
    }
    return o;
}

// ---------------------------------------------------------------------------------------------
// output

void write_single_csv(const std::filesystem::path& path, const std::vector<SingleRow>& rows) {
    std::ofstream f(path);
    f << "method,setting,wall_s_per_cell_or_run,error,cpu_s_per_cell_or_run\n";
    char buf[200];
    for (const SingleRow& r : rows) {
        std::snprintf(buf, sizeof buf, "%s,%s,%.6e,%.6e,%.6e\n", r.method.c_str(), r.setting.c_str(),
                      r.per_run.wall, r.error, r.per_run.cpu);
        f << buf;
    }
    if (!f) throw std::runtime_error("cannot write " + path.string());
}

void write_spectra_csv(const std::filesystem::path& path, const std::vector<SpectraRow>& rows) {
    std::ofstream f(path);
    f << "method,setting,scenario,wall_s_per_cell_or_run,error,mismatched_cells,cells,cells_per_s,"
         "cpu_s_per_cell_or_run,max_rotation_err_max,max_rotation_err_p99\n";
    char buf[300];
    for (const SpectraRow& r : rows) {
        std::snprintf(buf, sizeof buf, "%s,%s,%s,%.6e,%.6e,%zu,%zu,%.1f,%.6e,%.6e,%.6e\n", r.method.c_str(),
                      r.setting.c_str(), r.scenario.c_str(), r.per_cell.wall, r.fraction(), r.mismatched, r.cells,
                      1.0 / r.per_cell.wall, r.per_cell.cpu, r.rotation_err_max, r.rotation_err_p99);
        f << buf;
    }
    if (!f) throw std::runtime_error("cannot write " + path.string());
}

int run(std::size_t grid, const std::filesystem::path& out_dir) {
    const auto t_start = Clock::now();
    std::filesystem::create_directories(out_dir);
    std::printf("work_precision: grid %zu x %zu, one thread; load average at start: %s\n", grid, grid,
                load_average().c_str());

    const Block block = rectangular_block(0.30, 1.36, 3361.0);
    const double strength = 0.4 * block.mass_kg * block.gravity;

    // ---------------- (a) single runs ----------------
    std::fprintf(stderr, "[work_precision] (a) single runs ...\n");
    const std::vector<Case> cases = single_cases(block, strength);
    std::vector<std::vector<double>> ref(cases.size()), ref_check(cases.size());
    std::vector<std::vector<int>> ref_impacts(cases.size());
    double ref_error = 0.0;
    for (std::size_t c = 0; c < cases.size(); ++c) {
        for (double t : cases[c].times) {
            const Probe p = theta_at(cases[c].model, events(kSingleRef), t);
            const Probe q = theta_at(cases[c].model, events(kSingleRefCheck), t);
            ref[c].push_back(p.theta);
            ref_check[c].push_back(q.theta);
            ref_impacts[c].push_back(p.impacts);
            ref_error = std::max(ref_error, std::abs(p.theta - q.theta));
        }
    }
    std::vector<SingleRow> single;
    for (double n : kSteps) single.push_back(measure_single(cases, ref, events(n), "events"));
    for (double dt : kPaperDt) single.push_back(measure_single(cases, ref, paper(dt), "paper"));
    {
        SingleRow r = measure_single(cases, ref, events(kSingleRefCheck), "reference");
        r.setting = "4096_vs_8192";
        r.error = ref_error;
        single.push_back(r);
    }
    const double single_s = seconds_since(t_start);

    std::printf("\n== (a) Single runs: S. Matteo, F_u = 0.4 m g; error = max |theta(t) - theta_ref(t)| ==\n");
    std::printf("reference: events at %g steps/period; |ref(%g) - ref(%g)| = %.2e rad\n", kSingleRef,
                kSingleRef, kSingleRefCheck, ref_error);
    for (std::size_t c = 0; c < cases.size(); ++c) {
        std::printf("  %-32s", cases[c].name.c_str());
        for (std::size_t k = 0; k < cases[c].times.size(); ++k)
            std::printf("  t=%g: theta=%+.6f rad (%d impacts)", cases[c].times[k], ref[c][k], ref_impacts[c][k]);
        std::printf("\n");
    }
    std::printf("\n%-10s %-13s %12s %10s %10s %13s %11s |", "method", "setting", "us per run", "(CPU)",
                "runs/s", "max err [rad]", "err / alpha");
    for (const Case& c : cases) std::printf(" %10s", c.short_name.c_str());
    std::printf("\n");
    for (const SingleRow& r : single) {
        std::printf("%-10s %-13s %12.2f %10.2f %10.0f %13.3e %11.3e |", r.method.c_str(), r.setting.c_str(),
                    1e6 * r.per_run.wall, 1e6 * r.per_run.cpu, 1.0 / r.per_run.wall, r.error,
                    r.error / block.alpha_rad);
        for (double e : r.case_error) std::printf(" %10.2e", e);
        std::printf("%s%s\n",
                    marker(r.method, r.setting), r.any_overturned ? "  (a run overturned)" : "");
    }
    std::fflush(stdout);
    write_single_csv(out_dir / "work_precision_single.csv", single);

    // ---------------- (b) spectra ----------------
    SweepSpec spec;
    spec.block = block;
    spec.omega_ratio = Axis{1.0, 10.0, grid};
    spec.amplitude_ratio = Axis{1.0, 22.0, grid};
    spec.scenarios.push_back(Scenario{"free", free_anchorage(), 0.0, 1.0});
    spec.scenarios.push_back(
        Scenario{"adaptive_kmin0.1", adaptive_anchorage(block, strength, block.alpha_rad, 0.1), 1.0, 0.1});
    const std::size_t n = spec.cells_per_scenario();

    std::vector<SpectraRow> spectra;
    std::ofstream mism(out_dir / "work_precision_mismatches.csv");
    mism << "method,setting,scenario,omega_ratio,amplitude_ratio,outcome,reference_outcome,check_outcome\n";
    std::vector<std::vector<std::size_t>> ref_disagree(spec.scenarios.size());

    for (std::size_t sc = 0; sc < spec.scenarios.size(); ++sc) {
        const std::string& name = spec.scenarios[sc].name;
        std::fprintf(stderr, "[work_precision] (b) %s, %zu x %zu cells: reference ...\n", name.c_str(), grid, grid);
        Timing t_ref, t_chk;
        const Spectrum ref_s = run_spectrum(spec, sc, events(kSpectraRef), &t_ref);
        const Spectrum chk_s = run_spectrum(spec, sc, events(kSpectraRefCheck), &t_chk);
        const std::vector<std::uint8_t>& ref_o = ref_s.outcome;
        const std::vector<std::uint8_t>& chk_o = chk_s.outcome;
        auto cell_line = [&](const std::string& method, const std::string& setting, std::size_t i,
                             std::uint8_t o) {
            char buf[200];
            std::snprintf(buf, sizeof buf, "%s,%s,%s,%.6f,%.6f,%d,%d,%d\n", method.c_str(), setting.c_str(),
                          name.c_str(), spec.omega_ratio.at(i % grid), spec.amplitude_ratio.at(i / grid), o,
                          ref_o[i], chk_o[i]);
            mism << buf;
        };
        auto compare = [&](const std::string& method, const std::string& setting, const Spectrum& sp,
                           Timing per_cell) {
            const std::vector<std::uint8_t>& o = sp.outcome;
            SpectraRow r{method, setting, name, per_cell, 0, n, 0};
            std::vector<double> d;
            for (std::size_t i = 0; i < n; ++i) {
                if (o[i] == static_cast<std::uint8_t>(Outcome::not_converged)) ++r.not_converged;
                if (o[i] != ref_o[i]) {
                    ++r.mismatched;
                    cell_line(method, setting, i, o[i]);
                } else if (o[i] == static_cast<std::uint8_t>(Outcome::safe)) {
                    d.push_back(std::abs(sp.max_rotation[i] - ref_s.max_rotation[i]));
                }
            }
            if (!d.empty()) {
                const auto k = static_cast<std::ptrdiff_t>(0.99 * static_cast<double>(d.size() - 1));
                std::nth_element(d.begin(), d.begin() + k, d.end());
                r.rotation_err_p99 = d[static_cast<std::size_t>(k)];
                r.rotation_err_max = *std::max_element(d.begin(), d.end());
            }
            spectra.push_back(r);
        };
        {
            SpectraRow r{"reference", "1024", name, t_ref, 0, n, 0};
            spectra.push_back(r);
        }
        for (std::size_t i = 0; i < n; ++i)
            if (chk_o[i] != ref_o[i]) ref_disagree[sc].push_back(i);
        compare("reference", "512_vs_1024", chk_s, t_chk);
        for (double steps : kSteps) {
            std::fprintf(stderr, "[work_precision] (b) %s: events %g\n", name.c_str(), steps);
            Timing t;
            compare("events", setting_label(events(steps)), run_spectrum(spec, sc, events(steps), &t), t);
        }
        for (double dt : kPaperDt) {
            std::fprintf(stderr, "[work_precision] (b) %s: paper %g\n", name.c_str(), dt);
            Timing t;
            compare("paper", setting_label(paper(dt)), run_spectrum(spec, sc, paper(dt), &t), t);
        }
    }
    mism.close();
    write_spectra_csv(out_dir / "work_precision_spectra.csv", spectra);

    std::printf("\n== (b) Spectra: %zu x %zu cells per scenario, omega_p/p in [1, 10], a_p0/(alpha g) in [1, 22]; "
                "error = fraction of cells whose outcome differs from the reference (events %g) ==\n",
                grid, grid, kSpectraRef);
    for (const Scenario& scn : spec.scenarios) {
        std::printf("\n-- %s --\n", scn.name.c_str());
        std::printf("%-10s %-13s %12s %10s %10s %11s %12s %8s %11s %11s\n", "method", "setting", "us per cell",
                    "(CPU)", "cells/s", "mismatched", "fraction", "n.conv.", "drot max", "drot p99");
        for (const SpectraRow& r : spectra) {
            if (r.scenario != scn.name) continue;
            std::printf("%-10s %-13s %12.2f %10.2f %10.0f %11zu %12.3e %8zu %11.2e %11.2e%s\n", r.method.c_str(),
                        r.setting.c_str(), 1e6 * r.per_cell.wall, 1e6 * r.per_cell.cpu, 1.0 / r.per_cell.wall,
                        r.mismatched, r.fraction(), r.not_converged, r.rotation_err_max, r.rotation_err_p99,
                        marker(r.method, r.setting));
        }
    }
    std::printf("\nCells where events %g and %g disagree (the reference's own uncertainty):\n", kSpectraRefCheck,
                kSpectraRef);
    for (std::size_t sc = 0; sc < spec.scenarios.size(); ++sc) {
        std::printf("  %s: %zu", spec.scenarios[sc].name.c_str(), ref_disagree[sc].size());
        std::size_t shown = 0;
        for (std::size_t i : ref_disagree[sc]) {
            if (shown++ == 8) { std::printf(" ..."); break; }
            std::printf("  (w/p=%.4f, a=%.4f)", spec.omega_ratio.at(i % grid), spec.amplitude_ratio.at(i / grid));
        }
        std::printf("\n");
    }
    const double total = seconds_since(t_start);
    std::printf("\nwrote %s, %s, %s\n", (out_dir / "work_precision_single.csv").c_str(),
                (out_dir / "work_precision_spectra.csv").c_str(), (out_dir / "work_precision_mismatches.csv").c_str());
    std::printf("benchmark time: %.1f s (single runs %.1f s, spectra %.1f s); load average at end: %s\n", total,
                single_s, total - single_s, load_average().c_str());
    std::printf("times: wall (steady_clock), fastest of the batches; (CPU) = this thread's CPU time over the same "
                "batch: where wall >> CPU, other processes took the core.\n"
                "drot: |max|theta|/alpha - reference| over the cells safe in both (max, 99th percentile).\n");
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Work-precision of rocksweep's integrators: wall time vs error (see benchmarks/WORK_PRECISION.md)"};
    std::size_t grid = 200;
    std::string out = "benchmarks/results";
    bool quick = false;
    app.add_option("--grid", grid, "spectrum grid N x N")->check(CLI::Range(2, 100000));
    app.add_option("--out", out, "output directory");
    app.add_flag("--quick", quick, "smoke run: 60 x 60 grid");
    CLI11_PARSE(app, argc, argv);
    if (quick && app.count("--grid") == 0) grid = 60;
    try {
        return run(grid, out);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "work_precision: %s\n", e.what());
        return 1;
    }
}
