#include "rocksweep/grid/work_part.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "rocksweep/core/errors.hpp"

using namespace rocksweep;

namespace {

std::vector<int> owners(std::size_t total, const std::vector<IndexRange>& todo, std::size_t parts) {
    std::vector<int> owner(total, 0);
    for (std::size_t k = 1; k <= parts; ++k)
        for (const IndexRange& r : restrict_to_part(todo, {k, parts}))
            for (std::size_t i = r.first; i < r.first + r.count; ++i) owner[i] += static_cast<int>(k) * 1000 + 1;
    return owner;
}

}  // namespace

TEST(WorkPart, PartsAreDisjointAndCoverEveryCellOfTheWorkList) {
    // Ranges that start and end inside blocks, a gap, and a single cell.
    const std::vector<IndexRange> todo{{3, 700}, {900, 1}, {1000, 2000}};
    for (std::size_t parts : {1u, 2u, 3u, 7u, 50u}) {
        const auto owner = owners(3000, todo, parts);
        for (std::size_t i = 0; i < 3000; ++i) {
            const bool wanted = (i >= 3 && i < 703) || i == 900 || i >= 1000;
            if (!wanted) {
                EXPECT_EQ(owner[i], 0) << "cell " << i << " of no range, parts " << parts;
                continue;
            }
            ASSERT_EQ(owner[i] % 1000, 1) << "cell " << i << " owned " << owner[i] % 1000 << " times, parts " << parts;
            const std::size_t k = static_cast<std::size_t>(owner[i] / 1000);
            EXPECT_EQ(k, (i / kPartBlock) % parts + 1) << "cell " << i;  // blocks dealt round robin
        }
    }
}

TEST(WorkPart, RangesAreSortedAndMergedAndTheCountsAddUp) {
    const auto r = restrict_to_part({{0, 10 * kPartBlock}}, {2, 3});
    ASSERT_EQ(r.size(), 3u);  // blocks 1, 4, 7
    EXPECT_EQ(r[0].first, kPartBlock);
    EXPECT_EQ(r[1].first, 4 * kPartBlock);
    EXPECT_EQ(r[2].count, kPartBlock);
    // One part only: the blocks of a range join into the range itself.
    const auto whole = restrict_to_part({{5, 1000}}, {1, 1});
    ASSERT_EQ(whole.size(), 1u);
    EXPECT_EQ(whole[0].first, 5u);
    EXPECT_EQ(whole[0].count, 1000u);
    std::size_t sum = 0;
    for (std::size_t k = 1; k <= 4; ++k) sum += cells_in_part(12345, {k, 4});
    EXPECT_EQ(sum, 12345u);
    EXPECT_EQ(cells_in_part(100, {2, 2}), 0u);  // fewer cells than one block: all in part 1
}

TEST(WorkPart, ParsesKOverNAndRefusesTheRest) {
    const WorkPart p = parse_work_part("3/10");
    EXPECT_EQ(p.index, 3u);
    EXPECT_EQ(p.count, 10u);
    for (const char* bad : {"", "3", "0/4", "5/4", "1/0", "a/b", "1/2/3", "-1/4", "1 /4", "1/2000000", "3/10x"}) {
        try {
            parse_work_part(bad);
            ADD_FAILURE() << "accepted '" << bad << "'";
        } catch (const InputError& e) {
            EXPECT_EQ(e.field(), "part");
            EXPECT_EQ(e.value(), bad);
        }
    }
}
