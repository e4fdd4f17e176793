#include "rocksweep/parallel/scheduler.hpp"

#include <algorithm>
#include <functional>
#include <memory>

#include "schedule_parts.hpp"

namespace rocksweep {

namespace {

using namespace schedule_parts;

class SerialScheduler final : public Scheduler {
public:
    ScheduleStats run(const std::vector<IndexRange>& todo, const ScheduleOptions& options,
                      const ComputeFn& compute, const SinkFn& sink) override {
        stop_requested_ = options.stop_requested;
        return run_serial(todo, options, compute, sink, stopping_);
    }
    int rank() const override { return 0; }
    int size() const override { return 1; }
    bool stop_pending() override { return stopping_ || (stop_requested_ && stop_requested_()); }

private:
    bool stopping_ = false;
    std::function<bool()> stop_requested_;
};

}  // namespace

std::size_t guided_chunk_size(std::size_t remaining, std::size_t computing_ranks, const ScheduleOptions& options) {
    const std::size_t divisor = std::max<std::size_t>(1, options.guided_divisor) * std::max<std::size_t>(1, computing_ranks);
    const std::size_t guided = remaining / divisor + (remaining % divisor != 0 ? 1 : 0);
    return std::clamp(guided, min_chunk_of(options), std::max(options.max_chunk, min_chunk_of(options)));
}

std::unique_ptr<Scheduler> make_serial_scheduler() { return std::make_unique<SerialScheduler>(); }

}  // namespace rocksweep
