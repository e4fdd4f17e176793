// The HDF5 layer's attributes: numbers and strings (empty, UTF-8, longer than an object header)
// back exactly, strings stored fixed-length without a terminator, wrong kinds refused. Mirrors
// src/io/hdf5_attribute.cpp.
#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>

#include "rocksweep/io/hdf5.hpp"
#include "test_support.hpp"

using namespace rocksweep;
using rocksweep::testing::TempDir;

TEST(Hdf5, AttributesRoundTripIncludingLongText) {
    TempDir dir;
    const std::string path = dir.file("attrs.h5");
    // Larger than the 64 KiB an object header can hold: needs the 1.8 format's dense storage.
    std::string long_text;
    while (long_text.size() < 100'000) long_text += "key = \"value\" # comment\n";
    {
        h5::File f = h5::File::create(path);
        h5::write_attribute(f, "x", 0.1);
        h5::write_attribute(f, "n", std::int64_t{-42});
        h5::write_attribute(f, "count", std::size_t{7});
        h5::write_attribute(f, "empty", "");
        h5::write_attribute(f, "utf8", "θ_f = α/2");
        h5::write_attribute(f, "long", long_text);
        h5::write_attribute(f, "x", 0.2);  // replaces
        f.close();
    }
    const h5::File f = h5::File::open_read_only(path);
    EXPECT_EQ(h5::read_double_attribute(f, "x"), 0.2);
    EXPECT_EQ(h5::read_int64_attribute(f, "n"), -42);
    EXPECT_EQ(h5::read_int64_attribute(f, "count"), 7);
    EXPECT_EQ(h5::read_double_attribute(f, "count"), 7.0);
    EXPECT_EQ(h5::read_string_attribute(f, "empty"), "");
    EXPECT_EQ(h5::read_string_attribute(f, "utf8"), "θ_f = α/2");
    EXPECT_EQ(h5::read_string_attribute(f, "long"), long_text);
    // Stored without a terminator (netCDF would hand it to ncreadatt as a trailing char(0)):
    // exactly the text's bytes, null-padded; "" as one byte of padding.
    for (const auto& [name, bytes] : {std::pair<const char*, std::size_t>{"utf8", std::string("θ_f = α/2").size()},
                                      {"empty", 1}}) {
        const hid_t a = H5Aopen(f.id(), name, H5P_DEFAULT);
        ASSERT_GE(a, 0);
        const hid_t t = H5Aget_type(a);
        EXPECT_EQ(H5Tget_size(t), bytes) << name;
        EXPECT_EQ(H5Tget_strpad(t), H5T_STR_NULLPAD) << name;
        EXPECT_EQ(H5Tis_variable_str(t), 0) << name;
        H5Tclose(t);
        H5Aclose(a);
    }
    EXPECT_THROW(h5::read_int64_attribute(f, "x"), Hdf5Error);
    EXPECT_THROW(h5::read_double_attribute(f, "missing"), Hdf5Error);
}
