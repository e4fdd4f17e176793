// Dispatch capacity of the MPI scheduler's master: how many chunks per second rank 0 can hand
// out and collect when computing a chunk costs nothing. Rank 0 only dispatches here
// (master_computes_up_to = 0), every chunk has the same size, the sink does nothing.
//
//   mpirun --oversubscribe --allow-run-as-root -np 4 ./bench_dispatch [--chunks 20000] ...
//
// Prints, per repeat and best of all: chunks/s, wall time per chunk, and rank 0's CPU time per
// chunk (its real cost when it does not have a core to itself). See benchmarks/README.md.
#include "rocksweep/parallel/mpi_session.hpp"
#include "rocksweep/parallel/scheduler.hpp"

#include <CLI/CLI.hpp>

#include <time.h>

#include <algorithm>
#include <cstdio>
#include <exception>

namespace {

double thread_cpu_seconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

struct Options {
    std::size_t chunks = 20000;
    std::size_t chunk_cells = 256;
    std::size_t record_bytes = 48;
    std::size_t chunks_per_worker = 2;
    int repeats = 3;
};

struct Measurement {
    double wall_s = 0.0;
    double master_cpu_s = 0.0;
    std::size_t chunks = 0;
};

Measurement measure_once(rocksweep::Scheduler& scheduler, const Options& options, MPI_Comm comm) {
    rocksweep::ScheduleOptions schedule;
    schedule.record_bytes = options.record_bytes;
    schedule.max_chunk = options.chunk_cells;
    schedule.min_chunk = options.chunk_cells;
    schedule.chunks_per_worker = options.chunks_per_worker;
    schedule.master_computes_up_to = 0;  // measure the dispatcher alone
    const std::vector<rocksweep::IndexRange> todo = {{0, options.chunks * options.chunk_cells}};
    volatile unsigned char seen = 0;

    MPI_Barrier(comm);
    const double cpu0 = thread_cpu_seconds();
    const auto stats = scheduler.run(
        todo, schedule, [](std::size_t, std::size_t, std::byte*) {},
        [&](std::size_t, std::size_t, const std::byte* records) {
            if (options.record_bytes > 0) seen = seen ^ static_cast<unsigned char>(records[0]);
        });
    Measurement m;
    m.master_cpu_s = thread_cpu_seconds() - cpu0;
    m.wall_s = stats.wall_s;
    m.chunks = stats.chunks;
    return m;
}

}  // namespace

int main(int argc, char** argv) {
    rocksweep::MpiSession session(argc, argv);
    rocksweep::RootStream out(session, std::cout);

    CLI::App app{"Chunks per second the MPI scheduler's master can hand out and collect."};
    Options options;
    app.add_option("--chunks", options.chunks, "chunks per repeat")->check(CLI::PositiveNumber)->capture_default_str();
    app.add_option("--chunk-cells", options.chunk_cells, "cells per chunk")->check(CLI::PositiveNumber)->capture_default_str();
    app.add_option("--record-bytes", options.record_bytes, "bytes per cell record")->capture_default_str();
    app.add_option("--chunks-per-worker", options.chunks_per_worker, "chunks kept at each worker")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    app.add_option("--repeats", options.repeats, "repeats; the best is reported")->check(CLI::PositiveNumber)->capture_default_str();
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return session.is_root() ? app.exit(e) : (e.get_exit_code() != 0 ? 2 : 0);
    }
    if (session.size() < 2) {
        out << "bench_dispatch needs at least 2 ranks (a master and a worker)\n";
        return 2;
    }

    try {
        auto scheduler = rocksweep::make_mpi_scheduler(session.comm());
        char line[256];
        std::snprintf(line, sizeof line, "# %d ranks (1 master + %d workers), %zu chunks of %zu cells x %zu bytes, %zu per worker\n",
                      session.size(), session.size() - 1, options.chunks, options.chunk_cells, options.record_bytes,
                      options.chunks_per_worker);
        out << line << "# repeat   chunks/s   wall us/chunk   master cpu us/chunk\n";
        Measurement best;
        for (int r = 0; r < options.repeats; ++r) {
            const Measurement m = measure_once(*scheduler, options, session.comm());
            const double rate = static_cast<double>(m.chunks) / m.wall_s;
            std::snprintf(line, sizeof line, "%8d %10.0f %15.2f %21.2f\n", r + 1, rate, 1e6 * m.wall_s / static_cast<double>(m.chunks),
                          1e6 * m.master_cpu_s / static_cast<double>(m.chunks));
            out << line;
            if (r == 0 || m.wall_s < best.wall_s) best = m;
        }
        const double rate = static_cast<double>(best.chunks) / best.wall_s;
        std::snprintf(line, sizeof line, "best: np=%d  %.0f chunks/s  %.2f us/chunk wall  %.2f us/chunk master cpu\n",
                      session.size(), rate, 1e6 * best.wall_s / static_cast<double>(best.chunks),
                      1e6 * best.master_cpu_s / static_cast<double>(best.chunks));
        out << line;
    } catch (const std::exception& e) {
        rocksweep::abort_on_error(session.rank(), e);
    }
    return 0;
}
