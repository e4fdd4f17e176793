// The master's end of the MPI scheduler's protocol (mpi_protocol.hpp): hand out guided chunks,
// keep every worker fed, receive and sink results, compute its own share, stop. Apart from the
// worker's end because the two share only the protocol, and this one is the whole of the
// scheduling policy.
#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <deque>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "mpi_protocol.hpp"
#include "schedule_parts.hpp"

namespace rocksweep::mpi_protocol {

using namespace schedule_parts;

namespace {

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

}  // namespace

ScheduleStats run_master(MPI_Comm comm, int size, const std::vector<IndexRange>& todo,
                         const ScheduleOptions& options, const ComputeFn& compute, const SinkFn& sink,
                         bool& stopping) {
    const auto start = Clock::now();
    validate(todo);
    const std::size_t n_ranks = static_cast<std::size_t>(size);
    const bool master_computes = size <= options.master_computes_up_to;
    const std::size_t computing_ranks = n_ranks - 1 + (master_computes ? 1 : 0);
    const std::size_t record_bytes = options.record_bytes;

    ScheduleStats stats;
    stats.cells_per_rank.assign(n_ranks, 0);
    stats.chunks_per_rank.assign(n_ranks, 0);
    ChunkSource source(todo);
    SmallSends small_sends(comm);
    Ticker ticker(options);
    Backoff backoff;
    auto begin_stop = [&] {
        if (stopping) return;
        stopping = true;
        stats.stopped = true;
        for (int worker = 1; worker < size; ++worker) small_sends.send(worker, tag_halt, {}, 1);
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
        for (int worker = 1; worker < size; ++worker) hand_out(worker);

    auto last_stop_poll = Clock::now();
    for (;;) {
        bool progressed = false;

        // 1. Results that have started to arrive: post their receive, refill the worker.
        for (;;) {
            int found = 0;
            MPI_Message message;
            MPI_Status status;
            mpi_check(MPI_Improbe(MPI_ANY_SOURCE, MPI_ANY_TAG, comm, &found, &message, &status), "MPI_Improbe");
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
    for (int worker = 1; worker < size; ++worker) small_sends.send(worker, tag_stop, verdict, 4);
    small_sends.wait_all();
    stats.wall_s = seconds_since(start);
    return stats;
}

}  // namespace rocksweep::mpi_protocol
