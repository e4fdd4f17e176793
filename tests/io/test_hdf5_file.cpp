// The HDF5 layer's files and errors: a failure carries HDF5's own text and the path, and a file
// refuses to close while objects opened from it live. Apart from datasets and attributes as
// src/io/hdf5_file.cpp and hdf5_error.cpp are.
#include <gtest/gtest.h>

#include <string>

#include "rocksweep/io/hdf5.hpp"
#include "test_support.hpp"

using namespace rocksweep;
using rocksweep::testing::TempDir;

TEST(Hdf5, ErrorsCarryHdf5Text) {
    TempDir dir;
    const std::string path = dir.file("absent.h5");
    try {
        h5::File::open_read_only(path);
        FAIL() << "expected Hdf5Error";
    } catch (const Hdf5Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find(path), std::string::npos) << what;
        EXPECT_NE(what.find("unable to open file"), std::string::npos) << what;
    }
}

TEST(Hdf5, CloseRefusesWhileObjectsAreOpen) {
    TempDir dir;
    {
        h5::File f = h5::File::create(dir.file("open.h5"));
        const h5::Group g = f.create_group("g");
        try {
            f.close();
            ADD_FAILURE() << "expected Hdf5Error";
        } catch (const Hdf5Error& e) {
            EXPECT_NE(std::string(e.what()).find("open.h5"), std::string::npos) << e.what();
        }
    }
    // The destructor closed the file once the group was gone: nothing is left open in this
    // process (run as one binary, this also covers the tests before it).
    EXPECT_EQ(H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL), 0);
}
