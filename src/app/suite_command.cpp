// `rocksweep suite`: the records of a suite scaled over intensity levels and block sizes, for
// every scenario; scheduled, checkpointed and resumed like `rocksweep sweep`.
#include "rocksweep/app/suite_command.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <iomanip>
#include <optional>

#include "rocksweep/app/made_on_ranks.hpp"
#include "rocksweep/app/memory_budget.hpp"
#include "rocksweep/app/option_checks.hpp"
#include "rocksweep/app/resume_check.hpp"
#include "rocksweep/app/run_support.hpp"
#include "rocksweep/app/suite_synthetic.hpp"
#include "rocksweep/core/errors.hpp"
#include "rocksweep/io/output_claim.hpp"
#include "rocksweep/io/run_inputs.hpp"
#include "rocksweep/io/suite_file.hpp"
#include "rocksweep/io/suite_stream.hpp"
#include "rocksweep/motion/floor_filter.hpp"
#include "rocksweep/parallel/progress.hpp"
#include "rocksweep/parallel/scheduler.hpp"


namespace rocksweep {

void add_suite_hazard_options(CLI::App& sub, SuiteCommand& cmd) {
    sub.add_option("--suite", cmd.suite, "Suite of records: CSV with name, file, format, units, ... (docs/records.md)")
        ->check(existing_file("a record suite (CSV)"));
    sub.add_option("--intensity-measure", cmd.measure,
                   "What the levels measure: pga (PGA [g]), pgv (PGV [m/s]), pga-ratio (PGA / (g tan alpha)), "
                   "scale (the factor itself), sa (Sa(T, zeta) of the ground [g]), pfa (peak floor acceleration [g])")
        ->check(one_of({"pga", "pgv", "pga-ratio", "scale", "sa", "pfa"}))->capture_default_str();
    sub.add_option("--floor", cmd.floors,
                   "Where the blocks stand, one scenario set per floor: ground, or 'NAME: T zeta gphi; T zeta gphi > T zeta "
                   "gphi' (a building's modes: period [s], damping ratio, participation; '>' chains a plinth on it; "
                   "docs/suite.md)");
    sub.add_option("--sa-period", cmd.sa_period_s, "Period T of the Sa(T, zeta) measure [s]")
        ->check(number_in(motion::floor_period_min_s, motion::floor_period_max_s, "s"))->capture_default_str();
    sub.add_option("--sa-damping", cmd.sa_damping, "Damping ratio zeta of the Sa(T, zeta) measure")
        ->check(number_in(0, 0.99, ""))->capture_default_str();
    sub.add_option("--intensity-range", cmd.intensity_range, "Levels from LO to HI, in the measure's unit")
        ->expected(2)->check(number_in(0, 1e3, "", true))->capture_default_str();
    sub.add_option("--intensity-points", cmd.intensity_points, "Levels, evenly spaced, both ends included")
        ->check(integer_in(1, 100000))->capture_default_str();
}

CLI::App* add_suite_command(CLI::App& app, SuiteCommand& cmd) {
    CLI::App* s = app.add_subcommand("suite", "Records of a suite scaled to intensity levels, per block size and scenario: "
                                              "IDA, overturning spectra, fragility curves");
    s->fallthrough();
    add_run_options(*s, cmd.run);
    add_suite_hazard_options(*s, cmd);
    add_suite_synthetic_options(*s, cmd);
    s->add_option("--radius-range", cmd.radius_range,
                  "Block sizes R from LO to HI [m], at the block's density (default: the block's own R)")
        ->expected(2)->check(number_in(1e-3, 1e3, "m"));
    s->add_option("--radius-points", cmd.radius_points, "Block sizes, evenly spaced, both ends included")
        ->check(integer_in(1, 100000))->capture_default_str();
    s->add_option("--alpha-range", cmd.alpha_range,
                  "Slenderness angles alpha = atan(b/h) from LO to HI [rad], at each R (default: the block's own alpha)")
        ->expected(2)->check(number_in(min_alpha_rad, M_PI / 2, "rad"));
    s->add_option("--alpha-points", cmd.alpha_points, "Slenderness angles, evenly spaced, both ends included")
        ->check(integer_in(1, 100000))->capture_default_str();
    s->add_option("--damage-states", cmd.damage_states,
                  "Damage states theta_max / alpha >= each value, for the fragility curves (overturning is always one)")
        ->check(number_in(0, 1e3, "", true))->capture_default_str();
    s->add_flag("--check-sensitivity", cmd.check_sensitivity,
                "Run each run again with the record's scale times (1 + 1e-9) at the tolerance / 100 and flag those whose "
                "outcome or damage state changes (about 2.5x the cost; docs/suite.md)");
    return s;
}

void check_suite_options(const CLI::App& app, const CLI::App& suite, const std::vector<std::string>& args,
                         const SuiteCommand& cmd) {
    refuse_typed(app, args,
                 pulse_region_options,
                 "an option of sweep; the suite's ground motions are its records");
    check_suite_synthetic_options(app, suite, args, cmd);
    if (cmd.run.refine_stride != 0)
        throw InputError("refine", std::to_string(cmd.run.refine_stride), "0 for suite (refinement is for spectra maps)");
    if (cmd.radius_range.empty() && cmd.radius_points != 1)
        throw InputError("radius-points", std::to_string(cmd.radius_points), "1 without --radius-range (the block's own R)");
    if (cmd.alpha_range.empty() && cmd.alpha_points != 1)
        throw InputError("alpha-points", std::to_string(cmd.alpha_points), "1 without --alpha-range (the block's own alpha)");
    // Each threshold is one row of the fragility datasets, read as increasing damage.
    const std::vector<double>& states = cmd.damage_states;
    if (std::adjacent_find(states.begin(), states.end(), std::greater_equal<double>()) != states.end()) {
        std::string given;
        for (double x : states) {
            if (!given.empty()) given += ' ';
            given += format_short(x);
        }
        throw InputError("damage-states", given, "thresholds in increasing order, each once (one fragility row each)");
    }
}

SuiteSpec make_suite_spec(const Options& opts, const SuiteCommand& cmd, SuiteMotions::Measures made_measures) {
    const SweepSpec base = make_sweep_spec(opts);
    const Axis levels = make_axis("intensity", cmd.intensity_range, cmd.intensity_points);
    std::vector<double> radii, alphas;
    if (!cmd.radius_range.empty()) radii = make_axis("radius", cmd.radius_range, cmd.radius_points).values();
    if (!cmd.alpha_range.empty()) {
        alphas = make_axis("alpha", cmd.alpha_range, cmd.alpha_points).values();
        // Every alpha must give a block that can rock: Housner's e = 1 - 2 sin^2(alpha) / (I0/(mR^2)) > 0.
        const double ratio = base.block.inertia_ratio, squat = std::asin(std::sqrt(std::min(ratio / 2.0, 1.0)));
        if (!(housner_e(alphas.back(), ratio) > 0.0))
            throw InputError("alpha-range", format_short(cmd.alpha_range[0]) + " " + format_short(cmd.alpha_range[1]),
                             "angles below " + format_short(squat, 4) + " rad, where Housner's e of this block's I0/(mR^2) = " +
                                 format_short(ratio, 4) + " reaches 0 (the block is too squat to rock)");
    }
    SuiteMotions motions;
    motions.measures = made_measures;
    for (const std::string& text : cmd.floors) motions.floors.push_back(motion::parse_floor("floor", text));
    motions.sa = motion::Oscillator{cmd.sa_period_s, cmd.sa_damping};
    const MadeMotions made = make_suite_motions(cmd);
    motions.made = made.source;
    // With --synthetic-only the records only fit the model: the spec reads none.
    SuiteSpec spec = make_suite_spec(cmd.synthetic_only ? std::string() : cmd.suite, base.block, base.scenarios,
                                     parse_intensity_measure("intensity-measure", cmd.measure), levels, radii, alphas,
                                     std::move(motions));
    label_fitted_motions(spec, cmd, made);
    // No output may replace a record of the suite (io/run_inputs.hpp), swept or only fitted.
    const auto note_files = [&](const SuiteRecord& entry) {
        const std::string where = cmd.suite + " line " + std::to_string(entry.line);
        note_input("record " + entry.name + " of the --suite file (" + where + ")", entry.source.path);
        if (entry.source.vertical) note_input("record " + entry.name + "'s vertical file (" + where + ")", entry.source.vertical->path);
    };
    if (cmd.synthetic_only)
        for (const SuiteRecord& entry : made.suite.records) note_files(entry);
    for (const SuiteMember& m : spec.records) {
        if (m.motion >= 0) continue;  // made, not read: no file, its PGA is the model's
        note_files(m.entry);
        check_suite_record_pga(cmd.suite, m.entry, m.record, opts.numerics.record_any_pga);
    }
    check_record_names(spec);  // before any work: a name the output cannot hold
    spec.equations = base.equations;
    spec.impact_threshold = base.impact_threshold;
    spec.friction = base.friction;
    return spec;
}

namespace {

struct Plan {
    SuiteSpec spec;
    std::vector<DamageState> states;
    IntegratorSettings settings;
};

Plan make_plan(const Options& opts, const SuiteCommand& cmd, const MpiSession& mpi) {
    // The made motions measured once over the ranks, not on each (made_on_ranks.hpp).
    Plan p{make_suite_spec(opts, cmd, SuiteMotions::Measures::none), {}, make_settings(opts.numerics)};
    measure_made_on_ranks(p.spec, mpi);
    for (double x : cmd.damage_states) p.states.push_back({x, false});
    p.states.push_back({0.0, true});
    p.spec.sensitivity.on = cmd.check_sensitivity;
    p.spec.sensitivity.damage_ratios = cmd.damage_states;
    // Rank 0 holds the runs since the last checkpoint, not the results (docs/streaming.md); what
    // it must hold at the end is one scenario's products: per record and block the overturning
    // spectrum (25 B), per state, block and level the fragility's counts and fractions (32 B).
    const SuiteSpec& spec = p.spec;
    const double blocks = static_cast<double>(spec.alphas_rad.size() * spec.radii_m.size()),
                 states = static_cast<double>(p.states.size()), levels = static_cast<double>(spec.intensity.points);
    require_memory("radius-points", std::to_string(cmd.radius_points),
                   blocks * (25.0 * static_cast<double>(spec.records.size()) + states * (32.0 * levels + 128.0)),
                   "the products (overturning spectra, fragility) of " + format_short(blocks) + " block sizes and slendernesses");
    return p;
}

// Rank 0 checkpoints early when the cells it holds reach this, as `sweep` does: its memory
// bound between checkpoints, whatever the suite and the cell rate.
constexpr std::size_t max_pending_bytes = std::size_t{64} << 20;

/// Rank 0's view of the output before any work.
struct Start {
    std::optional<OutputClaim> claim;
    std::optional<SuiteStream> stream;
    std::vector<IndexRange> todo;
    bool complete = false;  ///< resumed a finished suite: nothing to do
};

void prepare_output(Start& s, const Plan& plan, const SweepCommand& cmd, const Provenance& prov, std::ostream& log) {
    if (cmd.resume && cmd.overwrite) throw InputError("resume", "with --overwrite", "one of --resume, --overwrite");
    s.claim.emplace("output", cmd.output);
    const bool exists = s.claim->exists(), resuming = exists && cmd.resume;
    if (exists && !cmd.resume && !cmd.overwrite)
        throw InputError("output", cmd.output, "a new file; it exists: pass --resume to continue it or --overwrite to replace it");
    if (resuming) {  // the file's own checks first (their messages are the more precise), then every option
        check_suite_file(cmd.output, plan.spec, plan.settings);
        check_resumed_config(cmd.output, read_provenance_config(cmd.output), prov.config_text);
    }
    s.stream.emplace(cmd.output, plan.spec, plan.settings, prov, resuming);
    const std::size_t total = plan.spec.cell_count();
    SuiteStream& stream = *s.stream;
    if (!stream.finished())
        s.todo = resuming ? missing_cells(total, [&](std::size_t first, std::size_t count, std::uint8_t* out) {
            stream.read_done(first, count, out);
        })
                          : std::vector<IndexRange>{{0, total}};
    s.complete = stream.finished();
    if (resuming && !cmd.quiet)
        log << cmd.output << (s.complete ? ": suite already complete; nothing to do\n" : ": resuming, ")
            << (s.complete ? "" : std::to_string(stream.done_count()) + " of " + std::to_string(total) + " cells already done\n");
}

std::size_t nearest(const std::vector<double>& axis, double x) {
    std::size_t j = 0;
    for (std::size_t k = 1; k < axis.size(); ++k)
        if (std::abs(axis[k] - x) < std::abs(axis[j] - x)) j = k;
    return j;
}

/// One line per scenario: where the fragility of overturning lies, for the block nearest the
/// configured one.
void summarise(const Plan& plan, const std::vector<SuiteFragility>& fragility, std::ostream& log) {
    const SuiteSpec& spec = plan.spec;
    const std::size_t a = nearest(spec.alphas_rad, spec.block.alpha_rad), j = nearest(spec.radii_m, spec.block.radius_m);
    const IntensityMeasure m = spec.measure;
    const bool in_g = m == IntensityMeasure::pga_g || m == IntensityMeasure::sa_g || m == IntensityMeasure::pfa_g;
    const char* units = in_g ? " g" : m == IntensityMeasure::pgv_m_s ? " m/s" : "";
    log << std::setprecision(3) << "overturning fragility against " << intensity_long_name(spec.measure) << " (alpha = "
        << spec.alphas_rad[a] << " rad, R = " << spec.radii_m[j] << " m):\n";
    int width = 22;  // names on floors ("adaptive_rho0.1@f4_plinth") run longer
    for (const Scenario& sc : spec.scenarios) width = std::max(width, static_cast<int>(sc.name.size()) + 2);
    for (std::size_t s = 0; s < spec.scenarios.size(); ++s) {
        // Overturning is the last damage state.
        const SuiteFragility& fr = fragility.at(s);
        const std::size_t blocks = spec.alphas_rad.size() * spec.radii_m.size();
        const std::size_t k = (plan.states.size() - 1) * blocks + a * spec.radii_m.size() + j;
        const FragilityFit& fit = fr.fits.at(k);
        log << "  " << std::left << std::setw(width) << spec.scenarios[s].name << std::right;
        if (fit.status == FitStatus::ok)
            log << "median " << fit.curve.median << units << " (95 % " << fit.median_lo << " to " << fit.median_hi << "), beta "
                << fit.curve.beta;
        else
            log << to_string(fit.status);
        if (spec.sensitivity.on) log << "; " << fr.sensitive.at(k) << " of its runs flagged sensitive";
        log << "\n";
    }
}

}  // namespace

int run_suite(const Options& opts, const SuiteCommand& cmd, const std::string& config_text, const MpiSession& mpi) {
    const Plan plan = make_plan(opts, cmd, mpi);  // the same on every rank, so is any error
    const SuiteSpec& spec = plan.spec;
    IntegratorSettings settings = plan.settings;
    RootStream log(mpi);
    const StopSignals signals;

    const Provenance prov{ROCKSWEEP_VERSION, config_text, utc_now(), mpi.size(), 0.0};
    Start start;
    const OutputVerdict verdict = agree_on_output(
        mpi, log, [&] { prepare_output(start, plan, cmd.run, prov, log); return start.complete; },
        [&] { start.stream.reset(), start.claim.reset(); });
    if (verdict != OutputVerdict::go) return exit_status(verdict);

    std::size_t done_now = 0;
    const double t0 = MpiSession::wall_time();
    double last_save = t0;
    std::string save_error;  // a failed save stops the run like a signal; reported once at the end
    auto save = [&](auto&& write) {
        try {
            write();
        } catch (const std::exception& e) {
            if (save_error.empty()) save_error = e.what();
        }
        last_save = MpiSession::wall_time();
    };
    auto checkpoint = [&] { save([&] { start.stream->checkpoint(); }); };
    const auto scheduler = make_scheduler(mpi);
    std::size_t todo = 0;
    for (const IndexRange& r : start.todo) todo += r.count;
    Progress progress(todo, cmd.run.quiet || !mpi.is_root());

    ScheduleOptions so;
    so.record_bytes = sizeof(CellResult);
    // Record cells are long: small chunks keep the ranks evenly busy to the end.
    so.max_chunk = std::min<std::size_t>(cmd.run.max_chunk, 64);
    so.min_chunk = 1;
    so.stop_requested = [&] { return StopSignals::received() != 0 || !save_error.empty(); };
    so.tick_interval_s = std::min(0.5, cmd.run.checkpoint_s / 2);
    so.on_tick = [&] {
        progress.update(done_now);
        if (MpiSession::wall_time() - last_save >= cmd.run.checkpoint_s) checkpoint();
    };
    settings.stop_requested = [&] { return StopSignals::received() != 0 || scheduler->stop_pending(); };
    const int lanes = opts.numerics.lanes;
    const ComputeFn compute = cell_results_compute([&](std::size_t first, std::size_t count, CellResult* out) {
        compute_suite_cells(spec, settings, first, count, out, lanes);
    });
    std::vector<CellResult> cells;
    const SinkFn sink = [&](std::size_t first, std::size_t count, const std::byte* records) {
        cells.resize(count);
        std::memcpy(cells.data(), records, count * sizeof(CellResult));
        start.stream->add(first, count, cells.data());
        done_now += count;
        if (start.stream->pending_bytes() >= max_pending_bytes) checkpoint();
    };

    if (mpi.is_root() && !cmd.run.quiet) {
        // What each record is as read: a wrong unit shows before the results are believed.
        for (const SuiteMember& m : spec.records)
            if (m.motion < 0) log << "record " << m.entry.name << ": " << record_facts(m.record) << "\n";
        if (spec.motions) log << "synthetic motions: " << spec.motions->describe() << "\n";
        log << "suite: " << spec.scenarios.size() << " scenarios x " << spec.records.size() << " records x " << spec.alphas_rad.size()
            << " slendernesses x " << spec.radii_m.size() << " block sizes x " << spec.intensity.points << " levels = " << spec.cell_count() << " cells on " << mpi.size()
            << " rank(s) -> " << cmd.run.output << "\n";
    }
    scheduler->run(start.todo, so, compute, sink);
    progress.update(done_now);
    progress.finish();
    if (!mpi.is_root()) return 0;  // rank 0 alone decides the job's status
    std::vector<SuiteFragility> fragility;
    if (save_error.empty()) save([&] { fragility = start.stream->finish(plan.states, MpiSession::wall_time() - t0); });
    if (!save_error.empty()) {
        log << "rocksweep: error: " << save_error << "\n";
        return 1;
    }
    const std::size_t done = start.stream->done_count(), total = spec.cell_count();
    if (done < total) {
        log << "stopped by signal " << StopSignals::stopping_signal() << ": " << done << " of " << total << " cells saved in "
            << cmd.run.output << "; rerun with --resume to continue\n";
        return StopSignals::exit_status();
    }
    if (!cmd.run.quiet) {
        summarise(plan, fragility, log);
        log << "wrote " << cmd.run.output << "\n";
    }
    return 0;
}

}  // namespace rocksweep
