#pragma once
/// Hands out index ranges of a work list and brings fixed-size result records back to rank 0.
/// Knows nothing of what a cell is.
#include <mpi.h>

#include <cstddef>
#include <exception>
#include <functional>
#include <memory>
#include <vector>

namespace rocksweep {

struct IndexRange {
    std::size_t first = 0, count = 0;
};

/// Computes records [first, first + count) into `out` (count * record_bytes bytes).
/// A record must depend only on its index: results are then identical for any rank count and
/// chunk size (the scheduler never touches the bytes of a record).
/// It may give its chunk up by throwing ChunkAbandoned, e.g. when Scheduler::stop_pending()
/// turns true in the middle of slow cells.
using ComputeFn = std::function<void(std::size_t first, std::size_t count, std::byte* out)>;
/// Receives finished records on rank 0, in any order.
using SinkFn = std::function<void(std::size_t first, std::size_t count, const std::byte* records)>;

/// Thrown by a ComputeFn that gave its chunk up because a stop was requested. The chunk is not
/// done: it never reaches the sink, and the run stops as if stop_requested had returned true.
class ChunkAbandoned : public std::exception {
public:
    const char* what() const noexcept override { return "chunk abandoned on a stop request"; }
};

/// Must be equal on every rank, except the callbacks, which only rank 0 calls.
struct ScheduleOptions {
    std::size_t record_bytes = 0;
    std::size_t max_chunk = 256;  ///< largest chunk handed out; chunks shrink as work runs out
    std::size_t min_chunk = 8;    ///< smallest chunk, except at the end of a todo range (0 acts as 1)
    /// Guided scheduling: a chunk is remaining / (guided_divisor * computing ranks), clamped
    /// to [min_chunk, max_chunk]. Larger values give smaller chunks and a more even finish.
    std::size_t guided_divisor = 2;
    /// Chunks kept at each worker: one in hand and the rest waiting in its mailbox, so that no
    /// worker idles while the master replies.
    std::size_t chunks_per_worker = 2;
    /// Rank 0 also computes (in half-size chunks, between serving the workers) when the job has
    /// at most this many ranks; above it rank 0 only dispatches. 0: rank 0 never computes.
    int master_computes_up_to = 8;

    /// Polled on rank 0 (about every 10 ms, and before each chunk rank 0 computes itself).
    /// Once it returns true no new chunk is handed out and every worker is told so
    /// (Scheduler::stop_pending() turns true there); chunks already handed out are finished and
    /// sunk, or abandoned (ChunkAbandoned) and left undone, then run() returns normally on every
    /// rank with `stopped` set.
    std::function<bool()> stop_requested;
    /// Called on rank 0 every tick_interval_s while run() waits or works (between chunks when
    /// rank 0 computes), e.g. to checkpoint and print progress. Not called after the last chunk.
    std::function<void()> on_tick;
    double tick_interval_s = 0.5;
};

/// What a run did. `complete`, `stopped`, `chunks` and `cells_done` are the same on every rank;
/// the per-rank vectors (size() entries) are filled on rank 0, elsewhere only this rank's entry.
struct ScheduleStats {
    bool complete = false;  ///< every index of `todo` reached the sink
    bool stopped = false;   ///< stop_requested returned true (complete may still be true if nothing was left)
    std::size_t chunks = 0;      ///< chunks handed out, rank 0's own included
    std::size_t cells_done = 0;  ///< cells that reached the sink
    std::vector<std::size_t> cells_per_rank;
    std::vector<std::size_t> chunks_per_rank;
    double wall_s = 0.0;  ///< duration of run() on this rank
};

class Scheduler {
public:
    virtual ~Scheduler() = default;
    /// Runs every index of `todo`; `sink` sees each finished chunk on rank 0 only.
    /// Collective: every rank of the scheduler calls it with the same options (`todo` and
    /// `sink` are only read on rank 0). A chunk never spans two todo ranges.
    /// Throws std::invalid_argument for inconsistent options (on every rank, before any message).
    /// With one rank, exceptions from the callbacks propagate; with several, an exception on
    /// any rank prints "ERROR on rank N: ..." and aborts the job (see abort_on_error).
    virtual ScheduleStats run(const std::vector<IndexRange>& todo, const ScheduleOptions& options,
                              const ComputeFn& compute, const SinkFn& sink) = 0;
    virtual int rank() const = 0;
    virtual int size() const = 0;
    /// True once this run is stopping: on rank 0 when stop_requested returns true (asked
    /// afresh) or a chunk was abandoned, on a worker once rank 0's stop notice has arrived. Cheap (one
    /// MPI_Iprobe), callable from inside ComputeFn, so that a chunk of slow cells can be given
    /// up within a fraction of a second of the request.
    virtual bool stop_pending() = 0;
};

/// One process, no messages: chunks of max_chunk in order, sink after each.
std::unique_ptr<Scheduler> make_serial_scheduler();

/// Rank 0 of `comm` hands out chunks dynamically and gathers the results; every rank computes
/// (rank 0 only while the job is small, see ScheduleOptions::master_computes_up_to).
/// Collective over `comm` (duplicates it, so its messages never mix with the caller's).
/// With one rank it behaves exactly like the serial scheduler and sends no message.
/// Throws std::logic_error if MPI is not initialised.
std::unique_ptr<Scheduler> make_mpi_scheduler(MPI_Comm comm = MPI_COMM_WORLD);

class MpiSession;
/// The session's scheduler: the MPI one over its world when it uses MPI, else the serial one.
/// Both run a job of one rank through the same serial loop, hence the same results.
std::unique_ptr<Scheduler> make_scheduler(const MpiSession& session);

/// The guided chunk size for `remaining` cells shared among `computing_ranks`:
/// remaining / (guided_divisor * computing_ranks), rounded up, clamped to [min_chunk, max_chunk].
std::size_t guided_chunk_size(std::size_t remaining, std::size_t computing_ranks,
                              const ScheduleOptions& options);

}  // namespace rocksweep
