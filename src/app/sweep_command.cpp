// `rocksweep sweep`: build the work list, schedule it over the ranks, and keep rank 0's file
// up to date so that nothing computed is lost to a kill.
#include <cstring>
#include <iostream>
#include <optional>

#include "rocksweep/app/cli.hpp"
#include "rocksweep/app/run_support.hpp"
#include "rocksweep/core/errors.hpp"
#include "rocksweep/physics/integrator.hpp"
#include "rocksweep/io/output_claim.hpp"
#include "rocksweep/parallel/progress.hpp"
#include "rocksweep/grid/refine.hpp"
#include "rocksweep/parallel/scheduler.hpp"
#include "rocksweep/io/spectra_file.hpp"
#include "rocksweep/grid/work_part.hpp"

#ifndef ROCKSWEEP_VERSION
#define ROCKSWEEP_VERSION "unknown"
#endif

namespace rocksweep {

namespace {

/// Rank 0's view of the output before any work: the output held for this run, and where the
/// results start from.
struct Start {
    std::optional<OutputClaim> claim;
    SweepResults results;
    std::vector<IndexRange> todo;
    bool complete = false;  ///< resumed a finished sweep: nothing to compute, nothing to write
};

void prepare_output(Start& s, const SweepSpec& spec, const IntegratorSettings& settings, const SweepCommand& cmd,
                    WorkPart part, std::ostream& log) {
    if (cmd.resume && cmd.overwrite) throw InputError("resume", "with --overwrite", "one of --resume, --overwrite");
    s.claim.emplace("output", cmd.output);
    s.results.resize(spec.cell_count());
    const bool exists = s.claim->exists();
    if (exists && cmd.resume) {
        s.results = read_spectra_results(cmd.output, spec, settings);
    } else if (exists && !cmd.overwrite) {
        throw InputError("output", cmd.output, "a new file; it exists: pass --resume to continue it or --overwrite to replace it");
    }
    s.todo = restrict_to_part(missing_ranges(s.results.done), part);
    // A requeued job resumes a sweep (or its part) that already ended: saving again would only
    // replace its recorded wall time with this run's few milliseconds.
    s.complete = exists && cmd.resume && s.todo.empty();
    if (!(exists && cmd.resume) || cmd.quiet) return;
    const std::size_t total = spec.cell_count();
    if (!s.complete)
        log << "resuming " << cmd.output << ": " << s.results.done_count() << " of " << total << " cells already done\n";
    else if (part.count > 1)
        log << cmd.output << ": part " << part.index << " of " << part.count << " already complete (" << cells_in_part(total, part)
            << " cells); nothing to do\n";
    else
        log << cmd.output << ": sweep already complete (" << total << " cells); nothing to do\n";
}

}  // namespace

int run_sweep(const Options& opts, const SweepCommand& cmd, const std::string& config_text, const MpiSession& mpi) {
    const SweepSpec spec = make_sweep_spec(opts);  // the same on every rank, so is any error
    IntegratorSettings settings = make_settings(opts.numerics);
    const WorkPart part = cmd.part.empty() ? WorkPart{} : parse_work_part(cmd.part);
    if (part.count > 1 && cmd.refine_stride != 0)
        throw InputError("part", cmd.part, "not with --refine: refinement needs the whole grid between its passes");
    RootStream log(mpi);
    const StopSignals signals;

    // The output is claimed on rank 0 only; the verdict reaches every rank before any work.
    Start start;
    int verdict = 0;
    std::string why;
    if (mpi.is_root()) {
        try {
            prepare_output(start, spec, settings, cmd, part, log);
        } catch (const InputError& e) {
            start.claim.reset();  // releases the output before the message
            verdict = 2;
            why = cli_message(e);
        }
    }
    constexpr int nothing_to_do = -1;
    if (start.complete) verdict = nothing_to_do;
    if (mpi.size() > 1) MPI_Bcast(&verdict, 1, MPI_INT, 0, mpi.comm());
    if (verdict == nothing_to_do) return 0;
    if (verdict != 0) {
        log << "rocksweep: error: " << why << "\n";
        return verdict;
    }

    Provenance prov;
    prov.version = ROCKSWEEP_VERSION;
    prov.config_text = config_text;
    prov.created_utc = utc_now();
    prov.ranks = mpi.size();

    SweepResults& results = start.results;
    const std::size_t total = spec.cell_count();
    std::size_t done_now = 0;
    const double t0 = MPI_Wtime();
    double last_save = t0;
    // A failed save (e.g. a full disk) stops the run like a signal, so that every rank leaves
    // the scheduler normally; rank 0 reports it once at the end.
    std::string save_error;
    auto save = [&] {
        prov.wall_s = MPI_Wtime() - t0;
        try {
            write_spectra(cmd.output, spec, results, prov, settings);
        } catch (const std::exception& e) {
            if (save_error.empty()) save_error = e.what();
        }
        last_save = MPI_Wtime();
    };
    Progress* progress = nullptr;
    const auto scheduler = make_mpi_scheduler(mpi.comm());

    ScheduleOptions so;
    so.record_bytes = sizeof(CellResult);
    so.max_chunk = cmd.max_chunk;
    so.min_chunk = std::min<std::size_t>(8, cmd.max_chunk);
    so.stop_requested = [&] { return StopSignals::received() != 0 || !save_error.empty(); };
    so.tick_interval_s = std::min(0.5, cmd.checkpoint_s / 2);
    so.on_tick = [&] {
        if (progress) progress->update(done_now);
        if (MPI_Wtime() - last_save >= cmd.checkpoint_s) save();
    };
    // A slow cell polls this every few hundred steps: a stop is honoured in the middle of a
    // chunk, which is then abandoned (not done) rather than finished.
    settings.stop_requested = [&] { return StopSignals::received() != 0 || scheduler->stop_pending(); };
    const int lanes = opts.numerics.lanes;
    const ComputeFn compute = [&](std::size_t first, std::size_t count, std::byte* out) {
        std::vector<CellResult> buf(count);
        try {
            compute_cells(spec, settings, first, count, buf.data(), lanes);
        } catch (const Interrupted&) {
            throw ChunkAbandoned();
        }
        std::memcpy(out, buf.data(), count * sizeof(CellResult));
    };
    const SinkFn sink = [&](std::size_t first, std::size_t count, const std::byte* records) {
        for (std::size_t i = 0; i < count; ++i) {
            CellResult r;
            std::memcpy(&r, records + i * sizeof(CellResult), sizeof r);
            results.store(first + i, r);
        }
        done_now += count;
    };
    auto run_pass = [&](const std::vector<IndexRange>& todo) {
        std::size_t n = 0;
        for (const IndexRange& r : todo) n += r.count;
        Progress bar(n, cmd.quiet || !mpi.is_root());
        progress = &bar;
        done_now = 0;
        const ScheduleStats stats = scheduler->run(todo, so, compute, sink);
        bar.update(done_now);
        bar.finish();
        progress = nullptr;
        return stats;
    };

    if (mpi.is_root() && !cmd.quiet) {
        log << "sweep: " << spec.scenarios.size() << " scenarios x " << spec.amplitude_ratio.points << " amplitudes x "
            << spec.omega_ratio.points << " frequencies = " << total << " cells";
        if (part.count > 1) log << ", part " << part.index << " of " << part.count << ": " << cells_in_part(total, part);
        log << " on " << mpi.size() << " rank(s) -> " << cmd.output << "\n";
    }
    bool stopped = false;
    if (cmd.refine_stride == 0) {
        stopped = run_pass(start.todo).stopped;
    } else {
        // Every rank runs the same number of passes; only rank 0 knows each pass's cells.
        const std::size_t per = spec.cells_per_scenario();
        const Refinement refine(spec.amplitude_ratio.points, spec.omega_ratio.points, cmd.refine_stride);
        for (int k = 0; k < refine.passes() && !stopped; ++k) {
            std::vector<IndexRange> todo;
            if (mpi.is_root()) {
                for (std::size_t s = 0; s < spec.scenarios.size(); ++s)
                    for (std::size_t i : refine.cells_for_pass(k, &results.outcome[s * per], &results.done[s * per])) {
                        if (!todo.empty() && todo.back().first + todo.back().count == s * per + i) ++todo.back().count;
                        else todo.push_back({s * per + i, 1});
                    }
                if (!cmd.quiet) log << "refinement pass " << k + 1 << " of " << refine.passes() << "\n";
            }
            stopped = run_pass(todo).stopped;
        }
        if (mpi.is_root() && !stopped)
            for (std::size_t s = 0; s < spec.scenarios.size(); ++s)
                refine.fill(&results.outcome[s * per], &results.done[s * per]);
    }
    // Rank 0 alone decides the job's status: a worker that exited non-zero first would make
    // mpirun kill rank 0, maybe in the middle of its last save.
    if (!mpi.is_root()) return 0;
    if (save_error.empty()) save();
    if (!save_error.empty()) {
        log << "rocksweep: error: " << save_error << "\n";
        return 1;
    }
    const std::size_t done = results.done_count();
    if (part.count > 1 && restrict_to_part(missing_ranges(results.done), part).empty()) {
        if (!cmd.quiet)
            log << "wrote part " << part.index << " of " << part.count << " (" << cells_in_part(total, part) << " of "
                << total << " cells) to " << cmd.output << "; join the parts with rocksweep merge\n";
        return 0;
    }
    if (done < total && part.count > 1) {
        log << "stopped by signal " << StopSignals::stopping_signal() << ": part " << part.index << " of " << part.count << " not finished, "
            << done << " cells saved in " << cmd.output << "; rerun with --resume to continue\n";
        return StopSignals::exit_status();
    }
    if (done < total) {
        log << "stopped by signal " << StopSignals::stopping_signal() << ": " << done << " of " << total << " cells saved in " << cmd.output
            << "; rerun with --resume to continue\n";
        return StopSignals::exit_status();
    }
    if (spec.friction > 0.0 && !cmd.quiet) {
        std::size_t slide = 0, jump = 0;
        for (std::size_t i = 0; i < total; ++i) {
            slide += results.done[i] == cell_computed && results.mu_required[i] > spec.friction;
            jump += results.pivot_uplift[i];
        }
        log << slide << " cells need more friction than mu_s = " << spec.friction
            << " (their pure-rocking results assume no sliding; see mu_required)";
        if (jump) log << ", " << jump << " would lift the pivot (pivot_uplift)";
        log << "\n";
    }
    if (!cmd.quiet) log << "wrote " << cmd.output << "\n";
    return 0;
}

}  // namespace rocksweep
