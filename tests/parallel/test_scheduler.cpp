// Scheduler and MPI session, as one process. For MPI this covers the size-1 path only; the
// multi-rank protocol is checked under mpirun by tests/mpi/. The progress report: test_progress.cpp.
#include "rocksweep/parallel/mpi_session.hpp"
#include "rocksweep/parallel/scheduler.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace rocksweep {
namespace {

// ---- MPI, started the first time a test needs it and finalised after the last test. ----------
// A session started by hand leaves MPI alone (no launcher), so the environment initialises MPI
// itself, as a singleton, to test the MPI scheduler on one rank; the session then adopts it.

class MpiEnvironment : public ::testing::Environment {
public:
    MpiSession& session() {
        if (!session_) {
            static char name[] = "test_scheduler";
            static char* args[] = {name, nullptr};
            argc_ = 1;
            argv_ = args;
            int initialized = 0, provided = 0;
            MPI_Initialized(&initialized);
            if (!initialized) {
                MPI_Init_thread(&argc_, &argv_, MPI_THREAD_FUNNELED, &provided);
                owns_mpi_ = true;
            }
            session_ = std::make_unique<MpiSession>(argc_, argv_);
        }
        return *session_;
    }
    void TearDown() override {
        session_.reset();
        if (owns_mpi_) MPI_Finalize();
    }

private:
    int argc_ = 0;
    char** argv_ = nullptr;
    bool owns_mpi_ = false;
    std::unique_ptr<MpiSession> session_;
};

MpiEnvironment* const mpi_environment =
    static_cast<MpiEnvironment*>(::testing::AddGlobalTestEnvironment(new MpiEnvironment));

// ---- A record that depends only on its index. ----------------------------------------------------

std::uint64_t mix(std::uint64_t x) {
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
}

void fill_record(std::size_t index, std::byte* out, std::size_t bytes) {
    for (std::size_t b = 0; b < bytes; ++b) out[b] = static_cast<std::byte>(mix(index * 131 + b) & 0xFF);
}

bool record_ok(std::size_t index, const std::byte* in, std::size_t bytes) {
    std::vector<std::byte> expected(bytes);
    fill_record(index, expected.data(), bytes);
    return std::memcmp(expected.data(), in, bytes) == 0;
}

// ---- Runs a scheduler and records what it did. -----------------------------------------------

enum class Kind { serial, mpi };

void PrintTo(Kind kind, std::ostream* os) { *os << (kind == Kind::serial ? "serial" : "mpi"); }

std::string kind_name(const ::testing::TestParamInfo<Kind>& info) {
    return info.param == Kind::serial ? "serial" : "mpi_size1";
}

struct Outcome {
    ScheduleStats stats;
    std::vector<int> sunk;             ///< times each index reached the sink
    std::vector<std::byte> records;    ///< everything sunk, at its index
    std::vector<IndexRange> computed;  ///< chunks in the order compute saw them
    std::vector<IndexRange> sinks;
    bool all_records_ok = true;
};

class SchedulerTest : public ::testing::TestWithParam<Kind> {
protected:
    std::unique_ptr<Scheduler> make() {
        if (GetParam() == Kind::serial) return make_serial_scheduler();
        mpi_environment->session();
        return make_mpi_scheduler(MPI_COMM_WORLD);
    }

    Outcome run(const std::vector<IndexRange>& todo, ScheduleOptions options, std::size_t n_indices) {
        Outcome outcome;
        outcome.sunk.assign(n_indices, 0);
        outcome.records.assign(n_indices * options.record_bytes, std::byte{0});
        const std::size_t rb = options.record_bytes;
        auto scheduler = make();
        EXPECT_EQ(scheduler->rank(), 0);
        EXPECT_EQ(scheduler->size(), 1);
        outcome.stats = scheduler->run(
            todo, options,
            [&](std::size_t first, std::size_t count, std::byte* out) {
                outcome.computed.push_back({first, count});
                for (std::size_t i = 0; i < count; ++i) fill_record(first + i, out + i * rb, rb);
            },
            [&](std::size_t first, std::size_t count, const std::byte* in) {
                outcome.sinks.push_back({first, count});
                for (std::size_t i = 0; i < count; ++i) {
                    ++outcome.sunk.at(first + i);
                    if (!record_ok(first + i, in + i * rb, rb)) outcome.all_records_ok = false;
                    std::memcpy(outcome.records.data() + (first + i) * rb, in + i * rb, rb);
                }
            });
        return outcome;
    }
};

TEST_P(SchedulerTest, VisitsEveryIndexOnceWithIntactRecords) {
    ScheduleOptions options;
    options.record_bytes = 37;  // not a multiple of any alignment
    options.max_chunk = 64;
    options.min_chunk = 4;
    const Outcome outcome = run({{0, 1000}}, options, 1000);
    for (std::size_t i = 0; i < 1000; ++i) EXPECT_EQ(outcome.sunk[i], 1) << "index " << i;
    EXPECT_TRUE(outcome.all_records_ok);
    EXPECT_TRUE(outcome.stats.complete);
    EXPECT_FALSE(outcome.stats.stopped);
    EXPECT_EQ(outcome.stats.cells_done, 1000u);
    EXPECT_EQ(outcome.stats.chunks, outcome.sinks.size());
    ASSERT_EQ(outcome.stats.cells_per_rank.size(), 1u);
    EXPECT_EQ(outcome.stats.cells_per_rank[0], 1000u);
    EXPECT_EQ(outcome.stats.chunks_per_rank[0], outcome.stats.chunks);
}

TEST_P(SchedulerTest, ChunksStayWithinBoundsAndWithinOneRange) {
    ScheduleOptions options;
    options.record_bytes = 8;
    options.max_chunk = 50;
    options.min_chunk = 10;
    const std::vector<IndexRange> todo = {{0, 7}, {20, 120}, {200, 50}, {300, 51}};
    const Outcome outcome = run(todo, options, 400);
    ASSERT_FALSE(outcome.computed.empty());
    for (const IndexRange& chunk : outcome.computed) {
        EXPECT_GE(chunk.count, 1u);
        EXPECT_LE(chunk.count, options.max_chunk);
        const IndexRange* home = nullptr;
        for (const IndexRange& r : todo)
            if (chunk.first >= r.first && chunk.first + chunk.count <= r.first + r.count) home = &r;
        ASSERT_NE(home, nullptr) << "chunk " << chunk.first << "+" << chunk.count << " spans ranges";
        if (chunk.first + chunk.count != home->first + home->count) {
            EXPECT_GE(chunk.count, options.min_chunk) << "a short chunk only at the end of a range";
        }
    }
    EXPECT_TRUE(outcome.stats.complete);
}

TEST_P(SchedulerTest, TodoWithHolesVisitsOnlyTheTodoIndices) {
    // The resume case: some cells are done already and are left out of the work list.
    ScheduleOptions options;
    options.record_bytes = 16;
    options.max_chunk = 32;
    options.min_chunk = 1;
    const std::vector<IndexRange> todo = {{3, 10}, {50, 3}, {100, 200}, {400, 0}, {999, 1}};
    const Outcome outcome = run(todo, options, 1000);
    std::vector<int> wanted(1000, 0);
    for (const IndexRange& r : todo)
        for (std::size_t i = r.first; i < r.first + r.count; ++i) wanted[i] = 1;
    EXPECT_EQ(outcome.sunk, wanted);
    EXPECT_TRUE(outcome.all_records_ok);
    EXPECT_EQ(outcome.stats.cells_done, 214u);
    EXPECT_TRUE(outcome.stats.complete);
}

TEST_P(SchedulerTest, EmptyTodoCompletesWithoutCalls) {
    ScheduleOptions options;
    options.record_bytes = 4;
    const Outcome outcome = run({{10, 0}}, options, 20);
    EXPECT_TRUE(outcome.computed.empty());
    EXPECT_TRUE(outcome.sinks.empty());
    EXPECT_TRUE(outcome.stats.complete);
    EXPECT_EQ(outcome.stats.chunks, 0u);
}

TEST_P(SchedulerTest, ResultsDoNotDependOnChunkSize) {
    std::vector<std::byte> reference;
    for (std::size_t max_chunk : {1u, 3u, 64u, 1000u}) {
        ScheduleOptions options;
        options.record_bytes = 24;
        options.max_chunk = max_chunk;
        options.min_chunk = 1;
        const Outcome outcome = run({{0, 500}}, options, 500);
        if (reference.empty())
            reference = outcome.records;
        else
            EXPECT_EQ(outcome.records, reference) << "max_chunk " << max_chunk;
    }
}

TEST_P(SchedulerTest, StopRequestedEndsEarlyAndSaysSo) {
    ScheduleOptions options;
    options.record_bytes = 8;
    options.max_chunk = 10;
    options.min_chunk = 10;
    int polls = 0;
    options.stop_requested = [&] { return ++polls > 3; };
    const Outcome outcome = run({{0, 1000}}, options, 1000);
    EXPECT_TRUE(outcome.stats.stopped);
    EXPECT_FALSE(outcome.stats.complete);
    EXPECT_GT(outcome.stats.cells_done, 0u);
    EXPECT_LT(outcome.stats.cells_done, 1000u);
    std::size_t sunk = 0;
    for (int n : outcome.sunk) {
        EXPECT_LE(n, 1);
        sunk += static_cast<std::size_t>(n);
    }
    EXPECT_EQ(sunk, outcome.stats.cells_done);
    EXPECT_EQ(outcome.computed.size(), outcome.sinks.size()) << "every chunk computed reaches the sink";
    EXPECT_TRUE(outcome.all_records_ok);
}

TEST_P(SchedulerTest, StopBeforeStartComputesNothing) {
    ScheduleOptions options;
    options.record_bytes = 8;
    options.stop_requested = [] { return true; };
    const Outcome outcome = run({{0, 100}}, options, 100);
    EXPECT_TRUE(outcome.stats.stopped);
    EXPECT_FALSE(outcome.stats.complete);
    EXPECT_EQ(outcome.stats.cells_done, 0u);
    EXPECT_TRUE(outcome.computed.empty());
}

TEST_P(SchedulerTest, AnAbandonedChunkIsNeverSunkAndStopsTheRun) {
    ScheduleOptions options;
    options.record_bytes = 8;
    options.max_chunk = 10;
    options.min_chunk = 10;
    std::vector<std::byte> scratch(10 * 8);
    std::vector<IndexRange> computed;
    std::vector<int> sunk(100, 0);
    auto scheduler = make();
    const ScheduleStats stats = scheduler->run(
        {{0, 100}}, options,
        [&](std::size_t first, std::size_t count, std::byte* out) {
            computed.push_back({first, count});
            if (first == 30) throw ChunkAbandoned();  // a stop arrived in the middle of it
            for (std::size_t i = 0; i < count; ++i) fill_record(first + i, out + i * 8, 8);
        },
        [&](std::size_t first, std::size_t count, const std::byte*) {
            for (std::size_t i = 0; i < count; ++i) ++sunk.at(first + i);
        });
    EXPECT_TRUE(stats.stopped);
    EXPECT_FALSE(stats.complete);
    EXPECT_TRUE(scheduler->stop_pending());
    // Chunks 0, 10, 20 done; 30 abandoned; nothing after it handed out.
    ASSERT_EQ(computed.size(), 4u);
    EXPECT_EQ(computed.back().first, 30u);
    EXPECT_EQ(stats.cells_done, 30u);
    for (std::size_t i = 0; i < 100; ++i) EXPECT_EQ(sunk[i], i < 30 ? 1 : 0) << "index " << i;
}

TEST_P(SchedulerTest, StopPendingIsFalseWhileRunningNormally) {
    ScheduleOptions options;
    options.record_bytes = 8;
    options.max_chunk = 10;
    auto scheduler = make();
    bool seen = false;
    scheduler->run(
        {{0, 50}}, options, [&](std::size_t, std::size_t, std::byte*) { seen = seen || scheduler->stop_pending(); },
        [](std::size_t, std::size_t, const std::byte*) {});
    EXPECT_FALSE(seen);
    EXPECT_FALSE(scheduler->stop_pending());
}

TEST_P(SchedulerTest, OnTickIsCalledWhileWorking) {
    ScheduleOptions options;
    options.record_bytes = 8;
    options.max_chunk = 10;
    options.tick_interval_s = 0.0;
    int ticks = 0;
    options.on_tick = [&] { ++ticks; };
    run({{0, 100}}, options, 100);
    EXPECT_GE(ticks, 5);
}

TEST_P(SchedulerTest, ExceptionInComputePropagates) {
    ScheduleOptions options;
    options.record_bytes = 8;
    options.max_chunk = 16;
    auto scheduler = make();
    EXPECT_THROW(scheduler->run(
                     {{0, 100}}, options,
                     [](std::size_t first, std::size_t count, std::byte*) {
                         if (first <= 50 && 50 < first + count) throw std::runtime_error("cell 50 failed");
                     },
                     [](std::size_t, std::size_t, const std::byte*) {}),
                 std::runtime_error);
}

TEST_P(SchedulerTest, InconsistentOptionsAreRejected) {
    auto scheduler = make();
    const auto compute = [](std::size_t, std::size_t, std::byte*) {};
    const auto sink = [](std::size_t, std::size_t, const std::byte*) {};
    ScheduleOptions options;
    options.record_bytes = 8;
    options.max_chunk = 0;
    EXPECT_THROW(scheduler->run({{0, 10}}, options, compute, sink), std::invalid_argument);
    options.max_chunk = 4;
    options.min_chunk = 5;
    EXPECT_THROW(scheduler->run({{0, 10}}, options, compute, sink), std::invalid_argument);
    options.min_chunk = 1;
    options.tick_interval_s = -1.0;
    EXPECT_THROW(scheduler->run({{0, 10}}, options, compute, sink), std::invalid_argument);
}

INSTANTIATE_TEST_SUITE_P(Schedulers, SchedulerTest, ::testing::Values(Kind::serial, Kind::mpi), kind_name);

// ---- Guided chunk sizes. -----------------------------------------------------------------------

TEST(GuidedChunkSize, ShrinksAsWorkRunsOutWithinBounds) {
    ScheduleOptions options;
    options.max_chunk = 256;
    options.min_chunk = 8;
    options.guided_divisor = 2;
    EXPECT_EQ(guided_chunk_size(100000, 4, options), 256u);  // clamped to max_chunk
    EXPECT_EQ(guided_chunk_size(1000, 4, options), 125u);    // 1000 / (2 * 4)
    EXPECT_EQ(guided_chunk_size(1001, 4, options), 126u);    // rounded up
    EXPECT_EQ(guided_chunk_size(20, 4, options), 8u);        // clamped to min_chunk
    EXPECT_EQ(guided_chunk_size(0, 4, options), 8u);
    options.min_chunk = 0;  // acts as 1
    EXPECT_EQ(guided_chunk_size(3, 4, options), 1u);
}

// ---- MPI session and root stream. ----------------------------------------------------------------

TEST(MpiSession, AdoptsAnInitialisedMpiAsRankZeroOfOne) {
    MpiSession& session = mpi_environment->session();
    EXPECT_EQ(session.rank(), 0);
    EXPECT_EQ(session.size(), 1);
    EXPECT_TRUE(session.is_root());
    EXPECT_TRUE(session.uses_mpi());
    EXPECT_GE(session.thread_level(), MPI_THREAD_SINGLE);
}

// The environment variables of each launcher family, one at a time. Open MPI's singleton
// start-up (the environment above) sets PMIX_RANK in this process: saved, cleared, restored.
TEST(MpiSession, LauncherIsRecognisedByItsEnvironment) {
    const char* names[] = {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"};
    std::vector<std::pair<std::string, std::string>> saved;
    for (const char* name : names)
        if (const char* value = std::getenv(name)) saved.emplace_back(name, value);
    for (const char* name : names) unsetenv(name);
    EXPECT_FALSE(launched_by_mpi_launcher());
    for (const char* name : names) {
        setenv(name, "1", 1);
        EXPECT_TRUE(launched_by_mpi_launcher()) << name;
        unsetenv(name);
    }
    EXPECT_FALSE(launched_by_mpi_launcher());
    for (const auto& [name, value] : saved) setenv(name.c_str(), value.c_str(), 1);
}

TEST(RootStream, ForwardsWhenActiveAndDiscardsOtherwise) {
    std::ostringstream target;
    RootStream on(true, target);
    RootStream off(false, target);
    on << "rank zero " << 42 << '\n';
    off << "other rank " << 7 << '\n';
    EXPECT_EQ(target.str(), "rank zero 42\n");
    EXPECT_TRUE(on.is_active());
    EXPECT_FALSE(off.is_active());
    EXPECT_TRUE(off.good()) << "discarding is not a stream error";
}

}  // namespace
}  // namespace rocksweep
