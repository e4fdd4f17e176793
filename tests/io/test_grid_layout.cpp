// A result grid laid out from a list of axes: any number of axes, each a dimension scale of
// the group attached to its dimension, and the difference test a resume relies on.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "rocksweep/io/grid_layout.hpp"
#include "rocksweep/io/hdf5.hpp"
#include "test_support.hpp"

using namespace rocksweep;
using rocksweep::testing::TempDir;

namespace {

// Three axes of different lengths, so that a swapped dimension changes the shape.
std::vector<GridAxis> three_axes() {
    return {{"amplitude_ratio", "1", "a_p0 / (alpha g)", {1.0, 2.0}},
            {"omega_ratio", "1", "omega_p / p", {1.0, 4.0, 7.0}},
            {"duration_s", "s", "pulse duration", {0.1, 0.2, 0.3, NAN}}};
}

}  // namespace

TEST(GridLayout, ThreeAxesNeedNoOtherCode) {
    TempDir dir;
    const std::string path = dir.file("grid.h5");
    const std::vector<GridAxis> axes = three_axes();
    std::vector<std::int32_t> values(24);
    for (std::size_t i = 0; i < values.size(); ++i) values[i] = static_cast<std::int32_t>(100 + i);
    {
        h5::File f = h5::File::create(path);
        {
            const h5::Group g = f.create_group("case");
            const GridGroup grid(g, axes);
            EXPECT_EQ(grid.cell_count(), 24u);
            grid.write<std::int32_t>("count", values);
            EXPECT_THROW(grid.write<std::int32_t>("short", std::span<const std::int32_t>(values).first(23)),
                         std::invalid_argument);
        }
        f.close();
    }
    const h5::File f = h5::File::open_read_only(path);
    const h5::Group g = f.open_group("case");
    const h5::ArrayN<std::int32_t> back = h5::read_array<std::int32_t>(g, "count");
    EXPECT_EQ(back.dims, (std::vector<hsize_t>{2, 3, 4}));
    EXPECT_EQ(back.values, values);  // C order: the last axis varies fastest
    const h5::Dataset ds = g.open_dataset("count");
    EXPECT_EQ(h5::read_string_attribute(ds, "dimensions"), "amplitude_ratio, omega_ratio, duration_s");
    for (unsigned d = 0; d < axes.size(); ++d) {
        const h5::Dataset scale = g.open_dataset(axes[d].name);
        EXPECT_EQ(h5::read_string_attribute(scale, "units"), axes[d].units);
        EXPECT_EQ(h5::read_string_attribute(scale, "long_name"), axes[d].long_name);
        for (unsigned other = 0; other < axes.size(); ++other)
            EXPECT_EQ(h5::is_attached(ds, scale, other), other == d) << axes[d].name << " on dimension " << other;
    }
    EXPECT_EQ(axes_difference(g, axes), "");  // NaN matches NaN
}

TEST(GridLayout, DifferencesAreNamedInWords) {
    TempDir dir;
    const std::string path = dir.file("grid.h5");
    {
        h5::File f = h5::File::create(path);
        {
            const h5::Group g = f.create_group("case");
            const std::vector<GridAxis> axes = three_axes();
            const GridGroup grid(g, axes);
        }
        f.close();
    }
    const h5::File f = h5::File::open_read_only(path);
    const h5::Group g = f.open_group("case");
    std::vector<GridAxis> more = three_axes();
    more[1].values.push_back(10.0);
    EXPECT_EQ(axes_difference(g, more), "omega_ratio has 3 points in the file, 4 in the config");
    std::vector<GridAxis> moved = three_axes();
    moved[2].values[1] = 0.25;
    EXPECT_EQ(axes_difference(g, moved), "duration_s[1] is 0.2 in the file, 0.25 in the config");
    std::vector<GridAxis> absent = three_axes();
    absent[0].name = "phase_rad";
    EXPECT_THROW(axes_difference(g, absent), Hdf5Error);
    EXPECT_EQ(dims_text(grid_dims(three_axes())), "2 x 3 x 4");
}
