#pragma once
// Files the record tests write: in a folder of their own per process, since ctest runs tests in
// parallel and other checkouts on the machine may run the same tests at the same time.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

#include <unistd.h>

namespace rocksweep::test_files {

/// The process's folder, removed with everything in it when the process ends.
inline const std::string& temp_dir() {
    struct Folder {
        std::string path = ::testing::TempDir() + "rocksweep_records_" + std::to_string(::getpid()) + "/";
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

}  // namespace rocksweep::test_files
