#include "rocksweep/app/run_support.hpp"

#include <ctime>

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

}  // namespace rocksweep
