#include "rocksweep/app/run_support.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <ctime>

#include "rocksweep/core/errors.hpp"
#include "rocksweep/physics/integrator.hpp"

namespace rocksweep {

namespace {
volatile std::sig_atomic_t g_signal = 0;
extern "C" void note_signal(int sig) { g_signal = sig; }
}  // namespace

StopSignals::StopSignals() {
    g_signal = 0;
    struct sigaction sa{};
    sa.sa_handler = note_signal;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, &old_int_);
    sigaction(SIGTERM, &sa, &old_term_);
}

StopSignals::~StopSignals() {
    sigaction(SIGINT, &old_int_, nullptr);
    sigaction(SIGTERM, &old_term_, nullptr);
}

int StopSignals::received() { return g_signal; }
int StopSignals::stopping_signal() { return g_signal ? g_signal : SIGINT; }

OutputVerdict agree_on_output(const MpiSession& mpi, std::ostream& log, const std::function<bool()>& prepare,
                              const std::function<void()>& release) {
    int verdict = static_cast<int>(OutputVerdict::go);
    std::string why;
    if (mpi.is_root()) {
        try {
            if (prepare()) verdict = static_cast<int>(OutputVerdict::nothing_to_do);
        } catch (const InputError& e) {
            verdict = static_cast<int>(OutputVerdict::refused), why = cli_message(e);
        } catch (const std::runtime_error& e) {
            verdict = static_cast<int>(OutputVerdict::failed), why = e.what();
        }
        if (!why.empty()) release();  // the output is given up before the message
    }
    mpi.broadcast(verdict);
    if (!why.empty()) log << "rocksweep: error: " << why << "\n";
    return static_cast<OutputVerdict>(verdict);
}

int exit_status(OutputVerdict v) {
    switch (v) {
        case OutputVerdict::refused: return 2;
        case OutputVerdict::failed: return 1;
        default: return 0;
    }
}

ComputeFn cell_results_compute(std::function<void(std::size_t, std::size_t, CellResult*)> compute) {
    return [compute = std::move(compute)](std::size_t first, std::size_t count, std::byte* out) {
        std::vector<CellResult> buf(count);
        try {
            compute(first, count, buf.data());
        } catch (const Interrupted&) {
            throw ChunkAbandoned();
        }
        std::memcpy(out, buf.data(), count * sizeof(CellResult));
    };
}

std::string utc_now() {
    char buf[32];
    const std::time_t t = std::time(nullptr);
    std::tm tm{};
    gmtime_r(&t, &tm);
    std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
    return buf;
}

std::vector<IndexRange> missing_ranges(const std::vector<std::uint8_t>& done) {
    std::vector<IndexRange> todo;
    for (std::size_t i = 0; i < done.size();) {
        if (done[i]) { ++i; continue; }
        std::size_t j = i;
        while (j < done.size() && !done[j]) ++j;
        todo.push_back({i, j - i});
        i = j;
    }
    return todo;
}

std::vector<IndexRange> missing_cells(std::size_t total, const DoneReader& read_done) {
    // Cells whose `done` byte is read at once: what a resume holds, whatever the grid.
    constexpr std::size_t scan_cells = std::size_t{1} << 24;
    std::vector<IndexRange> todo;
    std::vector<std::uint8_t> done;
    for (std::size_t first = 0; first < total; first += scan_cells) {
        done.resize(std::min(scan_cells, total - first));
        read_done(first, done.size(), done.data());
        for (IndexRange r : missing_ranges(done)) {
            r.first += first;
            if (!todo.empty() && todo.back().first + todo.back().count == r.first) todo.back().count += r.count;
            else todo.push_back(r);
        }
    }
    return todo;
}

}  // namespace rocksweep
