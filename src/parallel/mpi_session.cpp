#include "rocksweep/parallel/mpi_session.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <string>

namespace rocksweep {

namespace {

bool mpi_active() noexcept {
    int initialized = 0, finalized = 0;
    MPI_Initialized(&initialized);
    MPI_Finalized(&finalized);
    return initialized && !finalized;
}

}  // namespace

bool launched_by_mpi_launcher() noexcept {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"})
        if (std::getenv(name) != nullptr) return true;
    return false;
}

MpiSession::MpiSession(int& argc, char**& argv) {
    int initialized = 0;
    MPI_Initialized(&initialized);  // one of the few calls allowed before MPI_Init
    if (!initialized && !launched_by_mpi_launcher()) return;  // rank 0 of 1, without MPI
    uses_mpi_ = true;
    if (!initialized) {
        if (MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &thread_level_) != MPI_SUCCESS)
            throw std::runtime_error("MPI_Init_thread failed");
        owns_mpi_ = true;
    } else {
        MPI_Query_thread(&thread_level_);
    }
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiSession::~MpiSession() {
    if (!owns_mpi_) return;
    int finalized = 0;
    MPI_Finalized(&finalized);
    if (!finalized) MPI_Finalize();
}

void MpiSession::broadcast(int& value) const {
    if (size_ > 1) MPI_Bcast(&value, 1, MPI_INT, 0, comm());
}

void MpiSession::broadcast(std::vector<double>& values) const {
    if (size_ == 1) return;
    unsigned long long n = values.size();
    MPI_Bcast(&n, 1, MPI_UNSIGNED_LONG_LONG, 0, comm());
    values.resize(n);
    if (n > 0) MPI_Bcast(values.data(), static_cast<int>(n), MPI_DOUBLE, 0, comm());
}

std::vector<double> MpiSession::gather(const std::vector<double>& values) const {
    if (size_ == 1) return values;
    const int n = static_cast<int>(values.size());
    std::vector<int> counts(rank_ == 0 ? size_ : 0), offsets(counts.size());
    MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm());
    std::vector<double> all;
    if (rank_ == 0) {
        long long total = 0;
        for (int r = 0; r < size_; ++r) {
            offsets[r] = static_cast<int>(total);
            total += counts[r];
        }
        // The others already wait in the gather: a local failure must end the job.
        if (total > std::numeric_limits<int>::max()) abort_on_error(0, "MpiSession::gather: more than 2^31 values at once");
        all.resize(static_cast<std::size_t>(total));
    }
    MPI_Gatherv(values.data(), n, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE, 0, comm());
    return all;
}

double MpiSession::wall_time() noexcept {
    // Not MPI_Wtime: MPI may not be initialised, and only differences on one rank are used.
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

void MpiSession::abort(int code) const noexcept {
    std::fflush(stdout);
    std::fflush(stderr);
    if (mpi_active()) MPI_Abort(MPI_COMM_WORLD, code);
    std::abort();  // MPI_Abort does not return; this is only reached without MPI
}

void abort_on_error(int rank, const std::exception& error, MPI_Comm comm) noexcept {
    abort_on_error(rank, std::string_view(error.what()), comm);
}

void abort_on_error(int rank, std::string_view what, MPI_Comm comm) noexcept {
    // One fprintf so that the line is not interleaved with other ranks' output.
    std::fflush(stdout);
    std::fprintf(stderr, "ERROR on rank %d: %.*s\n", rank, static_cast<int>(what.size()), what.data());
    std::fflush(stderr);
    if (mpi_active()) MPI_Abort(comm, 1);
    std::abort();
}

RootStream::RootStream(bool active, std::ostream& target) : std::ostream(nullptr), active_(active) {
    rdbuf(active ? target.rdbuf() : &null_);  // also clears the badbit set by the null buffer above
    flags(target.flags());
}

}  // namespace rocksweep
