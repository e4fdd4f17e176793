#include "rocksweep/cli.hpp"

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "rocksweep/errors.hpp"

#ifndef ROCKSWEEP_VERSION
#define ROCKSWEEP_VERSION "unknown"
#endif

namespace rocksweep {

namespace {

/// A number in [lo, hi] (open ends where asked); NaN and infinities are never in range.
CLI::Validator number_in(double lo, double hi, bool open_lo = false, bool open_hi = false) {
    std::ostringstream range;
    range << (open_lo ? "(" : "[") << lo << ", " << hi << (open_hi ? ")" : "]");
    const std::string allowed = range.str();
    return CLI::Validator(
        [=](std::string& in) -> std::string {
            double x;
            std::size_t used = 0;
            try {
                x = std::stod(in, &used);
            } catch (const std::exception&) {
                return "value " + in + " is not a number; allowed range " + allowed;
            }
            const bool ok = used == in.size() && std::isfinite(x) && (open_lo ? x > lo : x >= lo) &&
                            (open_hi ? x < hi : x <= hi);
            if (!ok) return "value " + in + " is outside the allowed range " + allowed;
            return {};
        },
        allowed, "NUMBER IN " + allowed);
}

CLI::Validator positive() { return number_in(0.0, INFINITY, true, true); }

void add_model_options(CLI::App& app, Options& o) {
    BlockOptions& b = o.block;
    const char* blk = "Block";
    app.add_option("--half-width", b.half_width_m, "Half-width b of the rectangular block [m]")
        ->check(positive())->capture_default_str()->group(blk);
    app.add_option("--half-height", b.half_height_m, "Half-height h [m]")->check(positive())->capture_default_str()->group(blk);
    app.add_option("--mass", b.mass_kg, "Mass m [kg]")->check(positive())->capture_default_str()->group(blk);
    app.add_option("--radius", b.radius_m, "Equivalent block: R, corner to centre of mass [m] (with --alpha)")
        ->check(positive())->group(blk);
    app.add_option("--alpha", b.alpha_rad, "Equivalent block: slenderness angle [rad]")
        ->check(number_in(0, M_PI / 2, true, true))->group(blk);
    app.add_option("--inertia-ratio", b.inertia_ratio, "Equivalent block: I0/(m R^2) (default 4/3)")
        ->check(number_in(1.0, 1e6))->group(blk);
    app.add_option("--frequency-parameter", b.p, "Equivalent block: p [rad/s] instead of --inertia-ratio")
        ->check(positive())->group(blk);
    app.add_option("--gravity", b.gravity, "g [m/s^2]")->check(number_in(0, 1e3, true))->capture_default_str()->group(blk);
    app.add_option("--restitution", b.restitution, "Impact velocity ratio e, at most Housner's (default: Housner's)")
        ->check(number_in(0, 1, true))->group(blk);
    app.add_option("--equations", b.equations, "nonlinear | linearised (sin x = x, cos x = 1)")
        ->check(CLI::IsMember({"nonlinear", "linearised", "linearized"}))->capture_default_str()->group(blk);

    const char* pul = "Pulse";
    app.add_option("--phase", o.pulse.phase, "Phase psi of the one-sine pulse [rad]")
        ->check(number_in(-2 * M_PI, 2 * M_PI))->capture_default_str()->group(pul);
    app.add_option("--vertical-amplitude", o.pulse.vertical_g, "Vertical pulse amplitude a_v0 / g (same frequency and window)")
        ->check(number_in(-0.99, 0.99))->capture_default_str()->group(pul);
    app.add_option("--vertical-phase", o.pulse.vertical_phase, "Phase of the vertical pulse [rad]")
        ->check(number_in(-2 * M_PI, 2 * M_PI))->capture_default_str()->group(pul);

    app.add_option("--friction-coefficient", o.base.friction,
                   "Static friction mu_s of the base: report the cells that need more to rock without sliding "
                   "(0: not checked)")
        ->check(number_in(0, 100))->capture_default_str()->group(pul);

    const char* anc = "Anchorage";
    app.add_option("--strength-ratio", o.anchorage.strength_ratio, "Anchorage strength F_u / (m g)")
        ->check(number_in(0, 1e3, true))->capture_default_str()->group(anc);
    app.add_option("--adaptive-break", o.anchorage.break_rule,
                   "Adaptive restrainer breaks at the K_max spring's angle, or when the force reaches F_u")
        ->check(CLI::IsMember({"angle", "force"}))->capture_default_str()->group(anc);

    GridOptions& g = o.grid;
    const char* grd = "Sweep grid and scenarios";
    app.add_option("--omega-ratio-range", g.omega_range, "omega_p / p from LO to HI")
        ->expected(2)->check(positive())->capture_default_str()->group(grd);
    app.add_option("--omega-ratio-points", g.omega_points, "Points on the omega_p / p axis, both ends included")
        ->check(CLI::Range(std::size_t{1}, std::size_t{100000}))->capture_default_str()->group(grd);
    app.add_option("--amplitude-ratio-range", g.amplitude_range, "a_p0 / (alpha g) from LO to HI")
        ->expected(2)->check(positive())->capture_default_str()->group(grd);
    app.add_option("--amplitude-ratio-points", g.amplitude_points, "Points on the a_p0 / (alpha g) axis")
        ->check(CLI::Range(std::size_t{1}, std::size_t{100000}))->capture_default_str()->group(grd);
    app.add_option("--anchorages", g.anchorages, "Scenario kinds: free, constant, adaptive")
        ->check(CLI::IsMember({"free", "constant", "adaptive"}))->capture_default_str()->group(grd);
    app.add_option("--theta-f-ratios", g.theta_f_ratios, "Constant K: fracture angles theta_f / alpha, one scenario each")
        ->check(number_in(0, 14.4, true))->capture_default_str()->group(grd);
    app.add_option("--kmin-ratios", g.kmin_ratios, "Adaptive: K_min / K_max, one scenario each")
        ->check(number_in(0, 1, true))->capture_default_str()->group(grd);
    app.add_option("--adaptive-theta-f-ratio", g.adaptive_theta_f_ratio, "Adaptive: theta_f / alpha of the K_max spring")
        ->check(number_in(0, 14.4, true))->capture_default_str()->group(grd);
    app.add_option("--scenario", g.only, "Run only this scenario (repeatable); names as `rocksweep info` lists")->group(grd);

    NumericsOptions& n = o.numerics;
    const char* num = "Numerics";
    app.add_option("--method", n.method, "events (RK4, every discontinuity located) | paper (fixed dt, for comparison)")
        ->check(CLI::IsMember({"events", "paper"}))->capture_default_str()->group(num);
    app.add_option("--steps-per-period", n.steps_per_period, "Accuracy: RK4 steps per period of the cell's fastest time scale")
        ->check(number_in(4, 1e5))->capture_default_str()->group(num);
    app.add_option("--paper-dt", n.paper_dt_s, "Step of the paper's method [s]")
        ->check(number_in(1e-7, 0.1))->capture_default_str()->group(num);
    app.add_option("--impact-threshold", n.impact_threshold, "Impacts slower than this fraction of p alpha are settling")
        ->check(number_in(1e-12, 0.1))->capture_default_str()->group(num);
    app.add_option("--max-steps", n.max_steps, "Step cap per cell; beyond it the cell is 'not converged' (255)")
        ->check(CLI::Range(std::int64_t{100}, std::int64_t{1'000'000'000}))->capture_default_str()->group(num);
    app.add_flag("--no-energy-stop", n.no_energy_stop, "Integrate every cell to rest instead of deciding by energy")->group(num);
    app.add_option("--lanes", n.lanes, "Cells advanced together in one batch")
        ->check(CLI::IsMember({1, 4, 8, 16}))->capture_default_str()->group(num);
}

void print_info(const Options& o, std::ostream& out) {
    const SweepSpec spec = make_sweep_spec(o);
    const Block& b = spec.block;
    out << std::setprecision(6);
    out << "block\n"
        << "  b = " << b.half_width_m() << " m, h = " << b.half_height_m() << " m, R = " << b.radius_m << " m\n"
        << "  alpha = " << b.alpha_rad << " rad (" << b.alpha_rad * 180 / M_PI << " deg)\n"
        << "  p = " << b.p() << " rad/s, I0 = " << b.inertia() << " kg m^2 (I0/(m R^2) = " << b.inertia_ratio << ")\n"
        << "  m = " << b.mass_kg << " kg, g = " << b.gravity << " m/s^2\n"
        << "  e = " << b.e << " (Housner: " << b.housner_e() << "), r = e^2 = " << b.e * b.e << "\n"
        << "  uplift threshold a_p0 / (alpha g) = " << std::tan(b.alpha_rad) / b.alpha_rad << "\n"
        << "  equations: " << to_string(spec.equations) << "\n";
    out << "grid\n"
        << "  omega_p / p: " << spec.omega_ratio.lo << " .. " << spec.omega_ratio.hi << ", " << spec.omega_ratio.points << " points\n"
        << "  a_p0 / (alpha g): " << spec.amplitude_ratio.lo << " .. " << spec.amplitude_ratio.hi << ", "
        << spec.amplitude_ratio.points << " points\n"
        << "  " << spec.scenarios.size() << " scenarios x " << spec.cells_per_scenario() << " = " << spec.cell_count() << " cells\n";
    out << "scenarios\n";
    for (const Scenario& s : spec.scenarios) {
        const Anchorage& a = s.anchorage;
        out << "  " << std::left << std::setw(22) << s.name << std::right << to_string(a.kind);
        if (a.kind != AnchorageKind::free) {
            out << "  F_u = " << a.strength_n << " N, theta_f = " << a.theta_f_rad << " rad (" << s.theta_f_ratio
                << " alpha), K = " << a.k_max << " N/m";
            if (a.kind == AnchorageKind::adaptive) out << ", K_min = " << a.k_min << " N/m (" << s.kmin_ratio << " K_max)";
        }
        out << "\n";
    }
}

}  // namespace

int run_cli(int argc, char** argv, const MpiSession& mpi) {
    RootStream err(mpi);
    Options opts;
    CLI::App app{"rocksweep: overturning spectra of rocking blocks (free, anchored, adaptive anchorages)", "rocksweep"};
    app.set_config("--config", "", "TOML config file; every key can be overridden on the command line");
    app.allow_config_extras(CLI::config_extras_mode::error);
    app.require_subcommand(1);
    add_model_options(app, opts);
    bool show_version = false;
    app.add_flag("--version", show_version, "Print the version and exit");

    SweepCommand sweep_cmd;
    CLI::App* sweep = app.add_subcommand("sweep", "Overturning spectra over omega_p/p x a_p0/(alpha g) for every scenario");
    sweep->fallthrough();
    sweep->add_option("-o,--output", sweep_cmd.output, "Output HDF5 file")->required();
    sweep->add_flag("--resume", sweep_cmd.resume, "Continue the unfinished sweep in the output file");
    sweep->add_flag("--overwrite", sweep_cmd.overwrite, "Replace an existing output file");
    sweep->add_flag("-q,--quiet", sweep_cmd.quiet, "No progress output");
    sweep->add_option("--chunk", sweep_cmd.max_chunk, "Largest chunk of cells handed to a rank")
        ->check(CLI::Range(std::size_t{1}, std::size_t{1} << 20))->capture_default_str();
    sweep->add_option("--refine", sweep_cmd.refine_stride,
                      "Boundary refinement: compute every STRIDE-th cell, then only where outcomes differ, "
                      "halving the spacing down to the full grid (0: compute every cell)")
        ->check(CLI::IsMember({0, 2, 4, 8, 16, 32, 64, 128}))->capture_default_str();
    sweep->add_option("--checkpoint-interval", sweep_cmd.checkpoint_s, "Seconds between saves of the finished cells")
        ->check(number_in(0.1, 86400))->capture_default_str();

    std::string sim_output;
    bool sim_quiet = false, sim_overwrite = false;
    SingleOptions& so = opts.single;
    CLI::App* sim = app.add_subcommand("simulate", "One time history: theta, theta_dot, stiffness, works");
    sim->fallthrough();
    sim->add_option("-o,--output", sim_output, "Output file, .h5 or .csv")->required();
    sim->add_option("--pulse", so.pulse, "sine | constant")->check(CLI::IsMember({"sine", "constant"}))->capture_default_str();
    sim->add_option("--omega-ratio", so.omega_ratio, "omega_p / p of the sine pulse")->check(number_in(0, 1e4, true))->capture_default_str();
    sim->add_option("--amplitude-ratio", so.amplitude_ratio, "a_p0 / (alpha g)")->check(number_in(-1e4, 1e4))->capture_default_str();
    sim->add_option("--duration", so.duration_s, "Length of the constant pulse [s]")->check(positive());
    sim->add_option("--anchorage", so.anchorage, "free | constant | adaptive")
        ->check(CLI::IsMember({"free", "constant", "adaptive"}))->capture_default_str();
    sim->add_option("--theta-f-ratio", so.theta_f_ratio, "Fracture angle theta_f / alpha (of K_max for adaptive)")
        ->check(number_in(0, 14.4, true))->capture_default_str();
    sim->add_option("--kmin-ratio", so.kmin_ratio, "Adaptive: K_min / K_max")->check(number_in(0, 1, true))->capture_default_str();
    sim->add_option("--stiffness", so.stiffness, "Constant anchorage: K [N/m] instead of --theta-f-ratio")->check(positive());
    sim->add_option("--t-end", so.t_end_s, "Record length [s] (default: pulse + 10 rocking periods 2 pi / p)")->check(positive());
    sim->add_option("--output-dt", so.output_dt_s, "Output interval [s]")->check(number_in(1e-6, 100))->capture_default_str();
    sim->add_option("--record", so.record, "A recorded ground motion instead of a pulse: text file, time [s] and acceleration per line")
        ->check(CLI::ExistingFile);
    sim->add_option("--record-units", so.record_units, "Unit of the record's acceleration column: g or m/s^2 (required with --record)")
        ->check(CLI::IsMember({"g", "m/s^2"}));
    sim->add_option("--record-scale", so.record_scale, "Factor applied to the record")->check(number_in(-100, 100))->capture_default_str();
    sim->add_flag("-q,--quiet", sim_quiet, "Print nothing on success");
    sim->add_flag("--overwrite", sim_overwrite, "Replace an existing output file");

    CLI::App* info = app.add_subcommand("info", "Derived values: alpha, p, e, R, I0, K and F_u per scenario");
    info->fallthrough();
    for (CLI::App* sub : {sweep, sim, info})
        sub->footer("Block, pulse, anchorage, grid and numerics options (and --config): rocksweep --help");

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        if (mpi.is_root()) app.exit(e);
        return 0;
    } catch (const CLI::CallForAllHelp& e) {
        if (mpi.is_root()) app.exit(e);
        return 0;
    } catch (const CLI::ParseError& e) {
        if (show_version) {
            err << "rocksweep " << ROCKSWEEP_VERSION << "\n";
            return 0;
        }
        std::string what = e.what();
        const std::string extra = "INI was not able to parse ";
        if (what.rfind(extra, 0) == 0)
            what = "config key '" + what.substr(extra.size()) + "' is not an option of rocksweep (see rocksweep --help)";
        err << "rocksweep: error: " << what << "\n";
        return 2;
    }
    const std::string config_text = app.config_to_str(true, false);
    try {
        if (*info) {
            if (mpi.is_root()) print_info(opts, std::cout);
            return 0;
        }
        if (*sim) {
            if (!mpi.is_root()) return 0;  // one history: one rank is enough
            return run_simulate(opts, SimulateCommand{sim_output, sim_quiet, sim_overwrite}, config_text);
        }
        return run_sweep(opts, sweep_cmd, config_text, mpi);
    } catch (const InputError& e) {
        err << "rocksweep: error: " << cli_message(e) << "\n";
        return 2;
    }
}

}  // namespace rocksweep
