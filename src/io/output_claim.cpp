#include "rocksweep/io/output_claim.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstring>
#include <filesystem>
#include <utility>

#include "rocksweep/core/errors.hpp"
#include "rocksweep/io/run_inputs.hpp"

namespace rocksweep {

namespace {

namespace fs = std::filesystem;

// The longest sibling we create; checking it covers PATH.tmp too.
constexpr const char* lock_suffix = ".lock";

std::string tmp_of(const std::string& path) { return path + ".tmp"; }
std::string lock_of(const std::string& path) { return path + lock_suffix; }

void check_name(const std::string& field, const std::string& path, const fs::path& dir) {
    if (path.empty()) throw InputError(field, "\"\"", "a file name");
    // -o=x.h5 hands CLI11 the value "=x.h5" (only --output=x.h5 splits at '='): never a name meant.
    if (path[0] == '=')
        throw InputError(field, path, "a file name that does not begin with '=' (write -o FILE or --output=FILE)");
    const std::string file = fs::path(path).filename().string();
    if (file.empty() || file == "." || file == "..") throw InputError(field, path, "a file name, not a directory");
    long name_max = ::pathconf(dir.c_str(), _PC_NAME_MAX);
    if (name_max <= 0) name_max = NAME_MAX;
    const std::size_t extra = std::strlen(lock_suffix);
    if (file.size() + extra > static_cast<std::size_t>(name_max))
        throw InputError(field, path,
                         "a file name of at most " + std::to_string(name_max - static_cast<long>(extra)) +
                             " bytes (" + file.substr(0, 16) + "... has " + std::to_string(file.size()) +
                             "; NAME.tmp and NAME.lock must fit in " + std::to_string(name_max) + ")");
    if (path.size() + extra >= PATH_MAX)
        throw InputError(field, path.substr(0, 40) + "...",
                         "a path of at most " + std::to_string(PATH_MAX - 1 - extra) + " bytes (it has " +
                             std::to_string(path.size()) + ")");
}

void check_place(const std::string& field, const std::string& path, const fs::path& dir) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec))
        throw InputError(field, path, "a file in an existing directory (" + dir.string() + " does not exist)");
    if (::access(dir.c_str(), W_OK) != 0)
        throw InputError(field, path, "a file in a writable directory (" + dir.string() + " is not writable)");
    const fs::file_status st = fs::symlink_status(path, ec);
    if (fs::is_directory(fs::status(path, ec))) throw InputError(field, path, "a file name, not a directory");
    if (fs::exists(st) && !fs::is_regular_file(fs::status(path, ec)))
        throw InputError(field, path, "a regular file (it exists and is not one)");
    const fs::file_status tmp = fs::symlink_status(tmp_of(path), ec);
    if (fs::exists(tmp) && !fs::is_regular_file(tmp))
        throw InputError(field, path,
                         "a name whose temporary file " + tmp_of(path) +
                             " is free or a regular file (it exists and is not one; move it away)");
}

/// An exclusive lock on PATH.lock, or InputError. Returns the descriptor holding it.
int take_lock(const std::string& field, const std::string& path) {
    const std::string lock = lock_of(path);
    // A run that finishes unlinks its lock file while holding the lock; one that opened the
    // file just before may then lock an unlinked inode. Only a lock on the file still at
    // that name counts, hence the check and the retry.
    for (int attempt = 0; attempt < 100; ++attempt) {
        const int fd = ::open(lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
        if (fd < 0)
            throw InputError(field, path,
                             "a location where files can be created (" + lock + ": " + std::strerror(errno) + ")");
        if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
            const int err = errno;
            ::close(fd);
            if (err == EWOULDBLOCK)
                throw InputError(field, path,
                                 "an output no other run is writing (another rocksweep holds " + lock + ")");
            throw InputError(field, path, "a file system with locks (" + lock + ": " + std::strerror(err) + ")");
        }
        struct stat held {}, named {};
        if (::fstat(fd, &held) == 0 && ::stat(lock.c_str(), &named) == 0 && held.st_dev == named.st_dev &&
            held.st_ino == named.st_ino)
            return fd;
        ::close(fd);
    }
    throw InputError(field, path, "an output no other run is writing (" + lock + " keeps changing)");
}

/// Creates PATH.tmp and removes it again: the proof that the save at the end can be made.
void prove_creatable(const std::string& field, const std::string& path) {
    const std::string tmp = tmp_of(path);
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (fd < 0)
        throw InputError(field, path, "a location where files can be created (" + tmp + ": " + std::strerror(errno) + ")");
    ::close(fd);
    ::unlink(tmp.c_str());
}

}  // namespace

OutputClaim::OutputClaim(const std::string& field, const std::string& path) : path_(path) {
    const fs::path p(path);
    const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
    check_name(field, path, dir);
    refuse_input_as_output(field, path);
    check_place(field, path, dir);
    lock_fd_ = take_lock(field, path);
    try {
        prove_creatable(field, path);
    } catch (...) {
        ::unlink(lock_of(path_).c_str());
        ::close(lock_fd_);
        lock_fd_ = -1;
        throw;
    }
}

OutputClaim::OutputClaim(OutputClaim&& other) noexcept
    : path_(std::move(other.path_)), lock_fd_(std::exchange(other.lock_fd_, -1)) {}

OutputClaim::~OutputClaim() {
    if (lock_fd_ < 0) return;
    // We hold the lock, so any PATH.tmp is ours (or a dead run's): a partial save.
    ::unlink(tmp_of(path_).c_str());
    // Unlink before closing: once the lock is released the name may belong to the next run.
    ::unlink(lock_of(path_).c_str());
    ::close(lock_fd_);
}

bool OutputClaim::exists() const {
    std::error_code ec;
    return fs::exists(path_, ec);
}

}  // namespace rocksweep
