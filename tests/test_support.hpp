#pragma once
// What the file tests share: temporary files, bitwise comparison of columns, and the one-line
// message a bad input would print.
#include <gtest/gtest.h>
#include <stdlib.h>
#include <unistd.h>

#include <bit>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include "rocksweep/core/errors.hpp"

namespace rocksweep::testing {

/// A fresh directory per test, removed afterwards (permissions restored first, so that a test
/// that made it read-only still cleans up).
class TempDir {
public:
    TempDir() {
        std::string tmpl = (std::filesystem::temp_directory_path() / "rocksweep_h5_XXXXXX").string();
        if (!mkdtemp(tmpl.data())) throw std::runtime_error("mkdtemp failed");
        path_ = tmpl;
    }
    ~TempDir() {
        std::error_code ec;
        std::filesystem::permissions(path_, std::filesystem::perms::owner_all, std::filesystem::perm_options::add, ec);
        std::filesystem::remove_all(path_, ec);
    }
    std::string file(const std::string& name) const { return (path_ / name).string(); }
    const std::filesystem::path& path() const { return path_; }

private:
    std::filesystem::path path_;
};

/// Bitwise equality of double columns, so NaN == NaN and -0.0 != 0.0.
inline std::vector<std::uint64_t> bits(const std::vector<double>& v) {
    std::vector<std::uint64_t> b;
    for (double x : v) b.push_back(std::bit_cast<std::uint64_t>(x));
    return b;
}

/// A folder per test process, removed with everything in it when the process ends: ctest runs
/// tests in parallel, and other checkouts on the machine may run the same tests at once.
inline const std::string& temp_dir() {
    struct Folder {
        std::string path = ::testing::TempDir() + "rocksweep_tests_" + std::to_string(::getpid()) + "/";
        Folder() { std::filesystem::create_directories(path); }
        ~Folder() {
            std::error_code ignored;
            std::filesystem::remove_all(path, ignored);
        }
    };
    static const Folder folder;
    return folder.path;
}

/// Writes `text` to `name` in temp_dir(); returns its path.
inline std::string write_file(const std::string& name, const std::string& text) {
    const std::string path = temp_dir() + name;
    std::ofstream(path) << text;
    return path;
}

/// The line the command line would print for what `run` throws, or "accepted".
template <class Run>
std::string message_of(Run&& run) {
    try {
        run();
    } catch (const InputError& e) {
        return cli_message(e);
    }
    return "accepted";
}

}  // namespace rocksweep::testing
