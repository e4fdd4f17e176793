#pragma once
/// The design criterion: the share of a hazard over which an anchored block is acceptable — it
/// does not overturn and it meets the conservator's limits on rotation and on the force the
/// anchorage puts on it. The hazard is a region (a rectangle of the one-sine pulse plane
/// ω_p/p × a_p0/(αg)) or the runs of a record suite over its intensity levels.
#include <cstddef>
#include <vector>

#include "rocksweep/grid/sweep.hpp"

namespace rocksweep {

/// Limits beyond "does not overturn"; 0 means no limit.
struct DesignConstraints {
    double max_rotation_ratio = 0.0;  ///< max |theta| / alpha allowed
    double max_force_ratio = 0.0;     ///< peak anchorage force / F_u allowed: the object's own limit / F_u
};

/// Area a node of an axis stands for: half the gaps to its neighbours (the ends own only the
/// half-gap inside the range), so that the weights of an axis sum to hi - lo; 1 for a
/// one-point axis. The trapezoid rule, the area of each node's cell clipped to the range.
std::vector<double> node_weights(const Axis& axis);

/// A scenario over the region, as area fractions in [0, 1].
struct RegionScore {
    double acceptable = 0.0;  ///< safe and within every limit: the criterion
    double standing = 0.0;    ///< safe (not overturned), limits ignored
};

/// Scores scenario `scenario` of `spec` from the sweep's results `r`. A cell is acceptable if
/// its outcome is safe, max_rotation <= max_rotation_ratio and peak_force_ratio <=
/// max_force_ratio (NaN, a free block's, meets any force limit). A not-converged cell (255)
/// counts as not safe. Throws std::invalid_argument if a cell is pending, or if a limit is set
/// and a cell's outcome was inferred by refinement (it carries no rotation or force).
RegionScore score_scenario(const SweepSpec& spec, const SweepResults& r, std::size_t scenario,
                           const DesignConstraints& c);

/// Per level of one block of a record suite, whose runs are cells [record, level] from `first`
/// (C order): the share of the records acceptable and standing at each level, the fragility
/// that a hazard curve turns into an annual rate (design --hazard, docs/risk.md).
std::vector<RegionScore> score_levels(const SweepResults& r, std::size_t first, std::size_t records, std::size_t levels,
                                      const DesignConstraints& c);

/// The same over cells [first, first + count) of `r`, each of equal weight: the share of the
/// runs of a record suite (every record at every level counts once) that are acceptable.
RegionScore score_cells(const SweepResults& r, std::size_t first, std::size_t count, const DesignConstraints& c);

}  // namespace rocksweep
