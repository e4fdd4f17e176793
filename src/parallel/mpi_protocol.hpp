#pragma once
// The MPI scheduler's master/worker protocol: message tags and layouts, the rules of termination
// and stopping, and the two ends that speak it (mpi_master.cpp, mpi_worker.cpp). Apart from the
// Scheduler object (mpi_scheduler.cpp), which only picks the end a rank runs. Internal to src/.
#include <mpi.h>

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "rocksweep/parallel/scheduler.hpp"

namespace rocksweep::mpi_protocol {

// ---------------------------------------------------------------------------------------------
// Master/worker with dynamic, guided chunks.
//
// Messages (on a private duplicate of the caller's communicator, so tags cannot collide):
//   master -> worker  tag_work    2 x uint64 {first, count}
//   master -> worker  tag_stop    4 x uint64 {complete, stopped, chunks, cells_done}
//   master -> worker  tag_halt    1 x uint64: a stop was requested, give up the chunks you hold
//   worker -> master  tag_result  bytes: {first, count} as 2 x uint64, then count * record_bytes
//   worker -> master  tag_abandoned  2 x uint64 {first, count}: that chunk was given up, not done
//
// The master keeps chunks_per_worker chunks at every worker (one in hand, the others in its
// mailbox). It refills a worker as soon as it *sees* a result from it (matched probe), before
// the data has arrived, so the refill never waits for a large transfer. A worker only sends
// results and receives work; it never waits for anything but its next chunk, which is normally
// already there. MPI message order between one pair of ranks is preserved, so the results of a
// worker arrive in the order its chunks were handed out.
//
// Termination: when nothing is left to hand out (or a stop was requested) and every chunk handed
// out has been received and sunk or reported abandoned, the master sends tag_stop to each
// worker. A worker leaves on tag_stop; by then all its result sends have been matched, so
// nothing is left unmatched at MPI_Finalize.
//
// Stopping: once stop_requested returns true (or a chunk comes back abandoned) the master sends
// tag_halt to every worker, once, before its tag_stop. A worker's ComputeFn sees it through
// stop_pending() (a probe) and gives its chunk up; chunks still in its mailbox are reported
// abandoned without computing. Both kinds of worker message are matched by one probe on any tag,
// so they are taken in the order the worker sent them, which is the order of `assigned`.
//
// Rule for the master computing: with few ranks a dedicated master wastes a large share of the
// machine (half of it on 2 ranks), so when size() <= master_computes_up_to (default 8; above it
// a dedicated master costs less than 1/8 of the machine) rank 0 computes too. It computes
// half-size chunks between polls: a worker holds at least one chunk of at least the current
// guided size in reserve, so while rank 0 is away for half a chunk no worker runs dry (measured:
// 99.7 % of the ideal speed-up on 2 ranks with 5 ms chunks). Above the threshold the gain
// (1/size) is small and the master's promptness is worth more.
// ---------------------------------------------------------------------------------------------

enum Tag : int { tag_work = 101, tag_stop = 102, tag_result = 103, tag_halt = 104, tag_abandoned = 105 };
constexpr std::size_t header_bytes = 2 * sizeof(std::uint64_t);

inline void mpi_check(int rc, const char* call) {
    if (rc == MPI_SUCCESS) return;
    char text[MPI_MAX_ERROR_STRING];
    int length = 0;
    MPI_Error_string(rc, text, &length);
    throw std::runtime_error(std::string(call) + " failed: " + std::string(text, static_cast<std::size_t>(length)));
}

/// A worker's answer to stop_pending(): true once `stopping` is set or the master's tag_halt is
/// waiting (which sets it).
inline bool halt_pending(MPI_Comm comm, bool& stopping) {
    if (stopping) return true;
    int found = 0;
    mpi_check(MPI_Iprobe(0, tag_halt, comm, &found, MPI_STATUS_IGNORE), "MPI_Iprobe");
    stopping = found != 0;
    return stopping;
}

/// Rank 0's end: hands out `todo` to ranks 1..size-1 (and computes too when size <=
/// options.master_computes_up_to), sinks every result, then sends tag_stop. Sets `stopping` when
/// a stop begins. Options are validated by the caller.
ScheduleStats run_master(MPI_Comm comm, int size, const std::vector<IndexRange>& todo,
                         const ScheduleOptions& options, const ComputeFn& compute, const SinkFn& sink,
                         bool& stopping);

/// A worker's end (rank > 0): computes the chunks it is sent until tag_stop. Sets `stopping` on
/// tag_halt, which the caller's stop_pending() reports.
ScheduleStats run_worker(MPI_Comm comm, int rank, int size, const ScheduleOptions& options,
                         const ComputeFn& compute, bool& stopping);

}  // namespace rocksweep::mpi_protocol
