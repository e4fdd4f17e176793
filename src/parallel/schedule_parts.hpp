#pragma once
// What the serial and the MPI scheduler share: option checks, the chunk source, the tick clock
// and the one-process loop (an MPI scheduler on one rank runs it too). Internal to src/.
#include <algorithm>
#include <chrono>
#include <climits>
#include <cmath>
#include <cstdint>
#include <deque>
#include <stdexcept>
#include <string>
#include <vector>

#include "rocksweep/parallel/scheduler.hpp"

namespace rocksweep::schedule_parts {

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

inline std::size_t min_chunk_of(const ScheduleOptions& options) { return std::max<std::size_t>(1, options.min_chunk); }

/// Every rank runs this on the same arguments, so every rank throws the same error before any
/// message is sent: nobody is left waiting.
inline void validate(const ScheduleOptions& options) {
    if (options.max_chunk == 0) throw std::invalid_argument("ScheduleOptions: max_chunk must be at least 1");
    if (options.min_chunk > options.max_chunk)
        throw std::invalid_argument("ScheduleOptions: min_chunk (" + std::to_string(options.min_chunk) +
                                    ") exceeds max_chunk (" + std::to_string(options.max_chunk) + ")");
    if (options.guided_divisor == 0) throw std::invalid_argument("ScheduleOptions: guided_divisor must be at least 1");
    if (options.chunks_per_worker == 0)
        throw std::invalid_argument("ScheduleOptions: chunks_per_worker must be at least 1");
    if (!(options.tick_interval_s >= 0.0) || !std::isfinite(options.tick_interval_s))
        throw std::invalid_argument("ScheduleOptions: tick_interval_s must be finite and >= 0");
    if (options.record_bytes != 0 && options.max_chunk > SIZE_MAX / options.record_bytes)
        throw std::invalid_argument("ScheduleOptions: max_chunk * record_bytes overflows");
}

inline void validate(const std::vector<IndexRange>& todo) {
    for (const IndexRange& r : todo)
        if (r.first + r.count < r.first) throw std::invalid_argument("todo range overflows the index type");
}

/// Walks the todo ranges front to back, cutting chunks of the size asked for; a chunk never
/// crosses from one range into the next.
class ChunkSource {
public:
    explicit ChunkSource(const std::vector<IndexRange>& todo) {
        for (const IndexRange& r : todo) {
            if (r.count == 0) continue;
            ranges_.push_back(r);
            remaining_ += r.count;
        }
        total_ = remaining_;
    }
    bool empty() const { return remaining_ == 0; }
    std::size_t remaining() const { return remaining_; }
    std::size_t total() const { return total_; }

    /// Precondition: !empty() and want >= 1.
    IndexRange take(std::size_t want) {
        const IndexRange& r = ranges_[pos_];
        const std::size_t n = std::min(want, r.count - offset_);
        const IndexRange chunk{r.first + offset_, n};
        offset_ += n;
        remaining_ -= n;
        if (offset_ == r.count) {
            ++pos_;
            offset_ = 0;
        }
        return chunk;
    }

private:
    std::vector<IndexRange> ranges_;
    std::size_t pos_ = 0, offset_ = 0, remaining_ = 0, total_ = 0;
};

/// Calls on_tick when tick_interval_s has passed since the last call (or the start).
class Ticker {
public:
    explicit Ticker(const ScheduleOptions& options)
        : on_tick_(options.on_tick),
          interval_(std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(options.tick_interval_s))),
          last_(Clock::now()) {}
    void poll(Clock::time_point now) {
        if (on_tick_ && now - last_ >= interval_) {
            on_tick_();
            last_ = Clock::now();
        }
    }

private:
    const std::function<void()>& on_tick_;
    Clock::duration interval_;
    Clock::time_point last_;
};

inline ScheduleStats run_serial(const std::vector<IndexRange>& todo, const ScheduleOptions& options,
                         const ComputeFn& compute, const SinkFn& sink, bool& stopping) {
    stopping = false;
    const auto start = Clock::now();
    validate(options);
    validate(todo);
    ChunkSource source(todo);
    std::vector<std::byte> records(options.max_chunk * options.record_bytes);
    ScheduleStats stats;
    stats.cells_per_rank.assign(1, 0);
    stats.chunks_per_rank.assign(1, 0);
    Ticker ticker(options);

    while (!source.empty()) {
        if (options.stop_requested && options.stop_requested()) {
            stopping = true;
            break;
        }
        const IndexRange chunk = source.take(options.max_chunk);
        try {
            compute(chunk.first, chunk.count, records.data());
        } catch (const ChunkAbandoned&) {
            stopping = true;
            break;
        }
        sink(chunk.first, chunk.count, records.data());
        ++stats.chunks;
        stats.cells_done += chunk.count;
        ticker.poll(Clock::now());
    }
    stats.stopped = stopping;
    stats.complete = stats.cells_done == source.total();
    stats.cells_per_rank[0] = stats.cells_done;
    stats.chunks_per_rank[0] = stats.chunks;
    stats.wall_s = seconds_since(start);
    return stats;
}

}  // namespace rocksweep::schedule_parts
