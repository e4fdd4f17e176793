// The planes refinement works on: every cell of a scenario in exactly one plane, at the place C
// order gives it, for any pair of axes.
#include "rocksweep/grid/refine_planes.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace rocksweep {
namespace {

TEST(RefinePlanes, EveryCellIsInExactlyOnePlaneForAnyPair) {
    const std::vector<std::size_t> sizes{3, 4, 5, 2};
    for (std::size_t row = 0; row < 4; ++row)
        for (std::size_t col = row + 1; col < 4; ++col) {
            const RefinePlanes planes(sizes, row, col);
            EXPECT_EQ(planes.count() * planes.rows() * planes.cols(), 120u);
            std::vector<int> seen(120, 0);
            for (std::size_t j = 0; j < planes.count(); ++j)
                for (std::size_t r = 0; r < planes.rows(); ++r)
                    for (std::size_t c = 0; c < planes.cols(); ++c) {
                        const std::size_t cell = planes.cell(j, r, c);
                        ASSERT_LT(cell, 120u);
                        ++seen[cell];
                        EXPECT_GE(cell, planes.first(j));
                        EXPECT_LT(cell, planes.first(j) + planes.span());
                    }
            for (int n : seen) EXPECT_EQ(n, 1) << "row axis " << row << ", col axis " << col;
            EXPECT_EQ(planes.contiguous(), row == 2 && col == 3);
        }
}

TEST(RefinePlanes, CellsFollowCOrder) {
    // Axes (a, b, c) of sizes 3 x 4 x 5, refined over (a, c): plane j is b = j.
    const RefinePlanes planes({3, 4, 5}, 0, 2);
    EXPECT_EQ(planes.count(), 4u);
    EXPECT_EQ(planes.cell(2, 1, 3), 1u * 20 + 2u * 5 + 3u);
    EXPECT_EQ(planes.first(3), 15u);
    EXPECT_THROW(RefinePlanes({3, 4}, 1, 1), std::invalid_argument);
    EXPECT_THROW(RefinePlanes({3, 4}, 1, 0), std::invalid_argument);
}

}  // namespace
}  // namespace rocksweep
