// The MPI scheduler under mpirun with N ranks. Every rank computes a record that depends only on
// its index; rank 0 checks that each index of the work list arrived exactly once with the right
// bytes, for several chunk settings, and that the results are bitwise the same for all of them.
// Exit status 0 when all is well, 1 otherwise (per rank; mpirun reports the worst).
//
//   --mode check         the default, above
//   --mode stop          a stop requested from on_tick part-way: run() must return on every rank,
//                        every chunk computed must reach the sink, and the result says "stopped"
//   --mode abandon       slow chunks (2 s each) that poll stop_pending(); a stop requested 0.2 s
//                        in must end run() on every rank within 1 s, with no abandoned chunk sunk
//   --mode throw-worker  compute throws on rank 1: the job must abort with "ERROR on rank 1"
//   --mode throw-master  compute throws on rank 0: the job must abort with "ERROR on rank 0"
#include "rocksweep/parallel/mpi_session.hpp"
#include "rocksweep/parallel/scheduler.hpp"

#include <CLI/CLI.hpp>

#include <cstdint>
#include <cstring>
#include <numeric>
#include <stdexcept>
#include <chrono>
#include <string>
#include <thread>
#include <vector>

namespace {

using namespace rocksweep;

std::uint64_t mix(std::uint64_t x) {
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
}

/// The record of cell `index`; `work` extra rounds of mixing make a cell cost something.
void fill_record(std::size_t index, std::byte* out, std::size_t bytes, int work) {
    std::uint64_t h = mix(index);
    for (int i = 0; i < work; ++i) h = mix(h);
    for (std::size_t b = 0; b < bytes; ++b) out[b] = static_cast<std::byte>(mix(index * 131 + b) & 0xFF);
    if (bytes >= 1 && work > 0 && h == 0) out[0] = std::byte{0};  // keeps h alive; same bytes either way
}

const std::vector<IndexRange> todo_with_holes = {{0, 1500}, {1600, 1}, {1700, 2000}, {5000, 0}, {6000, 777}};
constexpr std::size_t n_indices = 6777;

std::size_t total_of(const std::vector<IndexRange>& todo) {
    std::size_t n = 0;
    for (const IndexRange& r : todo) n += r.count;
    return n;
}

/// What rank 0 saw through the sink.
struct Collected {
    std::vector<int> times;
    std::vector<std::byte> records;
    std::size_t bad_records = 0;
};

struct Case {
    std::string name;
    ScheduleOptions options;
};

std::vector<Case> cases() {
    std::vector<Case> list;
    auto add = [&](std::string name, std::size_t max_chunk, std::size_t min_chunk, auto&& tweak) {
        Case c{std::move(name), {}};
        c.options.record_bytes = 37;
        c.options.max_chunk = max_chunk;
        c.options.min_chunk = min_chunk;
        tweak(c.options);
        list.push_back(std::move(c));
    };
    auto none = [](ScheduleOptions&) {};
    add("chunks of 1", 1, 1, none);
    add("chunks 3..7, dedicated master", 7, 3, [](ScheduleOptions& o) { o.master_computes_up_to = 0; });
    add("chunks 8..64", 64, 8, none);
    add("chunks 8..256", 256, 8, none);
    add("chunks of 1000", 1000, 1000, none);
    add("chunks 8..64, one per worker", 64, 8, [](ScheduleOptions& o) { o.chunks_per_worker = 1; });
    add("chunks 1..17, divisor 4, 3 per worker", 17, 1, [](ScheduleOptions& o) {
        o.guided_divisor = 4;
        o.chunks_per_worker = 3;
    });
    add("chunks 8..64, record of 0 bytes", 64, 8, [](ScheduleOptions& o) { o.record_bytes = 0; });
    return list;
}

int run_checks(const MpiSession& session, RootStream& out) {
    auto scheduler = make_mpi_scheduler(session.comm());
    const std::size_t total = total_of(todo_with_holes);
    std::vector<int> wanted(n_indices, 0);
    for (const IndexRange& r : todo_with_holes)
        for (std::size_t i = r.first; i < r.first + r.count; ++i) wanted[i] = 1;

    int failures = 0;
    std::vector<std::byte> reference;
    for (const Case& c : cases()) {
        const std::size_t rb = c.options.record_bytes;
        Collected got;
        got.times.assign(n_indices, 0);
        got.records.assign(n_indices * rb, std::byte{0});
        const ScheduleStats stats = scheduler->run(
            todo_with_holes, c.options,
            [&](std::size_t first, std::size_t count, std::byte* records) {
                if (count == 0 || count > c.options.max_chunk) throw std::logic_error("chunk size out of bounds");
                for (std::size_t i = 0; i < count; ++i) fill_record(first + i, records + i * rb, rb, 50);
            },
            [&](std::size_t first, std::size_t count, const std::byte* records) {
                std::vector<std::byte> expected(rb);
                for (std::size_t i = 0; i < count; ++i) {
                    ++got.times.at(first + i);
                    fill_record(first + i, expected.data(), rb, 0);
                    if (rb > 0 && std::memcmp(expected.data(), records + i * rb, rb) != 0) ++got.bad_records;
                    if (rb > 0) std::memcpy(got.records.data() + (first + i) * rb, records + i * rb, rb);
                }
            });

        auto fail = [&](const std::string& what) {
            ++failures;
            // Every rank may report; rank 0's reports go through `out`, others' straight to stderr.
            std::cerr << "FAIL [" << c.name << "] rank " << session.rank() << ": " << what << '\n';
        };
        if (!stats.complete) fail("not complete");
        if (stats.stopped) fail("reports a stop nobody asked for");
        if (stats.cells_done != total) fail("cells_done " + std::to_string(stats.cells_done));
        if (session.is_root()) {
            if (got.times != wanted) fail("some index was not sunk exactly once, or an index outside todo was");
            if (got.bad_records != 0) fail(std::to_string(got.bad_records) + " records arrived altered");
            const auto cells = std::accumulate(stats.cells_per_rank.begin(), stats.cells_per_rank.end(), std::size_t{0});
            const auto chunks = std::accumulate(stats.chunks_per_rank.begin(), stats.chunks_per_rank.end(), std::size_t{0});
            if (cells != total) fail("cells_per_rank adds up to " + std::to_string(cells));
            if (chunks != stats.chunks) fail("chunks_per_rank adds up to " + std::to_string(chunks));
            if (rb == 37) {
                if (reference.empty())
                    reference = got.records;
                else if (got.records != reference)
                    fail("results differ bitwise from the first case");
            }
            out << "[" << c.name << "] " << stats.chunks << " chunks, cells per rank:";
            for (std::size_t n : stats.cells_per_rank) out << ' ' << n;
            out << ", " << stats.wall_s * 1e3 << " ms\n";
        }
    }
    return failures;
}

int run_stop(const MpiSession& session, RootStream& out) {
    auto scheduler = make_mpi_scheduler(session.comm());
    const std::vector<IndexRange> todo = {{0, 200000}};
    ScheduleOptions options;
    options.record_bytes = 24;
    options.max_chunk = 64;
    options.min_chunk = 4;
    options.tick_interval_s = 0.02;
    int ticks = 0;
    options.on_tick = [&] { ++ticks; };
    options.stop_requested = [&] { return ticks >= 5; };  // about 0.1 s in

    std::vector<int> times(200000, 0);
    std::size_t bad = 0, computed_here = 0;
    const ScheduleStats stats = scheduler->run(
        todo, options,
        [&](std::size_t first, std::size_t count, std::byte* records) {
            for (std::size_t i = 0; i < count; ++i) fill_record(first + i, records + i * 24, 24, 2000);
            computed_here += count;
        },
        [&](std::size_t first, std::size_t count, const std::byte* records) {
            std::vector<std::byte> expected(24);
            for (std::size_t i = 0; i < count; ++i) {
                ++times.at(first + i);
                fill_record(first + i, expected.data(), 24, 0);
                if (std::memcmp(expected.data(), records + i * 24, 24) != 0) ++bad;
            }
        });

    int failures = 0;
    auto fail = [&](const std::string& what) {
        ++failures;
        std::cerr << "FAIL [stop] rank " << session.rank() << ": " << what << '\n';
    };
    if (!stats.stopped) fail("not reported as stopped");
    if (stats.complete) fail("reported complete although stopped early");
    // Every chunk computed anywhere must have reached the sink.
    std::vector<unsigned long long> computed(static_cast<std::size_t>(session.size()), 0);
    const unsigned long long mine = computed_here;
    MPI_Gather(&mine, 1, MPI_UNSIGNED_LONG_LONG, computed.data(), 1, MPI_UNSIGNED_LONG_LONG, 0, session.comm());
    if (session.is_root()) {
        std::size_t sunk = 0;
        for (int n : times) {
            if (n > 1) fail("an index was sunk twice");
            sunk += static_cast<std::size_t>(n);
        }
        if (sunk != stats.cells_done) fail("sink saw " + std::to_string(sunk) + " cells, stats say " +
                                           std::to_string(stats.cells_done));
        if (bad != 0) fail(std::to_string(bad) + " records arrived altered");
        for (int r = 0; r < session.size(); ++r)
            if (computed[static_cast<std::size_t>(r)] != stats.cells_per_rank[static_cast<std::size_t>(r)])
                fail("rank " + std::to_string(r) + " computed " + std::to_string(computed[static_cast<std::size_t>(r)]) +
                     " cells but " + std::to_string(stats.cells_per_rank[static_cast<std::size_t>(r)]) + " reached the sink");
        out << "[stop] after " << ticks << " ticks: " << stats.cells_done << " of 200000 cells in " << stats.chunks
            << " chunks, " << stats.wall_s * 1e3 << " ms\n";
    }
    return failures;
}

int run_abandon(const MpiSession& session, RootStream& out) {
    auto scheduler = make_mpi_scheduler(session.comm());
    ScheduleOptions options;
    options.record_bytes = 8;
    options.max_chunk = 4;
    options.min_chunk = 4;
    options.tick_interval_s = 0.01;
    const double start = MPI_Wtime();
    options.stop_requested = [&] { return MPI_Wtime() - start > 0.2; };
    std::vector<int> times(64, 0);
    const ScheduleStats stats = scheduler->run(
        {{0, 64}}, options,
        [&](std::size_t first, std::size_t count, std::byte* records) {
            // A chunk of slow cells: 2 s unless a stop is noticed, as the integrator does.
            const double begun = MPI_Wtime();
            while (MPI_Wtime() - begun < 2.0) {
                if (scheduler->stop_pending()) throw ChunkAbandoned();
                std::this_thread::sleep_for(std::chrono::milliseconds(1));
            }
            for (std::size_t i = 0; i < count; ++i) fill_record(first + i, records + i * 8, 8, 0);
        },
        [&](std::size_t first, std::size_t count, const std::byte*) {
            for (std::size_t i = 0; i < count; ++i) ++times.at(first + i);
        });
    const double wall = MPI_Wtime() - start;
    int failures = 0;
    auto fail = [&](const std::string& what) {
        ++failures;
        std::cerr << "FAIL [abandon] rank " << session.rank() << ": " << what << '\n';
    };
    if (!stats.stopped) fail("not reported as stopped");
    if (stats.complete) fail("reported complete");
    if (!scheduler->stop_pending()) fail("stop_pending() false after a stop");
    if (wall > 1.2) fail("run() took " + std::to_string(wall) + " s; a stop must end it within about 1 s");
    if (session.is_root()) {
        std::size_t sunk = 0;
        for (int n : times) sunk += static_cast<std::size_t>(n);
        if (sunk != 0) fail(std::to_string(sunk) + " cells of abandoned chunks reached the sink");
        if (stats.cells_done != 0) fail("cells_done " + std::to_string(stats.cells_done));
        out << "[abandon] run() ended after " << wall << " s\n";
    }
    return failures;
}

int run_throw(const MpiSession& session, int failing_rank) {
    auto scheduler = make_mpi_scheduler(session.comm());
    ScheduleOptions options;
    options.record_bytes = 8;
    options.max_chunk = 16;
    const int rank = session.rank();
    scheduler->run(
        {{0, 100000}}, options,
        [&](std::size_t first, std::size_t, std::byte*) {
            if (rank == failing_rank) throw std::runtime_error("injected failure in cell " + std::to_string(first));
        },
        [](std::size_t, std::size_t, const std::byte*) {});
    std::cerr << "rank " << rank << ": run() returned although rank " << failing_rank << " threw\n";
    return 1;
}

}  // namespace

int main(int argc, char** argv) {
    MpiSession session(argc, argv);
    RootStream out(session);

    CLI::App app{"Checks the MPI scheduler; run under mpirun with any number of ranks."};
    std::string mode = "check";
    app.add_option("--mode", mode, "what to check")
        ->check(CLI::IsMember({"check", "stop", "abandon", "throw-worker", "throw-master"}))
        ->capture_default_str();
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return session.is_root() ? app.exit(e) : (e.get_exit_code() != 0 ? 2 : 0);  // same verdict everywhere
    }

    try {
        int failures = 0;
        if (mode == "check")
            failures = run_checks(session, out);
        else if (mode == "stop")
            failures = run_stop(session, out);
        else if (mode == "abandon")
            failures = run_abandon(session, out);
        else if (mode == "throw-worker")
            failures = run_throw(session, 1);
        else
            failures = run_throw(session, 0);
        out << (failures == 0 ? "OK" : "FAILED") << " with " << session.size() << " rank(s)\n";
        return failures == 0 ? 0 : 1;
    } catch (const std::exception& e) {
        abort_on_error(session.rank(), e);
    }
}
