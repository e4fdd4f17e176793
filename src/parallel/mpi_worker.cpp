// A worker's end of the MPI scheduler's protocol (mpi_protocol.hpp): compute the chunks the
// master sends, return their records without waiting, give chunks up once a stop is pending.
// Apart from the master's end because the two share only the protocol.
#include <array>
#include <cstdint>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "mpi_protocol.hpp"
#include "schedule_parts.hpp"

namespace rocksweep::mpi_protocol {

using namespace schedule_parts;

ScheduleStats run_worker(MPI_Comm comm, int rank, int size, const ScheduleOptions& options,
                         const ComputeFn& compute, bool& stopping) {
    const auto start = Clock::now();
    const std::size_t me = static_cast<std::size_t>(rank);
    ScheduleStats stats;
    stats.cells_per_rank.assign(static_cast<std::size_t>(size), 0);
    stats.chunks_per_rank.assign(static_cast<std::size_t>(size), 0);

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
        mpi_check(MPI_Recv(message.data(), 4, MPI_UINT64_T, 0, MPI_ANY_TAG, comm, &status), "MPI_Recv");
        if (status.MPI_TAG == tag_stop) {
            stats.complete = message[0] != 0;
            stats.stopped = message[1] != 0;
            stats.chunks = message[2];
            stats.cells_done = message[3];
            break;
        }
        if (status.MPI_TAG == tag_halt) {
            stopping = true;
            continue;
        }
        if (status.MPI_TAG != tag_work) throw std::logic_error("unexpected message tag " + std::to_string(status.MPI_TAG));
        const std::size_t first = message[0], count = message[1];
        if (count == 0 || count > options.max_chunk)
            throw std::logic_error("chunk of " + std::to_string(count) + " cells received");
        const std::uint64_t header[2] = {first, count};
        auto abandon = [&] {
            // Tiny and matched by the master's next probe: a blocking send costs nothing here.
            mpi_check(MPI_Send(header, 2, MPI_UINT64_T, 0, tag_abandoned, comm), "MPI_Send");
        };
        if (halt_pending(comm, stopping)) {
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
        mpi_check(MPI_Isend(slot.buffer.data(), static_cast<int>(slot.buffer.size()), MPI_BYTE, 0, tag_result, comm,
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

}  // namespace rocksweep::mpi_protocol
