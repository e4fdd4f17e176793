#pragma once
/// What every long-running command (sweep, suite, design) shares around the scheduler: signals
/// that stop it cleanly, the time stamp of its provenance, and the cells still to compute.
#include <csignal>
#include <cstdint>
#include <string>
#include <vector>

#include "rocksweep/parallel/scheduler.hpp"

namespace rocksweep {

/// SIGINT/SIGTERM only raise a flag while a run is under way (from before its output is claimed
/// to the end of its last save, so a signal never kills a save half-way and leaves NAME.tmp):
/// the integration polls it and gives up its chunk, rank 0 stops handing out work, gathers what
/// is done and saves it. One guard at a time; the previous handlers come back with it.
class StopSignals {
public:
    StopSignals();
    ~StopSignals();
    StopSignals(const StopSignals&) = delete;
    StopSignals& operator=(const StopSignals&) = delete;

    /// The signal received since the guard was made, or 0.
    static int received();
    /// The signal a stopped run reports: the one received, else SIGINT (it stopped for another
    /// reason, and is reported as interrupted).
    static int stopping_signal();
    /// The exit status of a stopped run: 128 + stopping_signal().
    static int exit_status() { return 128 + stopping_signal(); }

private:
    struct sigaction old_int_{}, old_term_{};
};

/// Now as ISO 8601 UTC, e.g. 2026-11-24T00:15:07Z.
std::string utc_now();

/// The runs of cells whose `done` entry is 0, in index order.
std::vector<IndexRange> missing_ranges(const std::vector<std::uint8_t>& done);

}  // namespace rocksweep
