#pragma once
/// One part of a sweep split over independent jobs (a Slurm job array): which cells a part
/// computes. The parts are joined afterwards by `rocksweep merge`.
#include <cstddef>
#include <string>
#include <vector>

#include "rocksweep/parallel/scheduler.hpp"

namespace rocksweep {

/// Part `index` (1-based) of `count`.
struct WorkPart {
    std::size_t index = 1, count = 1;
};

/// Parses "K/N" with 1 <= K <= N <= 1e6; throws InputError("part", text, ...) otherwise.
WorkPart parse_work_part(const std::string& text);

/// Cells are dealt to the parts in blocks of this many consecutive indices, round robin: cost
/// varies smoothly over a spectrum (slow near the overturning boundary), so interleaved blocks
/// give every part a similar mix, while a block keeps a chunk's cells together.
inline constexpr std::size_t kPartBlock = 256;

/// The cells of `todo` that belong to `part`, as ranges in increasing order. The parts of one
/// `todo` are disjoint and together cover it.
std::vector<IndexRange> restrict_to_part(const std::vector<IndexRange>& todo, WorkPart part);

/// Number of cells in [0, total) that belong to `part`.
std::size_t cells_in_part(std::size_t total, WorkPart part);

}  // namespace rocksweep
