// The MPI scheduler: rank 0 hands out guided chunks and gathers the records; see scheduler.hpp.
// This file is the Scheduler object (communicator, rank, the stop request, errors turned into an
// abort); the protocol and its two ends are mpi_protocol.hpp, mpi_master.cpp, mpi_worker.cpp.
#include "rocksweep/parallel/scheduler.hpp"

#include "rocksweep/parallel/mpi_session.hpp"

#include <climits>
#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>
#include <vector>

#include "mpi_protocol.hpp"
#include "schedule_parts.hpp"

namespace rocksweep {

namespace {

using namespace schedule_parts;
using namespace mpi_protocol;

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
        return halt_pending(comm_, stopping_);
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
            return rank_ == 0 ? run_master(comm_, size_, todo, options, compute, sink, stopping_)
                              : run_worker(comm_, rank_, size_, options, compute, stopping_);
        } catch (const std::exception& error) {
            abort_on_error(rank_, error, comm_);
        } catch (...) {
            abort_on_error(rank_, "unknown exception", comm_);
        }
    }

private:
    MPI_Comm comm_ = MPI_COMM_NULL;
    int rank_ = 0;
    int size_ = 1;
    bool stopping_ = false;
    std::function<bool()> stop_requested_;
};

}  // namespace

std::unique_ptr<Scheduler> make_mpi_scheduler(MPI_Comm comm) { return std::make_unique<MpiScheduler>(comm); }

std::unique_ptr<Scheduler> make_scheduler(const MpiSession& session) {
    return session.uses_mpi() ? make_mpi_scheduler(session.comm()) : make_serial_scheduler();
}

}  // namespace rocksweep
