// The MPI scheduler: rank 0 hands out guided chunks and gathers the records; see scheduler.hpp.
#include "rocksweep/parallel/scheduler.hpp"

#include "rocksweep/parallel/mpi_session.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <deque>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>

#include "schedule_parts.hpp"

namespace rocksweep {

namespace {

using namespace schedule_parts;

// ---------------------------------------------------------------------------------------------
// MPI: master/worker with dynamic, guided chunks.
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

void mpi_check(int rc, const char* call) {
    if (rc == MPI_SUCCESS) return;
    char text[MPI_MAX_ERROR_STRING];
    int length = 0;
    MPI_Error_string(rc, text, &length);
    throw std::runtime_error(std::string(call) + " failed: " + std::string(text, static_cast<std::size_t>(length)));
}

/// Sleeps a little when the master has had nothing to do for a while, so that on an
/// oversubscribed node it does not take the CPU from the workers. The first 100 µs of idleness
/// only yield, so a busy master answers at once; after that replies come at most ~100 µs late,
/// which the chunk held in reserve at each worker hides.
class Backoff {
public:
    void reset() { idle_ = false; }
    void idle() {
        const auto now = Clock::now();
        if (!idle_) {
            idle_ = true;
            idle_since_ = now;
        }
        if (now - idle_since_ < std::chrono::microseconds(100))
            std::this_thread::yield();
        else
            std::this_thread::sleep_for(std::chrono::microseconds(50));
    }

private:
    bool idle_ = false;
    Clock::time_point idle_since_{};
};

/// Small non-blocking sends whose buffers must live until they complete.
class SmallSends {
public:
    explicit SmallSends(MPI_Comm comm) : comm_(comm) {}
    void send(int dest, int tag, const std::array<std::uint64_t, 4>& data, int n) {
        if (live_.size() >= reap_at_) reap();
        auto message = std::make_unique<Message>();
        message->data = data;
        mpi_check(MPI_Isend(message->data.data(), n, MPI_UINT64_T, dest, tag, comm_, &message->request), "MPI_Isend");
        live_.push_back(std::move(message));
    }
    void wait_all() {
        for (auto& message : live_) mpi_check(MPI_Wait(&message->request, MPI_STATUS_IGNORE), "MPI_Wait");
        live_.clear();
    }

private:
    struct Message {
        std::array<std::uint64_t, 4> data{};
        MPI_Request request = MPI_REQUEST_NULL;
    };
    void reap() {
        std::erase_if(live_, [](std::unique_ptr<Message>& message) {
            int done = 0;
            mpi_check(MPI_Test(&message->request, &done, MPI_STATUS_IGNORE), "MPI_Test");
            return done != 0;
        });
        reap_at_ = std::max<std::size_t>(64, 2 * live_.size());
    }

    MPI_Comm comm_;
    std::vector<std::unique_ptr<Message>> live_;
    std::size_t reap_at_ = 64;
};

class MpiScheduler final : public Scheduler {
public:
    explicit MpiScheduler(MPI_Comm comm) {
        int initialized = 0, finalized = 0;
        MPI_Initialized(&initialized);
        MPI_Finalized(&finalized);
        if (!initialized || finalized) throw std::logic_error("make_mpi_scheduler: MPI is not active");
        mpi_check(MPI_Comm_dup(comm, &comm_), "MPI_Comm_dup");
        MPI_Comm_rank(comm_, &rank_);
        MPI_Comm_size(comm_, &size_);
    }
    ~MpiScheduler() override {
        int finalized = 0;
        MPI_Finalized(&finalized);
        if (!finalized) MPI_Comm_free(&comm_);
    }
    MpiScheduler(const MpiScheduler&) = delete;
    MpiScheduler& operator=(const MpiScheduler&) = delete;

    int rank() const override { return rank_; }
    int size() const override { return size_; }
    bool stop_pending() override {
        if (stopping_) return true;
        // Rank 0 asks the request itself: its own chunk may be the slow one. The scheduler
        // loop notices the same answer as soon as that chunk is given up.
        if (rank_ == 0) return stop_requested_ && stop_requested_();
        int found = 0;
        mpi_check(MPI_Iprobe(0, tag_halt, comm_, &found, MPI_STATUS_IGNORE), "MPI_Iprobe");
        stopping_ = found != 0;
        return stopping_;
    }

    ScheduleStats run(const std::vector<IndexRange>& todo, const ScheduleOptions& options,
                      const ComputeFn& compute, const SinkFn& sink) override {
        stopping_ = false;
        stop_requested_ = options.stop_requested;
        if (size_ == 1) return run_serial(todo, options, compute, sink, stopping_);
        validate(options);
        if (header_bytes + options.max_chunk * options.record_bytes > static_cast<std::size_t>(INT_MAX))
            throw std::invalid_argument("ScheduleOptions: max_chunk * record_bytes exceeds one MPI message (2 GiB)");
        // From here on an exception on one rank would leave the others waiting: abort instead.
        try {
            return rank_ == 0 ? run_master(todo, options, compute, sink) : run_worker(options, compute);
        } catch (const std::exception& error) {
            abort_on_error(rank_, error, comm_);
        } catch (...) {
            abort_on_error(rank_, "unknown exception", comm_);
        }
    }

private:
    ScheduleStats run_master(const std::vector<IndexRange>& todo, const ScheduleOptions& options,
                             const ComputeFn& compute, const SinkFn& sink);
    ScheduleStats run_worker(const ScheduleOptions& options, const ComputeFn& compute);

    MPI_Comm comm_ = MPI_COMM_NULL;
    int rank_ = 0;
    int size_ = 1;
    bool stopping_ = false;
    std::function<bool()> stop_requested_;
};

ScheduleStats MpiScheduler::run_master(const std::vector<IndexRange>& todo, const ScheduleOptions& options,
                                       const ComputeFn& compute, const SinkFn& sink) {
    const auto start = Clock::now();
    validate(todo);
    const std::size_t n_ranks = static_cast<std::size_t>(size_);
    const bool master_computes = size_ <= options.master_computes_up_to;
    const std::size_t computing_ranks = n_ranks - 1 + (master_computes ? 1 : 0);
    const std::size_t record_bytes = options.record_bytes;

    ScheduleStats stats;
    stats.cells_per_rank.assign(n_ranks, 0);
    stats.chunks_per_rank.assign(n_ranks, 0);
    ChunkSource source(todo);
    SmallSends small_sends(comm_);
    Ticker ticker(options);
    Backoff backoff;
    bool& stopping = stopping_;
    auto begin_stop = [&] {
        if (stopping) return;
        stopping = true;
        stats.stopped = true;
        for (int worker = 1; worker < size_; ++worker) small_sends.send(worker, tag_halt, {}, 1);
    };

    // Chunks handed to each worker whose result has not been seen yet, oldest first.
    std::vector<std::deque<IndexRange>> assigned(n_ranks);
    // Results being received: requests and what they carry, index for index.
    struct Incoming {
        int source;
        IndexRange chunk;
        std::vector<std::byte> buffer;
    };
    std::vector<MPI_Request> requests;
    std::vector<Incoming> incoming;
    std::vector<int> done_indices;
    std::vector<std::vector<std::byte>> spare_buffers;
    std::vector<std::byte> own_records;
    std::size_t outstanding = 0;  // handed out to workers, not yet sunk

    auto hand_out = [&](int worker) {
        if (stopping || source.empty()) return;
        const IndexRange chunk = source.take(guided_chunk_size(source.remaining(), computing_ranks, options));
        small_sends.send(worker, tag_work, {chunk.first, chunk.count, 0, 0}, 2);
        assigned[static_cast<std::size_t>(worker)].push_back(chunk);
        ++outstanding;
        ++stats.chunks;
    };

    // Prime: a chunk for every worker first, then the reserve ones.
    for (std::size_t round = 0; round < options.chunks_per_worker; ++round)
        for (int worker = 1; worker < size_; ++worker) hand_out(worker);

    auto last_stop_poll = Clock::now();
    for (;;) {
        bool progressed = false;

        // 1. Results that have started to arrive: post their receive, refill the worker.
        for (;;) {
            int found = 0;
            MPI_Message message;
            MPI_Status status;
            mpi_check(MPI_Improbe(MPI_ANY_SOURCE, MPI_ANY_TAG, comm_, &found, &message, &status), "MPI_Improbe");
            if (!found) break;
            progressed = true;
            const int worker = status.MPI_SOURCE;
            auto& queue = assigned[static_cast<std::size_t>(worker)];
            if (queue.empty()) throw std::logic_error("result from rank " + std::to_string(worker) + " which has no chunk");
            const IndexRange chunk = queue.front();
            queue.pop_front();
            if (status.MPI_TAG == tag_abandoned) {
                std::uint64_t header[2] = {0, 0};
                mpi_check(MPI_Mrecv(header, 2, MPI_UINT64_T, &message, MPI_STATUS_IGNORE), "MPI_Mrecv");
                if (header[0] != chunk.first || header[1] != chunk.count)
                    throw std::logic_error("rank " + std::to_string(worker) + " abandoned chunk " + std::to_string(header[0]) +
                                           "+" + std::to_string(header[1]) + ", expected " + std::to_string(chunk.first) +
                                           "+" + std::to_string(chunk.count));
                --outstanding;
                begin_stop();
                continue;
            }
            if (status.MPI_TAG != tag_result)
                throw std::logic_error("unexpected message tag " + std::to_string(status.MPI_TAG) + " from rank " +
                                       std::to_string(worker));
            int bytes = 0;
            mpi_check(MPI_Get_count(&status, MPI_BYTE, &bytes), "MPI_Get_count");
            if (static_cast<std::size_t>(bytes) != header_bytes + chunk.count * record_bytes)
                throw std::logic_error("result of " + std::to_string(bytes) + " bytes from rank " +
                                       std::to_string(worker) + " for a chunk of " + std::to_string(chunk.count) +
                                       " records");
            std::vector<std::byte> buffer;
            if (!spare_buffers.empty()) {
                buffer = std::move(spare_buffers.back());
                spare_buffers.pop_back();
            }
            buffer.resize(static_cast<std::size_t>(bytes));
            MPI_Request request;
            mpi_check(MPI_Imrecv(buffer.data(), bytes, MPI_BYTE, &message, &request), "MPI_Imrecv");
            requests.push_back(request);
            incoming.push_back(Incoming{worker, chunk, std::move(buffer)});  // moving keeps data() in place
            hand_out(worker);
        }

        // 2. Results fully arrived: sink them.
        if (!requests.empty()) {
            done_indices.resize(requests.size());
            int n_done = 0;
            mpi_check(MPI_Testsome(static_cast<int>(requests.size()), requests.data(), &n_done, done_indices.data(),
                                   MPI_STATUSES_IGNORE),
                      "MPI_Testsome");
            if (n_done != MPI_UNDEFINED && n_done > 0) {
                progressed = true;
                for (int i = 0; i < n_done; ++i) {
                    Incoming& in = incoming[static_cast<std::size_t>(done_indices[static_cast<std::size_t>(i)])];
                    std::uint64_t header[2];
                    std::memcpy(header, in.buffer.data(), header_bytes);
                    if (header[0] != in.chunk.first || header[1] != in.chunk.count)
                        throw std::logic_error("rank " + std::to_string(in.source) + " returned chunk " +
                                               std::to_string(header[0]) + "+" + std::to_string(header[1]) +
                                               ", expected " + std::to_string(in.chunk.first) + "+" +
                                               std::to_string(in.chunk.count));
                    sink(in.chunk.first, in.chunk.count, in.buffer.data() + header_bytes);
                    stats.cells_done += in.chunk.count;
                    stats.cells_per_rank[static_cast<std::size_t>(in.source)] += in.chunk.count;
                    ++stats.chunks_per_rank[static_cast<std::size_t>(in.source)];
                    --outstanding;
                    spare_buffers.push_back(std::move(in.buffer));
                }
                // Drop the finished entries (their requests are now MPI_REQUEST_NULL), keeping order.
                std::size_t kept = 0;
                for (std::size_t i = 0; i < requests.size(); ++i) {
                    if (requests[i] == MPI_REQUEST_NULL) continue;
                    requests[kept] = requests[i];
                    if (kept != i) incoming[kept] = std::move(incoming[i]);
                    ++kept;
                }
                requests.resize(kept);
                incoming.resize(kept);
            }
        }

        // 3. Clock-driven duties.
        const auto now = Clock::now();
        ticker.poll(now);
        if (!stopping && options.stop_requested &&
            ((master_computes && !source.empty()) || now - last_stop_poll >= std::chrono::milliseconds(10))) {
            last_stop_poll = now;
            if (options.stop_requested()) begin_stop();
        }

        // 4. Finished?
        if ((stopping || source.empty()) && outstanding == 0) break;

        // 5. Rank 0's own share, in half-size pieces.
        if (master_computes && !stopping && !source.empty()) {
            const std::size_t piece = std::max(min_chunk_of(options),
                                               guided_chunk_size(source.remaining(), computing_ranks, options) / 2);
            const IndexRange chunk = source.take(piece);
            ++stats.chunks;
            own_records.resize(chunk.count * record_bytes);
            try {
                compute(chunk.first, chunk.count, own_records.data());
            } catch (const ChunkAbandoned&) {
                begin_stop();
                continue;
            }
            sink(chunk.first, chunk.count, own_records.data());
            stats.cells_done += chunk.count;
            stats.cells_per_rank[0] += chunk.count;
            ++stats.chunks_per_rank[0];
            backoff.reset();
            continue;
        }

        if (progressed)
            backoff.reset();
        else
            backoff.idle();
    }

    stats.complete = stats.cells_done == source.total();
    const std::array<std::uint64_t, 4> verdict{stats.complete ? 1u : 0u, stats.stopped ? 1u : 0u, stats.chunks,
                                               stats.cells_done};
    for (int worker = 1; worker < size_; ++worker) small_sends.send(worker, tag_stop, verdict, 4);
    small_sends.wait_all();
    stats.wall_s = seconds_since(start);
    return stats;
}

ScheduleStats MpiScheduler::run_worker(const ScheduleOptions& options, const ComputeFn& compute) {
    const auto start = Clock::now();
    const std::size_t me = static_cast<std::size_t>(rank_);
    ScheduleStats stats;
    stats.cells_per_rank.assign(static_cast<std::size_t>(size_), 0);
    stats.chunks_per_rank.assign(static_cast<std::size_t>(size_), 0);

    // Result buffers in flight; one is reused as soon as its send has completed.
    struct Outgoing {
        std::vector<std::byte> buffer;
        MPI_Request request = MPI_REQUEST_NULL;
    };
    std::vector<std::unique_ptr<Outgoing>> outgoing;
    auto free_slot = [&]() -> Outgoing& {
        for (auto& slot : outgoing) {
            if (slot->request == MPI_REQUEST_NULL) return *slot;
            int done = 0;
            mpi_check(MPI_Test(&slot->request, &done, MPI_STATUS_IGNORE), "MPI_Test");
            if (done) return *slot;
        }
        return *outgoing.emplace_back(std::make_unique<Outgoing>());
    };

    for (;;) {
        std::array<std::uint64_t, 4> message{};
        MPI_Status status;
        mpi_check(MPI_Recv(message.data(), 4, MPI_UINT64_T, 0, MPI_ANY_TAG, comm_, &status), "MPI_Recv");
        if (status.MPI_TAG == tag_stop) {
            stats.complete = message[0] != 0;
            stats.stopped = message[1] != 0;
            stats.chunks = message[2];
            stats.cells_done = message[3];
            break;
        }
        if (status.MPI_TAG == tag_halt) {
            stopping_ = true;
            continue;
        }
        if (status.MPI_TAG != tag_work) throw std::logic_error("unexpected message tag " + std::to_string(status.MPI_TAG));
        const std::size_t first = message[0], count = message[1];
        if (count == 0 || count > options.max_chunk)
            throw std::logic_error("chunk of " + std::to_string(count) + " cells received");
        const std::uint64_t header[2] = {first, count};
        auto abandon = [&] {
            // Tiny and matched by the master's next probe: a blocking send costs nothing here.
            mpi_check(MPI_Send(header, 2, MPI_UINT64_T, 0, tag_abandoned, comm_), "MPI_Send");
        };
        if (stop_pending()) {
            abandon();
            continue;
        }
        Outgoing& slot = free_slot();
        slot.buffer.resize(header_bytes + count * options.record_bytes);
        std::memcpy(slot.buffer.data(), header, header_bytes);
        try {
            compute(first, count, slot.buffer.data() + header_bytes);
        } catch (const ChunkAbandoned&) {
            abandon();
            continue;
        }
        mpi_check(MPI_Isend(slot.buffer.data(), static_cast<int>(slot.buffer.size()), MPI_BYTE, 0, tag_result, comm_,
                            &slot.request),
                  "MPI_Isend");
        stats.cells_per_rank[me] += count;
        ++stats.chunks_per_rank[me];
    }
    // The master has received every result before it sends stop: these complete at once.
    for (auto& slot : outgoing) mpi_check(MPI_Wait(&slot->request, MPI_STATUS_IGNORE), "MPI_Wait");
    stats.wall_s = seconds_since(start);
    return stats;
}

}  // namespace

std::unique_ptr<Scheduler> make_mpi_scheduler(MPI_Comm comm) { return std::make_unique<MpiScheduler>(comm); }

}  // namespace rocksweep
