// `rocksweep sweep`: build the work list, schedule it over the ranks, and stream rank 0's
// results into the file as they come, so that nothing computed is lost to a kill and rank 0's
// memory does not grow with the grid.
#include <cstring>
#include <iostream>
#include <optional>

#include "rocksweep/app/cli.hpp"
#include "rocksweep/app/run_support.hpp"
#include "rocksweep/app/sweep_refinement.hpp"
#include "rocksweep/core/errors.hpp"
#include "rocksweep/grid/refine.hpp"
#include "rocksweep/grid/refine_planes.hpp"
#include "rocksweep/grid/work_part.hpp"
#include "rocksweep/io/output_claim.hpp"
#include "rocksweep/app/resume_check.hpp"
#include "rocksweep/io/spectra_stream.hpp"
#include "rocksweep/parallel/progress.hpp"
#include "rocksweep/parallel/scheduler.hpp"
#include "rocksweep/physics/integrator.hpp"


namespace rocksweep {

namespace {

// Rank 0 checkpoints early when the cells it holds reach this: its memory bound between
// checkpoints, whatever the grid and the cell rate (about 1 M cells).
constexpr std::size_t max_pending_bytes = std::size_t{64} << 20;

std::vector<IndexRange> missing_cells(const SpectraStream& stream, std::size_t total) {
    return rocksweep::missing_cells(total, [&](std::size_t first, std::size_t count, std::uint8_t* out) {
        stream.read_column("done", first, count, out);
    });
}

/// One sweep, in the order it runs: plan (constructor), agree on the output, run the passes,
/// finish. Rank 0 alone holds the output; every rank runs the same passes.
class SweepRun {
public:
    SweepRun(const Options& opts, const SweepCommand& cmd, const std::string& config_text, const MpiSession& mpi)
        : cmd_(cmd), mpi_(mpi), spec_(sweep_spec(opts, cmd)),  // the same on every rank, so is any error
          settings_(make_settings(opts.numerics)), lanes_(opts.numerics.lanes),
          part_(cmd.part.empty() ? WorkPart{} : parse_work_part(cmd.part)), log_(mpi) {
        if (part_.count > 1 && cmd.refine_stride != 0)
            throw InputError("part", cmd.part, "not with --refine: refinement needs the whole grid between its passes");
        planes_ = refine_planes(spec_, cmd);
        prov_.version = ROCKSWEEP_VERSION;
        prov_.config_text = config_text;
        prov_.created_utc = utc_now();
        prov_.ranks = mpi.size();
    }

    /// Rank 0 claims the output (or finds it complete, or refuses it); the verdict reaches every
    /// rank before any work. Returns the exit status when there is nothing to run.
    std::optional<int> agree_on_output();
    void announce();
    /// Runs every pass (one, or refinement's) until done or stopped (a signal, a failed save).
    void run_passes();
    /// Rank 0's last save and report. Returns the exit status.
    int finish();

private:
    void prepare_output();
    void save();
    ScheduleStats run_pass(const std::vector<IndexRange>& todo);
    std::vector<IndexRange> refinement_pass(const Refinement& refine, int k);
    void infer_the_rest(const Refinement& refine);
    /// Plane `j` of scenario `s` as the file holds it: its span of cells (`span_*`) and the plane
    /// gathered from it, row by row (`outcome`, `done`).
    struct PlaneCells {
        std::vector<std::uint8_t> span_outcome, span_done, outcome, done;
    };
    void read_plane(std::size_t s, std::size_t j, PlaneCells& p) const;
    void report_friction();

    const SweepCommand& cmd_;
    const MpiSession& mpi_;
    const SweepSpec spec_;
    std::optional<RefinePlanes> planes_;  // with --refine: the planes it works on
    IntegratorSettings settings_;
    const int lanes_;
    const WorkPart part_;
    RootStream log_;
    const StopSignals signals_;
    Provenance prov_;
    // Rank 0 only:
    std::optional<OutputClaim> claim_;
    std::optional<SpectraStream> stream_;
    std::vector<IndexRange> todo_;
    bool already_complete_ = false;
    double t0_ = 0.0, last_save_ = 0.0;
    // A failed save (e.g. a full disk) stops the run like a signal, so that every rank leaves
    // the scheduler normally; rank 0 reports it once at the end.
    std::string save_error_;
};

void SweepRun::prepare_output() {
    if (cmd_.resume && cmd_.overwrite) throw InputError("resume", "with --overwrite", "one of --resume, --overwrite");
    claim_.emplace("output", cmd_.output);
    const bool exists = claim_->exists();
    if (exists && !cmd_.resume && !cmd_.overwrite)
        throw InputError("output", cmd_.output, "a new file; it exists: pass --resume to continue it or --overwrite to replace it");
    const bool resuming = exists && cmd_.resume;
    if (resuming) {  // the file's own checks first (their messages are the more precise), then every option
        check_spectra_file(cmd_.output, spec_, settings_);
        check_resumed_config(cmd_.output, read_provenance_config(cmd_.output), prov_.config_text);
    }
    stream_.emplace(cmd_.output, spec_, settings_, prov_, resuming);
    const std::size_t total = spec_.cell_count();
    todo_ = restrict_to_part(resuming ? missing_cells(*stream_, total) : std::vector<IndexRange>{{0, total}}, part_);
    // A requeued job resumes a sweep (or its part) that already ended: saving again would only
    // replace its recorded wall time with this run's few milliseconds. One killed between its
    // last cell and its close-out has every cell but not `complete` nor its checksums: it runs
    // no cell and is closed out.
    already_complete_ = resuming && todo_.empty() && stream_->closed_out();
    if (!resuming || cmd_.quiet) return;
    if (!already_complete_)
        log_ << "resuming " << cmd_.output << ": " << stream_->done_count() << " of " << total << " cells already done\n";
    else if (part_.count > 1)
        log_ << cmd_.output << ": part " << part_.index << " of " << part_.count << " already complete ("
             << cells_in_part(total, part_) << " cells); nothing to do\n";
    else
        log_ << cmd_.output << ": sweep already complete (" << total << " cells); nothing to do\n";
}

std::optional<int> SweepRun::agree_on_output() {
    const OutputVerdict verdict = rocksweep::agree_on_output(
        mpi_, log_, [&] { prepare_output(); return already_complete_; }, [&] { stream_.reset(), claim_.reset(); });
    if (verdict != OutputVerdict::go) return exit_status(verdict);
    t0_ = last_save_ = MpiSession::wall_time();
    return std::nullopt;
}

void SweepRun::announce() {
    if (cmd_.quiet) return;
    const std::size_t total = spec_.cell_count();
    log_ << "sweep: " << spec_.scenarios.size() << " scenarios x " << spec_.amplitude_ratio.points << " amplitudes x "
         << spec_.omega_ratio.points << " frequencies = " << total << " cells";
    if (part_.count > 1) log_ << ", part " << part_.index << " of " << part_.count << ": " << cells_in_part(total, part_);
    log_ << " on " << mpi_.size() << " rank(s) -> " << cmd_.output << "\n";
}

void SweepRun::save() {
    try {
        stream_->checkpoint();
    } catch (const std::exception& e) {
        if (save_error_.empty()) save_error_ = e.what();
    }
    last_save_ = MpiSession::wall_time();
}

ScheduleStats SweepRun::run_pass(const std::vector<IndexRange>& todo) {
    const auto scheduler = make_scheduler(mpi_);
    std::size_t n = 0, done_now = 0;
    for (const IndexRange& r : todo) n += r.count;
    Progress bar(n, cmd_.quiet || !mpi_.is_root());

    ScheduleOptions so;
    so.record_bytes = sizeof(CellResult);
    so.max_chunk = cmd_.max_chunk;
    so.min_chunk = std::min<std::size_t>(8, cmd_.max_chunk);
    so.stop_requested = [&] { return StopSignals::received() != 0 || !save_error_.empty(); };
    so.tick_interval_s = std::min(0.5, cmd_.checkpoint_s / 2);
    so.on_tick = [&] {
        bar.update(done_now);
        if (MpiSession::wall_time() - last_save_ >= cmd_.checkpoint_s) save();
    };
    // A slow cell polls this every few hundred steps: a stop is honoured in the middle of a
    // chunk, which is then abandoned (not done) rather than finished.
    IntegratorSettings settings = settings_;
    settings.stop_requested = [&] { return StopSignals::received() != 0 || scheduler->stop_pending(); };
    const ComputeFn compute = [&](std::size_t first, std::size_t count, std::byte* out) {
        std::vector<CellResult> buf(count);
        try {
            compute_cells(spec_, settings, first, count, buf.data(), lanes_);
        } catch (const Interrupted&) {
            throw ChunkAbandoned();
        }
        std::memcpy(out, buf.data(), count * sizeof(CellResult));
    };
    std::vector<CellResult> cells;
    const SinkFn sink = [&](std::size_t first, std::size_t count, const std::byte* records) {
        cells.resize(count);
        std::memcpy(cells.data(), records, count * sizeof(CellResult));
        stream_->add(first, count, cells.data());
        done_now += count;
        if (stream_->pending_bytes() >= max_pending_bytes) save();
    };
    const ScheduleStats stats = scheduler->run(todo, so, compute, sink);
    bar.update(done_now);
    bar.finish();
    return stats;
}

/// The cells the passes before `k` compute in a run that is never interrupted, replayed from
/// the outcomes: a pass must choose from these alone, not from what a killed run had computed
/// beyond them (a corner known early would make a square mixed sooner, and the resumed sweep
/// would compute cells the uninterrupted one infers).
std::vector<std::uint8_t> known_before(const Refinement& refine, int k, const std::vector<std::uint8_t>& outcome) {
    std::vector<std::uint8_t> known(outcome.size(), cell_pending);
    for (int j = 0; j < k; ++j)
        for (std::size_t i : refine.cells_for_pass(j, outcome.data(), known.data())) known[i] = cell_computed;
    return known;
}

void SweepRun::read_plane(std::size_t s, std::size_t j, PlaneCells& p) const {
    const RefinePlanes& planes = *planes_;
    const std::size_t first = planes.first(j), cols = planes.cols();
    p.span_outcome.resize(planes.span());
    p.span_done.resize(planes.span());
    p.outcome.resize(planes.rows() * cols);
    p.done.resize(planes.rows() * cols);
    stream_->read_outcomes(s, first, planes.span(), p.span_outcome.data(), p.span_done.data());
    for (std::size_t r = 0; r < planes.rows(); ++r)
        for (std::size_t c = 0; c < cols; ++c) {
            const std::size_t at = planes.cell(j, r, c) - first;
            p.outcome[r * cols + c] = p.span_outcome[at];
            p.done[r * cols + c] = p.span_done[at];
        }
}

std::vector<IndexRange> SweepRun::refinement_pass(const Refinement& refine, int k) {
    // Each plane (the pair of axes refined over, at one point of every other axis) is refined
    // alone, from what earlier passes found, read back from the file.
    save();
    const RefinePlanes& planes = *planes_;
    const std::size_t per = spec_.cells_per_scenario();
    PlaneCells p;
    std::vector<std::size_t> cells;
    for (std::size_t s = 0; s < spec_.scenarios.size() && save_error_.empty(); ++s)
        for (std::size_t j = 0; j < planes.count() && save_error_.empty(); ++j) {
            read_plane(s, j, p);
            const std::vector<std::uint8_t> known = known_before(refine, k, p.outcome);
            for (std::size_t i : refine.cells_for_pass(k, p.outcome.data(), known.data()))
                if (p.done[i] != cell_computed)  // else computed before a kill
                    cells.push_back(s * per + planes.cell(j, i / planes.cols(), i % planes.cols()));
        }
    std::sort(cells.begin(), cells.end());
    std::vector<IndexRange> todo;
    for (std::size_t cell : cells) {
        if (!todo.empty() && todo.back().first + todo.back().count == cell) ++todo.back().count;
        else todo.push_back({cell, 1});
    }
    if (!cmd_.quiet) log_ << "refinement pass " << k + 1 << " of " << refine.passes() << "\n";
    return todo;
}

void SweepRun::infer_the_rest(const Refinement& refine) {
    save();
    const RefinePlanes& planes = *planes_;
    PlaneCells p;
    std::vector<std::uint8_t> span_after;
    for (std::size_t s = 0; s < spec_.scenarios.size() && save_error_.empty(); ++s)
        for (std::size_t j = 0; j < planes.count() && save_error_.empty(); ++j) {
            try {
                read_plane(s, j, p);
                std::vector<std::uint8_t> known = known_before(refine, refine.passes(), p.outcome);
                refine.fill(p.outcome.data(), known.data());
                // Back into the span: cells of other planes keep done_after = done_before, untouched.
                span_after = p.span_done;
                for (std::size_t i = 0; i < known.size(); ++i) {
                    const std::size_t at = planes.cell(j, i / planes.cols(), i % planes.cols()) - planes.first(j);
                    span_after[at] = known[i];
                    p.span_outcome[at] = p.outcome[i];
                }
                stream_->add_inferred(s, planes.first(j), planes.span(), p.span_outcome.data(), p.span_done.data(),
                                      span_after.data());
            } catch (const std::exception& e) {
                save_error_ = e.what();
            }
        }
}

void SweepRun::run_passes() {
    if (cmd_.refine_stride == 0) {
        run_pass(todo_);
        return;
    }
    // Every rank runs the same number of passes; only rank 0 knows each pass's cells.
    const Refinement refine(planes_->rows(), planes_->cols(), cmd_.refine_stride);
    for (int k = 0; k < refine.passes(); ++k) {
        const std::vector<IndexRange> todo = mpi_.is_root() ? refinement_pass(refine, k) : std::vector<IndexRange>{};
        if (run_pass(todo).stopped) return;
    }
    if (mpi_.is_root()) infer_the_rest(refine);
}

void SweepRun::report_friction() {
    // Read back a block at a time: the cells of earlier runs of a resumed sweep count too.
    constexpr std::size_t scan_cells = std::size_t{1} << 24;
    const std::size_t total = spec_.cell_count();
    std::size_t slide = 0, jump = 0;
    std::vector<double> mu;
    std::vector<std::uint8_t> uplift, done;
    for (std::size_t first = 0; first < total; first += scan_cells) {
        const std::size_t n = std::min(scan_cells, total - first);
        mu.resize(n), uplift.resize(n), done.resize(n);
        stream_->read_column("mu_required", first, n, mu.data());
        stream_->read_column("pivot_uplift", first, n, uplift.data());
        stream_->read_column("done", first, n, done.data());
        for (std::size_t i = 0; i < n; ++i) {
            slide += done[i] == cell_computed && mu[i] > spec_.friction;
            jump += uplift[i];
        }
    }
    log_ << slide << " cells need more friction than mu_s = " << spec_.friction
         << " (their pure-rocking results assume no sliding; see mu_required)";
    if (jump) log_ << ", " << jump << " would lift the pivot (pivot_uplift)";
    log_ << "\n";
}

int SweepRun::finish() {
    // Rank 0 alone decides the job's status: a worker that exited non-zero first would make
    // mpirun kill rank 0, maybe in the middle of its last save.
    if (!mpi_.is_root()) return 0;
    if (save_error_.empty()) {
        try {
            stream_->finish(MpiSession::wall_time() - t0_);
        } catch (const std::exception& e) {
            save_error_ = e.what();
        }
    }
    if (!save_error_.empty()) {
        log_ << "rocksweep: error: " << save_error_ << "\n";
        return 1;
    }
    const std::size_t total = spec_.cell_count(), done = stream_->done_count();
    if (part_.count > 1 && restrict_to_part(missing_cells(*stream_, total), part_).empty()) {
        if (!cmd_.quiet)
            log_ << "wrote part " << part_.index << " of " << part_.count << " (" << cells_in_part(total, part_) << " of "
                 << total << " cells) to " << cmd_.output << "; join the parts with rocksweep merge\n";
        return 0;
    }
    if (done < total && part_.count > 1) {
        log_ << "stopped by signal " << StopSignals::stopping_signal() << ": part " << part_.index << " of " << part_.count
             << " not finished, " << done << " cells saved in " << cmd_.output << "; rerun with --resume to continue\n";
        return StopSignals::exit_status();
    }
    if (done < total) {
        log_ << "stopped by signal " << StopSignals::stopping_signal() << ": " << done << " of " << total
             << " cells saved in " << cmd_.output << "; rerun with --resume to continue\n";
        return StopSignals::exit_status();
    }
    if (spec_.friction > 0.0 && !cmd_.quiet) report_friction();
    if (!cmd_.quiet) log_ << "wrote " << cmd_.output << "\n";
    return 0;
}

}  // namespace

int run_sweep(const Options& opts, const SweepCommand& cmd, const std::string& config_text, const MpiSession& mpi) {
    SweepRun sweep(opts, cmd, config_text, mpi);  // the cells, the settings, the part
    if (const std::optional<int> status = sweep.agree_on_output()) return *status;
    sweep.announce();
    sweep.run_passes();
    return sweep.finish();
}

}  // namespace rocksweep
