// Boundary refinement on synthetic outcome maps: exact where the boundary is resolved, and a
// small fraction of the cells computed.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

#include "rocksweep/grid/refine.hpp"

using namespace rocksweep;

namespace {

struct RunStats {
    std::size_t computed = 0, wrong = 0, pending = 0;
};

RunStats refine(std::size_t rows, std::size_t cols, std::size_t stride, bool halo,
                const std::function<std::uint8_t(std::size_t, std::size_t)>& truth) {
    Refinement ref(rows, cols, stride, halo);
    std::vector<std::uint8_t> outcome(rows * cols, 0), done(rows * cols, cell_pending);
    RunStats st;
    for (int k = 0; k < ref.passes(); ++k) {
        for (std::size_t i : ref.cells_for_pass(k, outcome.data(), done.data())) {
            EXPECT_EQ(done[i], cell_pending) << "computed twice";
            outcome[i] = truth(i / cols, i % cols);
            done[i] = cell_computed;
            ++st.computed;
        }
    }
    ref.fill(outcome.data(), done.data());
    for (std::size_t i = 0; i < rows * cols; ++i) {
        st.wrong += outcome[i] != truth(i / cols, i % cols);
        st.pending += done[i] == cell_pending;
    }
    return st;
}

}  // namespace

TEST(Refinement, SmoothBoundariesAreExactWithFewCellsComputed) {
    // Two bands like an overturning spectrum: a curve and a band below it.
    auto truth = [](std::size_t i, std::size_t j) -> std::uint8_t {
        const double x = j / 999.0, y = i / 999.0;
        if (y > 0.2 + 0.6 * x * x) return 2;
        if (y > 0.1 + 0.3 * x && y < 0.15 + 0.45 * x) return 1;
        return 0;
    };
    const RunStats st = refine(1000, 1000, 32, true, truth);
    EXPECT_EQ(st.pending, 0u);
    EXPECT_EQ(st.wrong, 0u);
    EXPECT_LT(st.computed, 100000u);  // under 10 % of the grid
}

TEST(Refinement, GridsThatAreNotPowersOfTwoAndDegenerateOnes) {
    auto truth = [](std::size_t i, std::size_t j) -> std::uint8_t { return (i * 7 + j * 3) > 200 ? 1 : 0; };
    for (std::size_t rows : {1u, 2u, 33u, 50u})
        for (std::size_t cols : {1u, 3u, 65u, 77u}) {
            const RunStats st = refine(rows, cols, 8, true, truth);
            EXPECT_EQ(st.pending, 0u) << rows << "x" << cols;
            EXPECT_EQ(st.wrong, 0u) << rows << "x" << cols;
        }
}

TEST(Refinement, HaloCatchesAnIslandNextToTheBoundary) {
    // A 5 x 5 island one coarse square away from a straight boundary, between the corners.
    auto truth = [](std::size_t i, std::size_t j) -> std::uint8_t {
        if (i >= 36 && i <= 40 && j >= 40 && j <= 44) return 0;
        return i > 20 ? 1 : 0;
    };
    EXPECT_EQ(refine(100, 100, 16, true, truth).wrong, 0u);
    EXPECT_EQ(refine(100, 100, 16, false, truth).wrong, 25u);  // without the halo it is missed
}

TEST(Refinement, RejectsAStrideThatIsNotAPowerOfTwo) {
    EXPECT_THROW(Refinement(10, 10, 6), std::invalid_argument);
    EXPECT_THROW(Refinement(10, 10, 1), std::invalid_argument);
}
