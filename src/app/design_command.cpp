// `rocksweep design`: a search over the anchorage stiffness (and over K_min/K_max) in which
// every evaluation is a sweep of the hazard region, run by the sweep command itself so that
// MPI, checkpoints, signals, refinement and --resume behave exactly as for `rocksweep sweep`.
#include "rocksweep/app/design_command.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <iomanip>
#include <optional>
#include <sstream>
#include <tuple>

#include "rocksweep/design/design_criterion.hpp"
#include "rocksweep/io/design_file.hpp"
#include "rocksweep/io/suite_file.hpp"
#include "rocksweep/design/design_search.hpp"
#include "rocksweep/core/errors.hpp"
#include "rocksweep/app/design_risk.hpp"
#include "rocksweep/app/option_checks.hpp"
#include "rocksweep/app/run_support.hpp"
#include "rocksweep/app/resume_check.hpp"
#include "rocksweep/app/sweep_refinement.hpp"
#include "rocksweep/io/output_claim.hpp"
#include "rocksweep/io/run_inputs.hpp"
#include "rocksweep/io/spectra_file.hpp"


namespace rocksweep {

void add_design_options(CLI::App& design, DesignCommand& cmd) {
    const char* grp = "Design search";
    design.add_option("--stiffness-range", cmd.stiffness_range,
                      "Constant K searched from LO to HI [N/m] (default: the K whose theta_f at F_u is 4 alpha, at most pi/2, "
                      "to that of alpha/16)")
        ->expected(2)->check(number_in(1, 1e12, "N/m"))->group(grp);
    design.add_option("--kmin-ratio-range", cmd.kmin_range, "K_min / K_max searched from LO to HI (K_max: --adaptive-theta-f-ratio)")
        ->expected(2)->check(number_in(1e-6, 1, ""))->capture_default_str()->group(grp);
    design.add_option("--coarse-points", cmd.coarse_points, "Values of the first round, log-spaced, both ends included")
        ->check(integer_in(3, 1000))->capture_default_str()->group(grp);
    design.add_option("--points-per-side", cmd.points_per_side, "Each later round: new values in each interval beside the best")
        ->check(integer_in(1, 100))->capture_default_str()->group(grp);
    design.add_option("--rounds", cmd.rounds, "Rounds after the coarse one (0: the coarse values only)")
        ->check(integer_in(0, 50))->capture_default_str()->group(grp);
    design.add_option("--tolerance", cmd.tolerance, "An interval narrower than this, in log10 of the value, is not split again")
        ->check(number_in(1e-6, 1, "", true))->capture_default_str()->group(grp);
    design.add_option("--max-rotation-ratio", cmd.max_rotation_ratio,
                      "Acceptable only if max |theta| / alpha stays at most this (default: no limit)")
        ->check(number_in(0, 1e3, "", true))->group(grp);
    design.add_option("--object-force-ratio", cmd.object_force_ratio,
                      "The object's own force limit / (m g): acceptable only if the anchorage's peak force does not exceed it "
                      "(default: F_u alone)")
        ->check(number_in(0, 1e3, "", true))->group(grp);
    design.add_option("--near-optimal", cmd.near_optimal,
                      "Report the range of values, around the best, whose safe fraction is within this of the best")
        ->check(number_in(0, 1, ""))->capture_default_str()->group(grp);
    design.add_flag("--keep-rounds", cmd.keep_rounds,
                    "Keep each round's spectra, OUT.roundN.h5, once the design file is written (default: removed)")
        ->group(grp);
    add_suite_hazard_options(design, cmd.hazard);
    design.add_option("--hazard", cmd.hazard_curve,
                      "With --suite: a site's hazard curve (docs/risk.md); the design then minimises the annual rate of the "
                      "unacceptable state (overturning, or beyond the limits) there")
        ->check(existing_file("a hazard curve file"))->group(grp);
    design.add_option("--hazard-site", cmd.hazard_site, "Row of an OpenQuake hazard file with several sites (0-based)")
        ->check(integer_in(0, 10000000))->group(grp);
    design.add_option("--exposure-years", cmd.exposure_years, "With --hazard: the exposure time t of exp(-rate t) [yr]")
        ->check(number_in(1e-3, 1e5, "yr"))->capture_default_str()->group(grp);
}

void check_design_options(const CLI::App& app, const std::vector<std::string>& args, const DesignCommand& cmd) {
    refuse_typed(app, args, {"--anchorages", "--theta-f-ratios", "--kmin-ratios", "--scenario"},
                 "an option of sweep and info only; design chooses its scenarios (--stiffness-range, --kmin-ratio-range)");
    if (cmd.hazard.suite.empty()) {
        refuse_typed(app, args,
                     {"--intensity-measure", "--intensity-range", "--intensity-points", "--floor", "--sa-period", "--sa-damping",
                      "--hazard", "--hazard-site"},
                     "an option of design --suite (the hazard is the pulse region without it)");
        return;
    }
    refuse_typed(app, args,
                 pulse_region_options,
                 "an option of the pulse region; with --suite the hazard is the suite's records");
    if (cmd.run.refine_stride != 0)
        throw InputError("refine", std::to_string(cmd.run.refine_stride), "0 with --suite (refinement is for pulse regions)");
    if (cmd.hazard.floors.size() > 1)
        throw InputError("floor", std::to_string(cmd.hazard.floors.size()) + " floors",
                         "one --floor with design --suite (it designs the anchorage where the object stands)");
}

namespace {

/// What every rank derives from the options, identically, before any work.
struct Problem {
    SweepSpec hazard;  ///< block and region; scenarios are made per round
    double strength_n = 0.0;
    double k_max = 0.0;
    SearchSettings stiffness, kmin;
    DesignConstraints limits;
    std::optional<DesignRisk> risk;  ///< --hazard: the criterion is the annual rate at that site
};

std::pair<double, double> range_of(const char* option, const std::vector<double>& v) {
    if (v.size() != 2 || !(v[0] < v[1]))
        throw InputError(option, v.size() == 2 ? format_short(v[0]) + " " + format_short(v[1]) : std::to_string(v.size()) + " values",
                         "two values LO HI with LO < HI");
    return {v[0], v[1]};
}

SearchSettings search_settings(const DesignCommand& cmd, std::pair<double, double> range) {
    return SearchSettings{std::log10(range.first), std::log10(range.second), cmd.coarse_points, cmd.points_per_side,
                          cmd.rounds, cmd.tolerance};
}

Problem make_problem(const Options& opts, const DesignCommand& cmd) {
    Problem p;
    Options one = opts;  // the block and the region, checked as a sweep checks them
    one.grid.anchorages = {"free"};
    one.grid.only.clear();
    p.hazard = make_sweep_spec(one);
    const Block& b = p.hazard.block;
    p.strength_n = opts.anchorage.strength_ratio * b.mass_kg * b.gravity;
    p.k_max = stiffness_from_strength(b, p.strength_n, opts.grid.adaptive_theta_f_ratio * b.alpha_rad);
    std::pair<double, double> k{stiffness_from_strength(b, p.strength_n, std::min(4.0 * b.alpha_rad, M_PI / 2)),
                                stiffness_from_strength(b, p.strength_n, b.alpha_rad / 16.0)};
    if (!cmd.stiffness_range.empty()) k = range_of("stiffness-range", cmd.stiffness_range);
    if (!(fracture_angle(b, p.strength_n, k.first) < 0.99 * M_PI))
        throw InputError("stiffness-range", format_short(k.first) + " " + format_short(k.second),
                         "LO large enough that F_u = " + format_short(p.strength_n, 6) + " N is reached before theta = pi");
    p.stiffness = search_settings(cmd, k);
    p.kmin = search_settings(cmd, range_of("kmin-ratio-range", cmd.kmin_range));
    p.limits.max_rotation_ratio = cmd.max_rotation_ratio;
    p.limits.max_force_ratio = cmd.object_force_ratio / opts.anchorage.strength_ratio;
    if (!cmd.hazard_curve.empty())
        p.risk = read_design_hazard(cmd.hazard_curve, cmd.hazard_site, cmd.exposure_years, make_suite_spec(opts, cmd.hazard));
    const bool limited = cmd.max_rotation_ratio > 0.0 || cmd.object_force_ratio > 0.0;
    if (limited && cmd.run.refine_stride != 0)
        throw InputError("refine", std::to_string(cmd.run.refine_stride),
                         "0 with --max-rotation-ratio or --object-force-ratio (refinement infers outcomes only; a limit "
                         "needs every cell's rotation and force)");
    return p;
}

/// Values a round sweeps, as log10 of K and of K_min / K_max (the search's axis).
struct RoundValues {
    std::vector<double> log_k, log_rho;
    bool empty() const { return log_k.empty() && log_rho.empty(); }
};

double rho_of(double log_rho) { return std::min(1.0, std::pow(10.0, log_rho)); }

/// A round's sweep: the free block (round 0, the reference), a constant anchorage per K —
/// at a fixed F_u, K fixes theta_f = 2 atan(F_u / (4 b K)) — and an adaptive one per ratio.
Options round_options(const Options& base, const Problem& p, const RoundValues& v, bool with_free) {
    Options o = base;
    const Block& b = p.hazard.block;
    o.grid.only.clear();
    o.grid.anchorages.clear();
    o.grid.theta_f_ratios.clear();
    o.grid.kmin_ratios.clear();
    if (with_free) o.grid.anchorages.push_back("free");
    if (!v.log_k.empty()) o.grid.anchorages.push_back("constant");
    if (!v.log_rho.empty()) o.grid.anchorages.push_back("adaptive");
    for (double x : v.log_k) o.grid.theta_f_ratios.push_back(fracture_angle(b, p.strength_n, std::pow(10.0, x)) / b.alpha_rad);
    for (double x : v.log_rho) o.grid.kmin_ratios.push_back(rho_of(x));
    return o;
}

/// OUT.h5 -> OUT.roundN.h5, beside it.
std::string round_path(const std::string& output, int round) {
    std::string stem = output;
    if (stem.size() > 3 && stem.compare(stem.size() - 3, 3, ".h5") == 0) stem.resize(stem.size() - 3);
    return stem + ".round" + std::to_string(round) + ".h5";
}

/// A value evaluated, on rank 0.
struct Evaluation {
    double x = 0.0;         ///< the search's axis
    double variable = 0.0;  ///< K [N/m] of the scenario, or K_min / K_max
    double theta_f_ratio = 0.0;
    DesignScore scored;
    int round = 0;
};

/// Rank 0's record of the search.
struct Ledger {
    std::optional<DesignScore> free;
    std::vector<Evaluation> constant, adaptive;

    static std::vector<SearchPoint> points(const std::vector<Evaluation>& e) {
        std::vector<SearchPoint> p;
        for (const Evaluation& x : e) p.push_back({x.x, x.scored.score.acceptable});
        return p;
    }

    /// Takes the round's scores, one per scenario in round_options' order.
    void add_round(const RoundValues& v, const std::vector<Scenario>& scenarios, const std::vector<DesignScore>& scores, int round) {
        std::size_t s = 0;
        if (round == 0) free = scores[s++];
        for (double x : v.log_k) {
            constant.push_back({x, scenarios[s].anchorage.k_max, scenarios[s].theta_f_ratio, scores[s], round});
            ++s;
        }
        for (double x : v.log_rho) adaptive.push_back({x, rho_of(x), 0.0, scores[s++], round});
    }
};

/// The round's file read back and scored, a score per scenario: area shares of the region, or
/// shares of the suite's runs.
std::vector<DesignScore> round_scores(const Options& round_opts, const DesignCommand& cmd, const std::string& path,
                                      const IntegratorSettings& settings, const Problem& p) {
    std::vector<DesignScore> scores;
    const double none = std::nan("");
    if (cmd.hazard.suite.empty()) {
        const SweepSpec spec = sweep_spec(round_opts, cmd.run);  // the round's refinement, as its file records it
        const SweepResults r = read_spectra_results(path, spec, settings);
        for (std::size_t s = 0; s < spec.scenarios.size(); ++s) scores.push_back({score_scenario(spec, r, s, p.limits), none, none});
    } else {
        const SuiteSpec spec = make_suite_spec(round_opts, cmd.hazard);
        const SweepResults r = read_suite_results(path, spec, settings);
        const std::size_t per = spec.cells_per_scenario();
        for (std::size_t s = 0; s < spec.scenarios.size(); ++s)
            scores.push_back(p.risk ? risk_score(*p.risk, spec.intensity.values(),
                                                 score_levels(r, s * per, spec.records.size(), spec.intensity.points, p.limits))
                                    : DesignScore{score_cells(r, s * per, per, p.limits), none, none});
    }
    return scores;
}

DesignCurve curve_of(std::vector<Evaluation> e, bool with_theta_f, double near_optimal) {
    std::stable_sort(e.begin(), e.end(), [](const Evaluation& a, const Evaluation& b) { return a.x < b.x; });
    DesignCurve c;
    std::vector<SearchPoint> pts;
    for (const Evaluation& x : e) {
        c.variable.push_back(x.variable);
        if (with_theta_f) c.theta_f_ratio.push_back(x.theta_f_ratio);
        c.acceptable.push_back(x.scored.score.acceptable);
        c.standing.push_back(x.scored.score.standing);
        c.rate.push_back(x.scored.rate);
        c.standing_rate.push_back(x.scored.standing_rate);
        c.round.push_back(x.round);
        pts.push_back({x.x, x.scored.score.acceptable});
    }
    c.optimum = best_point(pts);
    std::tie(c.near_lo, c.near_hi) = near_best(pts, c.optimum, near_optimal);
    return c;
}

/// A design's files (output, rounds) always record their options; only how the work is cut up
/// may change (a round's refinement is checked by its options, not by the round's attributes).
void check_resumed_design(const std::string& path, const std::string& config_text) {
    const std::string stored = read_provenance_config(path);
    if (stored.empty()) throw InputError("output", path, "a file of a rocksweep design to resume (it is damaged or not one)");
    check_resumed_config(path, stored, config_text, work_options());
}

/// Claims the design's output on rank 0 (the rounds claim their own files); an existing
/// output, or the round files of an unfinished design for it, is refused unless --resume or
/// --overwrite says what to do with it. Returns true when a resumed design is already complete.
bool claim_output(std::optional<OutputClaim>& claim, const SweepCommand& run, const std::string& config_text) {
    if (run.resume && run.overwrite) throw InputError("resume", "with --overwrite", "one of --resume, --overwrite");
    // A resumed design reads its rounds back: none may be replaced by the design's file.
    std::error_code ec;
    for (int round = 0; std::filesystem::exists(round_path(run.output, round), ec); ++round)
        refuse_same_file("output", run.output, "the design's round file", round_path(run.output, round));
    claim.emplace("output", run.output);
    const std::string round0 = round_path(run.output, 0);
    if (!run.resume && !run.overwrite) {
        if (claim->exists())
            throw InputError("output", run.output, "a new file; it exists: pass --resume to continue its design or --overwrite to replace it");
        if (std::filesystem::exists(round0))
            throw InputError("output", run.output,
                             "a new design; an unfinished design for it left " + round0 +
                                 ": pass --resume to continue it or --overwrite to start afresh");
    }
    if (!run.resume) return false;
    // A finished design has removed its rounds: it is complete if its options are these.
    if (claim->exists()) {
        check_resumed_design(run.output, config_text);
        return true;
    }
    if (std::filesystem::exists(round0)) check_resumed_design(round0, config_text);
    return false;
}

/// Removes the round files once the design file holds their results; none is resumable any more.
/// Also those of an earlier, longer design overwritten by this one.
void remove_rounds(const std::string& output, int rounds) {
    std::error_code ec;
    for (int r = 0; std::filesystem::remove(round_path(output, r), ec) || r < rounds; ++r) {
    }
}

void print_summary(std::ostream& log, const DesignReport& r) {
    const DesignCurve &c = r.constant, &a = r.adaptive;
    log << std::setprecision(4) << "design: safe fraction of the hazard, free-standing " << r.free.acceptable << "\n"
        << "  constant K:    best K = " << c.variable[c.optimum] << " N/m (theta_f = " << c.theta_f_ratio[c.optimum]
        << " alpha), safe fraction " << c.acceptable[c.optimum] << " (" << c.variable.size() << " values; within "
        << r.near_optimal << " of it from " << c.variable[c.near_lo] << " to " << c.variable[c.near_hi] << ")\n"
        << "  adaptive:      best K_min/K_max = " << a.variable[a.optimum] << " (K_max = " << r.k_max_n_per_m
        << " N/m), safe fraction " << a.acceptable[a.optimum] << " (" << a.variable.size() << " values; within "
        << r.near_optimal << " of it from " << a.variable[a.near_lo] << " to " << a.variable[a.near_hi] << ")\n";
    if (r.risk)
        log << "  at the site of " << r.risk->path << ", the annual rate of the unacceptable state: free " << r.free_rate
            << ", best constant " << c.rate[c.optimum] << ", best adaptive " << a.rate[a.optimum] << " [1/yr]; the safe fraction "
            << "above is exp(-rate t), the probability of none in " << r.risk->exposure_years << " years\n";
}

}  // namespace

int run_design(const Options& opts, const DesignCommand& cmd, const std::string& config_text, const MpiSession& mpi) {
    const Problem problem = make_problem(opts, cmd);  // the same on every rank, so is any error
    // A suite's records are read and checked (and noted as inputs) before the output is claimed.
    if (!cmd.hazard.suite.empty()) make_suite_spec(opts, cmd.hazard);
    const IntegratorSettings settings = make_settings(opts.numerics);
    RootStream log(mpi);

    std::optional<OutputClaim> claim;
    const OutputVerdict verdict = agree_on_output(
        mpi, log, [&] { return claim_output(claim, cmd.run, config_text); }, [&] { claim.reset(); });
    if (verdict == OutputVerdict::nothing_to_do && !cmd.run.quiet)
        log << cmd.run.output << ": design already complete; nothing to do\n";
    if (verdict != OutputVerdict::go) return exit_status(verdict);

    const double t0 = MpiSession::wall_time();
    const BracketSearch by_k(problem.stiffness), by_rho(problem.kmin);
    RoundValues values{by_k.first_round(), by_rho.first_round()};
    Ledger ledger;
    int rounds_run = 0;
    for (int round = 0; !values.empty(); ++round) {
        rounds_run = round + 1;
        const Options round_opts = round_options(opts, problem, values, round == 0);
        SweepCommand run = cmd.run;
        run.output = round_path(cmd.run.output, round);
        if (!cmd.run.quiet)
            log << "design round " << round << ": " << values.log_k.size() << " values of K, " << values.log_rho.size()
                << " of K_min/K_max -> " << run.output << "\n";
        SuiteCommand suite = cmd.hazard;
        suite.run = run;
        int status = suite.suite.empty() ? run_sweep(round_opts, run, config_text, mpi) : run_suite(round_opts, suite, config_text, mpi);
        mpi.broadcast(status);
        if (status != 0) {
            if (status != 2) log << "design stopped in round " << round << "; rerun it with --resume to continue\n";
            return mpi.is_root() ? status : 0;
        }
        if (mpi.is_root()) {
            ledger.add_round(values, make_sweep_spec(round_opts).scenarios,
                             round_scores(round_opts, cmd, run.output, settings, problem), round);
            values.log_k = by_k.next_round(round + 1, Ledger::points(ledger.constant));
            values.log_rho = by_rho.next_round(round + 1, Ledger::points(ledger.adaptive));
        }
        mpi.broadcast(values.log_k);
        mpi.broadcast(values.log_rho);
    }
    if (!mpi.is_root()) return 0;

    DesignReport report;
    report.hazard = problem.hazard;
    report.constraints = problem.limits;
    report.strength_n = problem.strength_n;
    report.object_force_n = cmd.object_force_ratio * problem.hazard.block.mass_kg * problem.hazard.block.gravity;
    report.k_max_n_per_m = problem.k_max;
    report.k_max_theta_f_ratio = opts.grid.adaptive_theta_f_ratio;
    report.free = ledger.free->score;
    report.free_rate = ledger.free->rate;
    report.free_standing_rate = ledger.free->standing_rate;
    if (problem.risk) report.risk = RiskHazard{problem.risk->path, hazard_measure_name(problem.risk->curve.measure(), problem.risk->curve.period_s()), problem.risk->exposure_years};
    report.constant = curve_of(ledger.constant, true, cmd.near_optimal);
    report.adaptive = curve_of(ledger.adaptive, false, cmd.near_optimal);
    report.near_optimal = cmd.near_optimal;
    report.stiffness_search = problem.stiffness;
    report.kmin_search = problem.kmin;
    report.refine_stride = cmd.run.refine_stride;
    if (!cmd.hazard.suite.empty()) {
        const SuiteSpec spec = make_suite_spec(opts, cmd.hazard);
        report.suite = SuiteHazard{cmd.hazard.suite, to_string(spec.measure), intensity_units(spec.measure), spec.intensity,
                                   spec.records.size()};
    }
    const Provenance prov{ROCKSWEEP_VERSION, config_text, utc_now(), mpi.size(), MpiSession::wall_time() - t0};
    try {
        write_design(cmd.run.output, report, prov);
    } catch (const InputError& e) {  // the output's directory went away during the run
        log << "rocksweep: error: " << cli_message(e) << "\n";
        return 2;
    } catch (const std::runtime_error& e) {
        log << "rocksweep: error: " << e.what() << "\n";
        return 1;
    }
    if (!cmd.keep_rounds) remove_rounds(cmd.run.output, rounds_run);
    if (!cmd.run.quiet) {
        print_summary(log, report);
        log << "wrote " << cmd.run.output << "\n";
    }
    return 0;
}

}  // namespace rocksweep
