#pragma once
/// What every long-running command (sweep, suite, design) shares around the scheduler: signals
/// that stop it cleanly, the time stamp of its provenance, and the cells still to compute.
#include <csignal>
#include <cstdint>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "rocksweep/grid/sweep.hpp"
#include "rocksweep/parallel/mpi_session.hpp"
#include "rocksweep/parallel/scheduler.hpp"

namespace rocksweep {

/// SIGINT/SIGTERM only raise a flag while a run is under way (from before its output is claimed
/// to the end of its last save, so a signal never kills a save half-way and leaves NAME.tmp):
/// the integration polls it and gives up its chunk, rank 0 stops handing out work, gathers what
/// is done and saves it. One guard at a time; the previous handlers come back with it.
class StopSignals {
public:
    StopSignals();
    ~StopSignals();
    StopSignals(const StopSignals&) = delete;
    StopSignals& operator=(const StopSignals&) = delete;

    /// The signal received since the guard was made, or 0.
    static int received();
    /// The signal a stopped run reports: the one received, else SIGINT (it stopped for another
    /// reason, and is reported as interrupted).
    static int stopping_signal();
    /// The exit status of a stopped run: 128 + stopping_signal().
    static int exit_status() { return 128 + stopping_signal(); }

private:
    struct sigaction old_int_{}, old_term_{};
};

/// What every rank does after rank 0 looked at the output.
enum class OutputVerdict { go, nothing_to_do, refused, failed };

/// The exit status of a verdict that ends the run: 0 nothing to do, 2 refused (bad input),
/// 1 failed (the output could not be laid out, e.g. a full disk).
int exit_status(OutputVerdict v);

/// Rank 0 calls `prepare`, which claims and reads the output and returns true if there is
/// nothing left to do (a finished run resumed), or throws InputError (refused) or
/// std::runtime_error (failed); `release` then gives the output up before the message. Every
/// rank learns the verdict; an error is printed once, by rank 0, as "rocksweep: error: ...".
/// Collective.
OutputVerdict agree_on_output(const MpiSession& mpi, std::ostream& log, const std::function<bool()>& prepare,
                              const std::function<void()>& release);

/// The scheduler's side of a computation of cells: `compute(first, count, out)` fills `count`
/// CellResults; an integration interrupted by a stop request gives its chunk up (ChunkAbandoned).
ComputeFn cell_results_compute(std::function<void(std::size_t first, std::size_t count, CellResult* out)> compute);

/// Now as ISO 8601 UTC, e.g. 2026-11-24T00:15:07Z.
std::string utc_now();

/// The runs of cells whose `done` entry is 0, in index order.
std::vector<IndexRange> missing_ranges(const std::vector<std::uint8_t>& done);
/// `read_done(first, count, out)`: the done bytes of cells [first, first + count) of a file.
using DoneReader = std::function<void(std::size_t first, std::size_t count, std::uint8_t* out)>;
/// The runs of cells [0, total) whose done byte is 0, read a block of 16 M cells at a time
/// (1 byte per cell of the block, not of the grid).
std::vector<IndexRange> missing_cells(std::size_t total, const DoneReader& read_done);

}  // namespace rocksweep
