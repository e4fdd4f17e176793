#pragma once
/// MPI start-up and shut-down as an object, the one stream that prints once per job, and the
/// "ERROR on rank N" abort used when a failure is local to one rank.
#include <mpi.h>

#include <exception>
#include <iostream>
#include <ostream>
#include <streambuf>
#include <string_view>
#include <vector>

namespace rocksweep {

/// Initialises MPI on construction and finalises it on destruction (RAII, one per program,
/// made first thing in `main`), but only in a process started by a launcher (mpirun, srun,
/// mpiexec: see launched_by_mpi_launcher). A process started on its own is rank 0 of 1 and
/// never touches MPI: Open MPI's singleton start-up (its orted helper) costs ~0.3 s, which
/// every `--help` would pay. Asks for MPI_THREAD_FUNNELED; only the main thread ever calls MPI.
///
/// If MPI was already initialised by someone else the session neither initialises nor
/// finalises it. Throws std::runtime_error if MPI_Init_thread reports failure.
///
/// Destruction finalises MPI, which is collective: a rank that leaves `main` through an
/// exception while the others wait for it must call abort_on_error instead.
class MpiSession {
public:
    MpiSession(int& argc, char**& argv);
    ~MpiSession();
    MpiSession(const MpiSession&) = delete;
    MpiSession& operator=(const MpiSession&) = delete;

    int rank() const noexcept { return rank_; }
    int size() const noexcept { return size_; }
    bool is_root() const noexcept { return rank_ == 0; }
    /// The thread support level MPI granted (MPI_THREAD_SINGLE ... MPI_THREAD_MULTIPLE).
    int thread_level() const noexcept { return thread_level_; }
    /// True when MPI is initialised (by this session or before it); false in a process that
    /// was started on its own, where no MPI function may be called.
    bool uses_mpi() const noexcept { return uses_mpi_; }
    /// MPI_COMM_WORLD; only meaningful when uses_mpi().
    MPI_Comm comm() const noexcept { return MPI_COMM_WORLD; }
    /// Rank 0's `value` on every rank (collective; nothing is sent on a job of one rank).
    void broadcast(int& value) const;
    /// Rank 0's `values` (its length too) on every rank.
    void broadcast(std::vector<double>& values) const;
    /// Every rank's `values` (any lengths), one after the other in rank order, on rank 0;
    /// empty elsewhere (collective; a job of one rank returns its own). At most 2^31 - 1 values
    /// in all: more aborts the job.
    std::vector<double> gather(const std::vector<double>& values) const;
    /// Seconds on a monotonic wall clock: differences between two calls on one rank are meaningful.
    static double wall_time() noexcept;
    /// Ends every rank of the job with exit status `code` (MPI_Abort on MPI_COMM_WORLD).
    [[noreturn]] void abort(int code) const noexcept;

private:
    int rank_ = 0;
    int size_ = 1;
    int thread_level_ = MPI_THREAD_SINGLE;
    bool owns_mpi_ = false;
    bool uses_mpi_ = false;
};

/// True when the environment says this process is one rank of a job started by a launcher:
/// Open MPI's mpirun (OMPI_COMM_WORLD_SIZE), a PMIx launcher such as srun --mpi=pmix or
/// prterun (PMIX_RANK), or a PMI-1/2 launcher such as MPICH's Hydra or srun --mpi=pmi2
/// (PMI_RANK, PMI_SIZE). A process started by hand has none of these.
bool launched_by_mpi_launcher() noexcept;

/// For an error local to one rank, which would leave the others blocked: prints
/// "ERROR on rank N: <what>" to stderr, flushes, and aborts the whole job with MPI_Abort(comm, 1).
/// Without an active MPI (not initialised, or already finalised) it prints and calls std::abort.
[[noreturn]] void abort_on_error(int rank, const std::exception& error,
                                 MPI_Comm comm = MPI_COMM_WORLD) noexcept;
[[noreturn]] void abort_on_error(int rank, std::string_view what, MPI_Comm comm = MPI_COMM_WORLD) noexcept;

/// An output stream that forwards to `target` (default std::cerr) when active and silently
/// discards everything otherwise: construct it active on rank 0 only, then print
/// `out << ...` without `if (rank == 0)` everywhere.
class RootStream : public std::ostream {
public:
    explicit RootStream(bool active, std::ostream& target = std::cerr);
    /// Active on the session's rank 0.
    explicit RootStream(const MpiSession& session, std::ostream& target = std::cerr)
        : RootStream(session.is_root(), target) {}
    RootStream(const RootStream&) = delete;
    RootStream& operator=(const RootStream&) = delete;

    bool is_active() const noexcept { return active_; }

private:
    /// Accepts and drops every character.
    class NullBuffer : public std::streambuf {
    protected:
        int_type overflow(int_type c) override { return traits_type::not_eof(c); }
        std::streamsize xsputn(const char*, std::streamsize n) override { return n; }
    };

    NullBuffer null_;
    bool active_;
};

}  // namespace rocksweep
