#pragma once
/// The output file of a run, claimed before any computing: a name that can be written, held by
/// this run alone, and no temporary file left behind whatever way the run ends short of SIGKILL.
#include <string>

namespace rocksweep {

/// Made by the one process that writes `path` (rank 0), before any cell is computed.
///
/// The constructor checks everything that would otherwise fail only after computing, and throws
/// InputError(field, path, allowed) for the first problem found:
/// - the name: not empty; PATH.tmp and PATH.lock within NAME_MAX and PATH_MAX;
/// - not an input: PATH is none of the files the run reads (run_inputs.hpp), by identity;
/// - the place: an existing, writable directory; PATH not a directory or other non-file;
///   PATH.tmp, if it exists, a regular file (a directory of that name is refused, never deleted);
/// - the lock: an exclusive flock(2) on PATH.lock, so that a second run writing the same output
///   fails at once. The kernel drops the lock when the process dies, so a run killed by
///   SIGKILL never blocks the `--resume` that follows (its PATH.lock stays, unlocked);
/// - creation: PATH.tmp is created and removed again (catches /proc, read-only mounts).
///
/// The destructor removes PATH.tmp (a partial save) and PATH.lock and releases the lock; it
/// runs on normal return, on exceptions and on the SIGINT/SIGTERM path, which returns normally.
class OutputClaim {
public:
    OutputClaim(const std::string& field, const std::string& path);
    ~OutputClaim();
    OutputClaim(OutputClaim&& other) noexcept;
    OutputClaim& operator=(OutputClaim&&) = delete;
    OutputClaim(const OutputClaim&) = delete;
    OutputClaim& operator=(const OutputClaim&) = delete;

    const std::string& path() const noexcept { return path_; }
    /// True if PATH exists (a regular file, by the constructor's checks).
    bool exists() const;

private:
    std::string path_;
    int lock_fd_ = -1;
};

}  // namespace rocksweep
