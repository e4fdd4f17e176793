#pragma once
/// Hands out index ranges of a work list and brings fixed-size result records back to rank 0.
/// Knows nothing of what a cell is.
#include <cstddef>
#include <functional>
#include <memory>
#include <vector>

namespace rocksweep {

struct IndexRange {
    std::size_t first = 0, count = 0;
};

/// Computes records [first, first + count) into `out` (count * record_bytes bytes).
using ComputeFn = std::function<void(std::size_t first, std::size_t count, std::byte* out)>;
/// Receives finished records on rank 0, in any order.
using SinkFn = std::function<void(std::size_t first, std::size_t count, const std::byte* records)>;

struct ScheduleOptions {
    std::size_t record_bytes = 0;
    std::size_t max_chunk = 256;  ///< largest chunk handed out; chunks shrink as work runs out
    std::size_t min_chunk = 8;
};

class Scheduler {
public:
    virtual ~Scheduler() = default;
    /// Runs every index of `todo`; `sink` sees each finished chunk on rank 0 only.
    virtual void run(const std::vector<IndexRange>& todo, const ScheduleOptions& options,
                     const ComputeFn& compute, const SinkFn& sink) = 0;
    virtual int rank() const = 0;
    virtual int size() const = 0;
};

/// One process, no messages.
std::unique_ptr<Scheduler> make_serial_scheduler();

}  // namespace rocksweep
