#include "rocksweep/app/cli.hpp"

#include <CLI/CLI.hpp>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <regex>
#include <sstream>

#include "rocksweep/app/basin_command.hpp"
#include "rocksweep/app/synth_command.hpp"
#include "rocksweep/app/config_file.hpp"
#include "rocksweep/app/design_command.hpp"
#include "rocksweep/app/info_command.hpp"
#include "rocksweep/app/risk_command.hpp"
#include "rocksweep/app/suite_command.hpp"
#include "rocksweep/core/errors.hpp"
#include "rocksweep/grid/parameter_axis.hpp"
#include "rocksweep/physics/history.hpp"
#include "rocksweep/app/option_checks.hpp"
#include "rocksweep/app/option_combinations.hpp"


namespace rocksweep {

namespace {

// Ranges: what a physicist would accept for a block, a pulse or an anchorage, and no wider, so
// that no derived quantity can overflow or vanish in the kernel (README, "Command line").
const std::string m = "m", kg = "kg", rad = "rad", none;

/// CLI11's form of a vector default, "[a,b]", each number to its last digit (CLI11's own keeps 6).
std::string exact_list(const std::vector<double>& v) {
    std::string out;
    for (const double x : v) {
        char buf[32];
        const auto end = std::to_chars(buf, buf + sizeof buf, x).ptr;
        out += (out.empty() ? "[" : ",") + std::string(buf, end);
    }
    return out + "]";
}

void add_model_options(CLI::App& app, Options& o) {
    BlockOptions& b = o.block;
    const char* blk = "Block";
    // Sizes from a 1 mm specimen to a 1 km tower; masses from 1 g to a 1 Mt monolith.
    app.add_option("--half-width", b.half_width_m, "Half-width b of the rectangular block [m]")
        ->check(number_in(1e-3, 1e3, m))->capture_default_str()->group(blk);
    app.add_option("--half-height", b.half_height_m, "Half-height h [m], at most 1e4 b")->check(number_in(1e-3, 1e3, m))->capture_default_str()->group(blk);
    app.add_option("--mass", b.mass_kg, "Mass m [kg]")->check(number_in(1e-3, 1e9, kg))->capture_default_str()->group(blk);
    app.add_option("--radius", b.radius_m, "Equivalent block: R, corner to centre of mass [m] (with --alpha)")
        ->check(number_in(1e-3, 1e3, m))->group(blk);
    app.add_option("--alpha", b.alpha_rad, "Equivalent block: slenderness angle [rad] (with --radius), at least atan(1e-4) (h/b <= 1e4)")
        ->check(number_in(min_alpha_rad, M_PI / 2, rad, false, true))->group(blk);
    app.add_option("--inertia-ratio", b.inertia_ratio, "Equivalent block: I0/(m R^2) (default 4/3)")
        ->check(number_in(1.0, max_inertia_ratio, none))->group(blk);
    app.add_option("--frequency-parameter", b.p, "Equivalent block: p [rad/s] instead of --inertia-ratio")
        ->check(number_in(1e-2, 1e3, "rad/s"))->group(blk);
    app.add_option("--gravity", b.gravity, "g [m/s^2]")->check(number_in(0.1, 100, "m/s^2"))->capture_default_str()->group(blk);
    app.add_option("--restitution", b.restitution, "Impact velocity ratio e, at most Housner's (default: Housner's)")
        ->check(number_in(0, 1, none, true))->group(blk);
    app.add_option("--equations", b.equations, "nonlinear | linearised (sin x = x, cos x = 1)")
        ->check(one_of({"nonlinear", "linearised", "linearized"}))->capture_default_str()->group(blk);

    const char* pul = "Pulse";
    app.add_option("--cycles", o.pulse.cycles, "n of --pulse n-sine (n full periods) and cycloidal-c (type C_n)")
        ->check(integer_in(1, 100))->capture_default_str()->group(pul);
    app.add_option("--phase", o.pulse.phase, "Phase psi of the one-sine and n-sine pulses [rad]")
        ->check(number_in(-2 * M_PI, 2 * M_PI, rad))->capture_default_str()->group(pul);
    app.add_option("--vertical-amplitude", o.pulse.vertical_g, "Vertical pulse amplitude a_v0 / g (same frequency and window)")
        ->check(number_in(-0.99, 0.99, none))->capture_default_str()->group(pul);
    app.add_option("--vertical-phase", o.pulse.vertical_phase, "Phase of the vertical pulse [rad]")
        ->check(number_in(-2 * M_PI, 2 * M_PI, rad))->capture_default_str()->group(pul);

    app.add_option("--friction-coefficient", o.base.friction,
                   "Static friction mu_s of the base: report the cells that need more to rock without sliding "
                   "(0: not checked)")
        ->check(number_in(0, 100, none))->capture_default_str()->group(pul);

    const char* anc = "Anchorage";
    app.add_option("--strength-ratio", o.anchorage.strength_ratio, "Anchorage strength F_u / (m g)")
        ->check(number_in(0, 1e3, none, true))->capture_default_str()->group(anc);
    app.add_option("--adaptive-break", o.anchorage.break_rule,
                   "Adaptive restrainer breaks at the K_max spring's angle, or when the force reaches F_u")
        ->check(one_of({"angle", "force"}))->capture_default_str()->group(anc);
    app.add_option("--adaptive-law", o.anchorage.law,
                   "Adaptive law: paper (Eq. 21-22) | passive (K_min -> K_max only while the spring is slack)")
        ->check(one_of({"paper", "passive"}))->capture_default_str()->group(anc);

    GridOptions& g = o.grid;
    const char* grd = "Sweep grid and scenarios";
    app.add_option("--omega-ratio-range", g.omega_range, "omega_p / p from LO to HI")
        ->expected(2)->check(number_in(1e-3, 1e3, none))->capture_default_str()->group(grd);
    app.add_option("--omega-ratio-points", g.omega_points, "Points on the omega_p / p axis, both ends included")
        ->check(integer_in(1, 100000))->capture_default_str()->group(grd);
    app.add_option("--amplitude-ratio-range", g.amplitude_range, "a_p0 / (alpha g) from LO to HI")
        ->expected(2)->check(number_in(1e-3, 1e3, none))->capture_default_str()->group(grd);
    app.add_option("--amplitude-ratio-points", g.amplitude_points, "Points on the a_p0 / (alpha g) axis")
        ->check(integer_in(1, 100000))->capture_default_str()->group(grd);
    app.add_option("--period-range", g.period_range, "Instead of omega_p / p: pulse periods T_p = 2 pi / omega_p from LO to HI [s]")
        ->expected(2)->check(number_in(1e-3, 1e3, "s"))->group(grd);
    app.add_option("--period-points", g.period_points, "Points on the T_p axis (default: --omega-ratio-points)")
        ->check(integer_in(1, 100000))->group(grd);
    app.add_option("--pga-range", g.pga_range, "Instead of a_p0 / (alpha g): peak ground accelerations a_p0 / g from LO to HI")
        ->expected(2)->check(number_in(1e-4, 100, "g"))->group(grd);
    app.add_option("--pga-points", g.pga_points, "Points on the a_p0 / g axis (default: --amplitude-ratio-points)")
        ->check(integer_in(1, 100000))->group(grd);
    app.add_option("--anchorages", g.anchorages, "Scenario kinds: free, constant, adaptive")
        ->check(one_of({"free", "constant", "adaptive"}))->capture_default_str()->group(grd);
    // 1/3 among the defaults: shown to the last digit, so that /provenance/config replays it.
    app.add_option("--theta-f-ratios", g.theta_f_ratios, "Constant K: fracture angles theta_f / alpha, one scenario each")
        ->check(number_in(1e-3, 1e3, none))->default_function([&g] { return exact_list(g.theta_f_ratios); })
        ->capture_default_str()->group(grd);
    app.add_option("--kmin-ratios", g.kmin_ratios, "Adaptive: K_min / K_max, one scenario each")
        ->check(number_in(1e-6, 1, none))->capture_default_str()->group(grd);
    app.add_option("--adaptive-theta-f-ratio", g.adaptive_theta_f_ratio, "Adaptive: theta_f / alpha of the K_max spring")
        ->check(number_in(1e-3, 1e3, none))->capture_default_str()->group(grd);
    app.add_option("--scenario", g.only, "Run only this scenario (repeatable); names as `rocksweep info` lists")->group(grd);
    app.add_option("--axis", g.axes,
                   "A parameter axis beside amplitude and frequency, NAME=LO:HI:POINTS or NAME=V1,V2,... "
                   "(repeatable, slowest first); NAME one of " + parameter_names())
        ->group(grd);

    NumericsOptions& n = o.numerics;
    const char* num = "Numerics";
    app.add_option("--method", n.method, "events (RK4, every discontinuity located) | paper (fixed dt, for comparison)")
        ->check(one_of({"events", "paper"}))->capture_default_str()->group(num);
    app.add_option("--steps-per-period", n.steps_per_period, "Accuracy: RK4 steps per period of the cell's fastest time scale (simulate: 384 unless given)")
        ->check(number_in(4, 1e5, none))->capture_default_str()->group(num);
    app.add_option("--tolerance", n.tolerance, "Under records: each step's local error in theta / alpha and theta_dot / (p alpha), "
                   "from which the step is chosen (simulate: 1e-9 unless given); 0: --steps-per-period's fixed step")
        ->check(number_in(0, 1e-2, none))->capture_default_str()->group(num);
    app.add_option("--paper-dt", n.paper_dt_s, "Step of the paper's method [s]")
        ->check(number_in(1e-7, 0.1, "s"))->capture_default_str()->group(num);
    app.add_option("--impact-threshold", n.impact_threshold, "Impacts slower than this fraction of p alpha are settling (simulate: 1e-4 unless given)")
        ->check(number_in(1e-12, 0.1, none))->capture_default_str()->group(num);
    app.add_option("--max-steps", n.max_steps, "Step cap per cell; beyond it the cell is 'not converged' (255)")
        ->check(integer_in(100, 1'000'000'000))->capture_default_str()->group(num);
    app.add_option("--record-steps", n.record_steps,
                   "samples (every record sample ends a step) | cross (steps of the knob's length cross samples on "
                   "moment nodes: 1.3-1.6x faster, ~8x the theta error, docs/physics_kernel.md)")
        ->check(one_of({"samples", "cross"}))->capture_default_str()->group(num);
    app.add_flag("--record-any-pga", n.record_any_pga,
                 "Accept a record whose PGA as read lies outside 0.005-5 g (otherwise taken for a wrong unit, docs/records.md)")
        ->group(num);
    app.add_flag("--no-energy-stop", n.no_energy_stop, "Integrate every cell to rest instead of deciding by energy")->group(num);
    app.add_option("--lanes", n.lanes, "Cells advanced together in one batch")
        ->check(integer_of({1, 4, 8, 16}))->capture_default_str()->group(num);
}

/// A single history is cheap: unless the user chose them, `simulate` takes the accuracy that
/// makes it a reference-grade history (kHistoryDefaults), not the sweep's. The defaults shown
/// in the provenance follow, so that replaying it reproduces the history.
void use_history_defaults(CLI::App& app, NumericsOptions& n) {
    CLI::Option* spp = app.get_option("--steps-per-period");
    if (spp->count() == 0) {
        n.steps_per_period = kHistoryDefaults.steps_per_period;
        spp->default_str(format_number(n.steps_per_period));
    }
    CLI::Option* tol = app.get_option("--tolerance");
    if (tol->count() == 0) {
        n.tolerance = kHistoryDefaults.tolerance;
        tol->default_str(format_number(n.tolerance));
    }
    CLI::Option* thr = app.get_option("--impact-threshold");
    if (thr->count() == 0) {
        n.impact_threshold = kHistoryDefaults.impact_threshold;
        thr->default_str(format_number(n.impact_threshold));
    }
}

/// CLI11's message for a parse error in our words: "--x = V is invalid: ..." for a bad value,
/// the unknown word and where it may be used otherwise; one line, values shortened.
std::string parse_message(const CLI::App& app, const CLI::ParseError& e, const std::vector<std::string>& subcommands) {
    const std::string what = e.what();
    std::string list;
    for (const std::string& s : subcommands) list += (list.empty() ? "" : ", ") + s;
    if (dynamic_cast<const CLI::ValidationError*>(&e)) {
        const std::size_t colon = what.find(": ");  // "--opt: VALUE is invalid: ..." from our validators
        if (colon != std::string::npos) return what.substr(0, colon) + " = " + what.substr(colon + 2);
    }
    if (dynamic_cast<const CLI::ArgumentMismatch*>(&e)) {
        // "--x: At Most 2 required but received 3", "--x: 1 required TYPE:DESC missing"
        std::smatch m;
        const std::string name = what.substr(0, what.find(": "));
        if (std::regex_search(what, m, std::regex("(\\d+) required but received (\\d+)")))
            return name + " is invalid: " + m[2].str() + " values given; allowed: " +
                   (m[1] == "1" ? std::string("one value (give the option once)") : m[1].str() + " values");
        if (std::regex_search(what, m, std::regex("(\\d+) required (.*) missing"))) {
            const std::string desc = m[2].str().substr(m[2].str().find(':') + 1);
            return name + " is invalid: a value is missing; allowed: " + (m[1] == "1" ? "one value, " : m[1].str() + " values, each ") + desc;
        }
    }
    const std::string extra = "INI was not able to parse ";
    if (what.rfind(extra, 0) == 0) {
        std::string key = what.substr(extra.size()), table;
        for (const std::string& s : subcommands)  // "sweep.mass": the key sits in the [sweep] table
            if (key.rfind(s + ".", 0) == 0) table = s, key = key.substr(s.size() + 1);
        const std::string where = table.empty() ? "" : " in the [" + table + "] table";
        for (const std::string& s : subcommands)  // a command's own option outside its table
            if (s != table && app.get_subcommand(s)->get_option_no_throw("--" + key))
                return "config key '" + key + "'" + where + " is an option of rocksweep " + s + ": put it in the config's [" + s + "] table";
        if (!table.empty() && app.get_option_no_throw("--" + key))
            return "config key '" + key + "'" + where + " is an option of every command: put it at the top of the config "
                   "(or under [block], [pulse], [anchorage], [grid] or [numerics])";
        return "config key '" + shorten(table.empty() ? key : table + "." + key) + "' is not an option of rocksweep (see rocksweep --help)";
    }
    const std::vector<const CLI::App*> chosen = app.get_subcommands([](const CLI::App* s) { return s->parsed(); });
    std::vector<std::string> left;
    for (const CLI::App* a : chosen) for (const std::string& r : a->remaining()) left.push_back(r);
    for (const std::string& r : app.remaining()) left.push_back(r);
    if (chosen.empty()) {
        for (const std::string& r : left)
            if (r.empty() || r[0] != '-') return "'" + shorten(r) + "' is not a command of rocksweep: one of " + list;
        return "a command is required: one of " + list + " (rocksweep --help)";
    }
    const std::string sub = chosen.front()->get_name();
    if (dynamic_cast<const CLI::ExtrasError*>(&e) && !left.empty())
        return "'" + shorten(left.front()) + "' is not an option of rocksweep " + sub + " (see rocksweep " + sub + " --help and rocksweep --help)";
    return shorten(what, 300);
}

}  // namespace

void add_run_options(CLI::App& sub, SweepCommand& cmd) {
    sub.add_option("-o,--output", cmd.output, "Output HDF5 file")->required();
    sub.add_flag("--resume", cmd.resume, "Continue the unfinished sweep in the output file");
    sub.add_flag("--overwrite", cmd.overwrite, "Replace an existing output file");
    sub.add_flag("-q,--quiet", cmd.quiet, "No progress output");
    sub.add_option("--chunk", cmd.max_chunk, "Largest chunk of cells handed to a rank")
        ->check(integer_in(1, 1 << 20))->capture_default_str();
    sub.add_option("--refine", cmd.refine_stride,
                   "Boundary refinement: compute every STRIDE-th cell, then only where outcomes differ, "
                   "halving the spacing down to the full grid (0: compute every cell)")
        ->check(integer_of({0, 2, 4, 8, 16, 32, 64, 128}))->capture_default_str();
    sub.add_option("--checkpoint-interval", cmd.checkpoint_s, "Seconds between saves of the finished cells")
        ->check(number_in(0.1, 86400, "s"))->capture_default_str();
}


int run_cli(int argc, char** argv, const MpiSession& mpi) {
    RootStream err(mpi);
    Options opts;
    CLI::App app{"rocksweep: overturning spectra of rocking blocks (free, anchored, adaptive anchorages)", "rocksweep"};
    CLI::Option* config = app.set_config("--config", "", "TOML config file; every key can be overridden on the command line");
    config->check(existing_file("a TOML config file"));
    app.allow_config_extras(CLI::config_extras_mode::error);
    app.require_subcommand(1);
    add_model_options(app, opts);
    app.set_version_flag("--version", std::string("rocksweep ") + ROCKSWEEP_VERSION, "Print the version and exit");

    SweepCommand sweep_cmd;
    CLI::App* sweep = app.add_subcommand("sweep", "Overturning spectra over omega_p/p x a_p0/(alpha g) for every scenario");
    sweep->fallthrough();
    add_run_options(*sweep, sweep_cmd);
    // The family shapes every cell: merge takes it too, to check its parts against it.
    const std::vector<std::string> families = pulse_family_names();
    const auto add_family_option = [&](CLI::App& sub) {
        sub.add_option("--pulse", opts.pulse.family,
                       "Pulse family (a_p: peak ground acceleration, axis a_p / (alpha g); T_p = 2 pi / omega_p, axis "
                       "omega_p / p; n: --cycles; docs/physics.md) -- " + pulse_family_help())
            ->check(one_of(families))->capture_default_str();
    };
    add_family_option(*sweep);
    sweep->add_option("--refine-axes", sweep_cmd.refine_axes,
                      "The two axes --refine works over, by name (default: amplitude_ratio omega_ratio; "
                      "any two of the grid's, parameter axes included)")
        ->expected(2);
    sweep->add_option("--part", sweep_cmd.part,
                      "Compute only part K of N of the cells (K/N, a job array's task); join the parts with rocksweep merge");

    MergeCommand merge_cmd;
    CLI::App* merge = app.add_subcommand("merge", "Join the part files of one sweep (sweep --part K/N) into one file");
    merge->fallthrough();
    merge->add_option("parts", merge_cmd.parts, "Part files of the sweep that the config and options describe")
        ->required()->check(existing_file("a part file"));
    merge->add_option("-o,--output", merge_cmd.output, "Output HDF5 file")->required();
    merge->add_flag("--overwrite", merge_cmd.overwrite, "Replace an existing output file");
    merge->add_flag("-q,--quiet", merge_cmd.quiet, "Print nothing on success");
    add_family_option(*merge);

    std::string sim_output;
    bool sim_quiet = false, sim_overwrite = false;
    SingleOptions& so = opts.single;
    CLI::App* sim = app.add_subcommand("simulate", "One time history: theta, theta_dot, stiffness, works");
    sim->fallthrough();
    sim->add_option("-o,--output", sim_output, "Output file, .h5 or .csv")->required();
    std::vector<std::string> sim_pulses{"sine", "constant"};
    sim_pulses.insert(sim_pulses.end(), families.begin(), families.end());
    sim->add_option("--pulse", so.pulse, "sine (one-sine) | constant (a_p held for --duration) | a family of sweep --pulse")
        ->check(one_of(sim_pulses))->capture_default_str();
    sim->add_option("--omega-ratio", so.omega_ratio, "omega_p / p of the pulse")->check(number_in(1e-3, 1e3, none))->capture_default_str();
    sim->add_option("--amplitude-ratio", so.amplitude_ratio, "a_p0 / (alpha g)")->check(number_in(-1e3, 1e3, none))->capture_default_str();
    sim->add_option("--duration", so.duration_s, "Length of the constant pulse [s]")->check(number_in(1e-4, 1e4, "s"));
    sim->add_option("--anchorage", so.anchorage, "free | constant | adaptive")
        ->check(one_of({"free", "constant", "adaptive"}))->capture_default_str();
    sim->add_option("--theta-f-ratio", so.theta_f_ratio, "Fracture angle theta_f / alpha (of K_max for adaptive)")
        ->check(number_in(1e-3, 1e3, none))->capture_default_str();
    sim->add_option("--kmin-ratio", so.kmin_ratio, "Adaptive: K_min / K_max")->check(number_in(1e-6, 1, none))->capture_default_str();
    sim->add_option("--stiffness", so.stiffness, "Constant anchorage: K [N/m] instead of --theta-f-ratio")->check(number_in(1, 1e12, "N/m"));
    sim->add_option("--t-end", so.t_end_s, "Record length [s] (default: pulse + 10 rocking periods 2 pi / p)")->check(number_in(1e-3, 1e6, "s"));
    sim->add_option("--output-dt", so.output_dt_s, "Output interval [s]")->check(number_in(1e-6, 100, "s"))->capture_default_str();
    sim->add_option("--record", so.record, "A recorded ground motion instead of a pulse: a PEER .AT2 file, or text "
                                           "(docs/records.md)")
        ->check(existing_file("a ground-motion record"));
    sim->add_option("--record-format", so.record_format,
                    "auto (at2 for a .AT2 file, else time_accel) | time_accel (time [s], acceleration columns) | "
                    "accel_only (acceleration only, with --record-dt) | at2 (PEER NGA)")
        ->check(one_of({"auto", "time_accel", "accel_only", "at2"}))->capture_default_str();
    sim->add_option("--record-units", so.record_units,
                    "Unit of the record's acceleration: g, m/s^2 or cm/s^2 (required except for .AT2, whose header states it)")
        ->check(one_of({"g", "m/s^2", "cm/s^2"}));
    sim->add_option("--record-dt", so.record_dt_s, "Sampling interval of an accel_only record [s]")->check(number_in(1e-5, 1, "s"));
    sim->add_option("--record-column", so.record_column,
                    "Column of the acceleration, counting the time column (default: 2 for time_accel, 1 for accel_only)")
        ->check(integer_in(1, 1000));
    sim->add_option("--record-vertical", so.record_vertical,
                    "The record's vertical component (upward positive): a second file in --record's format and unit "
                    "(without it, --record-vertical-column reads a column of --record's file)")
        ->check(existing_file("a ground-motion record"));
    sim->add_option("--record-vertical-column", so.record_vertical_column,
                    "Column of the vertical component, counting the time column")->check(integer_in(1, 1000));
    sim->add_option("--floor", so.floor,
                    "The floor the block stands on: 'NAME: T zeta gphi; T zeta gphi > T zeta gphi' (a building's modes: "
                    "period [s], damping ratio, participation; '>' chains a plinth on it), filtering --record (docs/physics.md)");
    sim->add_option("--record-scale", so.record_scale, "Factor applied to the record")->check(number_in(-100, 100, none))->capture_default_str();
    sim->add_flag("-q,--quiet", sim_quiet, "Print nothing on success");
    sim->add_flag("--overwrite", sim_overwrite, "Replace an existing output file");

    CLI::App* info = app.add_subcommand("info", "Derived values: alpha, p, e, R, I0, K and F_u per scenario");
    info->fallthrough();
    DesignCommand design_cmd;
    CLI::App* design = app.add_subcommand("design", "The constant K and the K_min/K_max that keep most of a pulse region safe");
    design->fallthrough();
    add_run_options(*design, design_cmd.run);
    add_design_options(*design, design_cmd);
    BasinCommand basin_cmd;
    CLI::App* basin = add_basin_command(app, basin_cmd);
    SuiteCommand suite_cmd;
    CLI::App* suite = add_suite_command(app, suite_cmd);
    RiskCommand risk_cmd;
    CLI::App* risk = add_risk_command(app, risk_cmd);
    SynthCommand synth_cmd;
    CLI::App* synth = add_synth_command(app, synth_cmd);
    for (CLI::App* sub : {sweep, merge, sim, info, design, basin, suite, synth})
        sub->footer("Block, pulse, anchorage, grid and numerics options (and --config): rocksweep --help");

    const std::vector<std::string> subcommands{"sweep", "merge", "simulate", "info", "design", "basin", "suite", "risk", "synth"};
    app.config_formatter(std::make_shared<TomlConfig>(subcommands, std::vector<std::string>{"block", "pulse", "anchorage", "grid", "numerics"},
                                                      [config] { return config->as<std::string>(); }));
    const std::vector<std::string> args(argv + (argc > 0 ? 1 : 0), argv + argc);
    try {
        app.parse(argc, argv);
        const CLI::App* chosen = app.get_subcommands().at(0);
        check_combinations(app, chosen->get_name(), opts, args);
        if (*design) check_design_options(app, args, design_cmd);
        if (*basin) check_basin_options(app, args);
        if (*suite) check_suite_options(app, *suite, args, suite_cmd);
        if (*risk) check_risk_options(app, args);
        if (*synth) check_synthetic_options(*synth, synth_cmd.source);
        synth_cmd.source.any_pga = suite_cmd.synthetic.any_pga = opts.numerics.record_any_pga;
        note_file_inputs(app);
    } catch (const CLI::Success& e) {  // --help, --help-all, --version: to stdout, once
        if (mpi.is_root()) app.exit(e);
        return 0;
    } catch (const CLI::ParseError& e) {
        err << "rocksweep: error: " << parse_message(app, e, subcommands) << "\n";
        return 2;
    } catch (const InputError& e) {
        err << "rocksweep: error: " << cli_message(e) << "\n";
        return 2;
    }
    if (*sim) use_history_defaults(app, opts.numerics);
    const std::string command = app.get_subcommands().at(0)->get_name();
    const std::string config_text =
        effective_config(app, command, [&](const std::string& name) {
            return command == "risk" ? risk_defines_run(name) : defines_run(command, name, opts);
        });
    try {
        if (*info) {
            if (mpi.is_root()) print_info(opts, std::cout);
            return 0;
        }
        if (*sim) {
            if (!mpi.is_root()) return 0;  // one history: one rank is enough
            return run_simulate(opts, SimulateCommand{sim_output, sim_quiet, sim_overwrite}, config_text);
        }
        if (*design) return run_design(opts, design_cmd, config_text, mpi);
        if (*merge) {
            if (!mpi.is_root()) return 0;  // reading and writing files: one rank
            return run_merge(opts, merge_cmd, config_text);
        }
        if (*basin) return mpi.is_root() ? run_basin(opts, basin_cmd, config_text) : 0;
        if (*suite) return run_suite(opts, suite_cmd, config_text, mpi);
        if (*risk) return mpi.is_root() ? run_risk(risk_cmd, config_text) : 0;
        if (*synth) return mpi.is_root() ? run_synth(synth_cmd) : 0;
        return run_sweep(opts, sweep_cmd, config_text, mpi);
    } catch (const InputError& e) {
        err << "rocksweep: error: " << cli_message(e) << "\n";
        return 2;
    }
}

}  // namespace rocksweep
