// The HDF5 layer's datasets: large ones chunked with shuffle + deflate, small ones contiguous,
// values back exactly, and a read of the wrong kind refused. Mirrors src/io/hdf5_dataset.cpp.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "rocksweep/io/hdf5.hpp"
#include "test_support.hpp"

using namespace rocksweep;
using rocksweep::testing::TempDir;

TEST(Hdf5, LargeDatasetsAreChunkedWithShuffleAndDeflate) {
    TempDir dir;
    const std::string path = dir.file("big.h5");
    std::vector<double> big(300 * 200);
    for (std::size_t i = 0; i < big.size(); ++i) big[i] = static_cast<double>(i % 17) * 0.5;
    const std::vector<std::uint8_t> small = {1, 2, 3};
    {
        h5::File f = h5::File::create(path);
        {
            h5::write_2d<double>(f, "big", big, 300, 200);
            h5::write_1d<std::uint8_t>(f, "small", small);
        }
        f.close();
    }
    const h5::File f = h5::File::open_read_only(path);
    {
        const h5::Dataset ds = f.open_dataset("big");
        const h5::PropertyList dcpl(H5Dget_create_plist(ds.id()));
        EXPECT_EQ(H5Pget_layout(dcpl.id()), H5D_CHUNKED);
        ASSERT_EQ(H5Pget_nfilters(dcpl.id()), 2);
        unsigned flags = 0;
        std::size_t n = 0;
        EXPECT_EQ(H5Pget_filter2(dcpl.id(), 0, &flags, &n, nullptr, 0, nullptr, nullptr), H5Z_FILTER_SHUFFLE);
        unsigned level = 0;
        n = 1;
        EXPECT_EQ(H5Pget_filter2(dcpl.id(), 1, &flags, &n, &level, 0, nullptr, nullptr), H5Z_FILTER_DEFLATE);
        EXPECT_EQ(level, 4u);
        const h5::Dataset s = f.open_dataset("small");
        const h5::PropertyList small_dcpl(H5Dget_create_plist(s.id()));
        EXPECT_EQ(H5Pget_layout(small_dcpl.id()), H5D_CONTIGUOUS);
    }
    const h5::Array2<double> back = h5::read_2d<double>(f, "big");
    EXPECT_EQ(back.rows, 300u);
    EXPECT_EQ(back.cols, 200u);
    EXPECT_EQ(back.values, big);
    EXPECT_EQ(h5::read_1d<std::uint8_t>(f, "small"), small);
    // Reading with the wrong element type fails rather than converting.
    EXPECT_THROW(h5::read_1d<std::int32_t>(f, "small"), Hdf5Error);
    EXPECT_THROW(h5::read_1d<double>(f, "big"), Hdf5Error);  // 2-D, not 1-D
}
