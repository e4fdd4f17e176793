// Saving without losing anything: a failed save keeps the previous file, and an output is
// claimed (validated, locked, proven creatable) before any computing.
#include <gtest/gtest.h>

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

#include "rocksweep/core/errors.hpp"
#include "rocksweep/io/hdf5.hpp"
#include "rocksweep/io/output_claim.hpp"
#include "test_support.hpp"

namespace fs = std::filesystem;
using namespace rocksweep;
using rocksweep::testing::TempDir;


TEST(Publish, FullDiskIsOneLineAndKeepsThePreviousFile) {
    TempDir dir;
    const std::string path = dir.file("out.h5");
    { std::ofstream(path) << "previous save"; }
    const auto disk_full = [](const std::string& tmp) {
        { std::ofstream(tmp) << "half"; }
        throw std::system_error(ENOSPC, std::generic_category(), "writing " + tmp);
    };
    try {
        h5::publish_atomically(path, disk_full);
        ADD_FAILURE() << "expected std::runtime_error";
    } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()),
                  "cannot write " + path + ": no space left on device (" + path + " still holds the previous save)");
    }
    EXPECT_FALSE(fs::exists(path + ".tmp"));
    std::ifstream in(path);
    std::string kept;
    std::getline(in, kept);
    EXPECT_EQ(kept, "previous save");

    // An HDF5 failure carries errno the same way; without a previous file there is no note.
    const std::string fresh = dir.file("fresh.h5");
    try {
        h5::publish_atomically(fresh, [](const std::string&) { throw Hdf5Error("writing dataset 'x': ...", EDQUOT); });
        ADD_FAILURE() << "expected std::runtime_error";
    } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()), "cannot write " + fresh + ": no space left on device");
    }
    EXPECT_FALSE(fs::exists(fresh));
}

TEST(OutputClaim, SecondClaimOfTheSameOutputFailsUntilTheFirstEnds) {
    TempDir dir;
    const std::string path = dir.file("out.h5");
    {
        const OutputClaim first("output", path);
        EXPECT_TRUE(fs::exists(path + ".lock"));
        EXPECT_FALSE(fs::exists(path + ".tmp")) << "the creation proof leaves no file";
        try {
            const OutputClaim second("output", path);
            ADD_FAILURE() << "expected InputError";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("another rocksweep holds " + path + ".lock"), std::string::npos)
                << e.what();
        }
        { std::ofstream(path + ".tmp") << "partial"; }  // a save cut short
    }
    EXPECT_FALSE(fs::exists(path + ".tmp")) << "the claim removes its partial save";
    EXPECT_FALSE(fs::exists(path + ".lock"));
    EXPECT_NO_THROW(OutputClaim("output", path));
}

TEST(OutputClaim, RefusesWhatCannotBeWrittenAndTouchesNothing) {
    TempDir dir;
    const std::string path = dir.file("out.h5");
    fs::create_directory(path + ".tmp");
    EXPECT_THROW(OutputClaim("output", path), InputError);
    EXPECT_TRUE(fs::is_directory(path + ".tmp")) << "never deleted";
    EXPECT_FALSE(fs::exists(path + ".lock"));

    EXPECT_THROW(OutputClaim("output", dir.file(std::string(251, 'n') + ".h5")), InputError);  // NAME.lock > 255
    EXPECT_NO_THROW(OutputClaim("output", dir.file(std::string(250, 'n'))));                    // exactly fits
    EXPECT_THROW(OutputClaim("output", dir.file("missing/out.h5")), InputError);
    EXPECT_THROW(OutputClaim("output", dir.path().string()), InputError);  // a directory
    EXPECT_THROW(OutputClaim("output", "/proc/out.h5"), InputError);
    EXPECT_THROW(OutputClaim("output", ""), InputError);
}
