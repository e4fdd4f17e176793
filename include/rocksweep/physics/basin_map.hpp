#pragma once
/// A map of basins of attraction: free rocking from every state of a grid (theta / alpha across,
/// theta_dot / p up), integrated by the kernel and predicted by the energy argument (basin.hpp).
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "rocksweep/physics/basin.hpp"
#include "rocksweep/physics/integrator.hpp"
#include "rocksweep/grid/sweep.hpp"

namespace rocksweep {

/// Initial states: row i holds theta_dot / p = theta_dot_ratio.at(i), column j theta / alpha =
/// theta_ratio.at(j); maps are [rows][columns] in C order.
struct BasinGrid {
    Axis theta_ratio;
    Axis theta_dot_ratio;
    std::size_t size() const { return theta_ratio.points * theta_dot_ratio.points; }
};

/// `block` with `anchorage` in free rocking: the ground at rest from t = 0 (a constant pulse of
/// zero length, so that the adaptive law is that of free oscillation, Eq. 22, throughout).
CellModel free_rocking_cell(const Block& block, const Anchorage& anchorage, Equations equations,
                            double impact_threshold);

/// `free` started from the state of cell `index` (row-major) of `grid`.
CellModel basin_cell(const CellModel& free, const BasinGrid& grid, std::size_t index);

/// Outcome codes (outcome.hpp) of every cell of `grid`, integrated `lanes` cells at a time.
std::vector<std::uint8_t> simulate_basin(const CellModel& free, const BasinGrid& grid,
                                         const IntegratorSettings& settings, int lanes = 8);

/// Outcome codes of every cell of `grid` by the energy argument.
std::vector<std::uint8_t> predict_basin(const BasinEnergy& energy, const CellModel& free, const BasinGrid& grid);

/// Share of the codes that are `safe`: the area of the rest basin on the grid.
double rest_fraction(std::span<const std::uint8_t> codes);

/// Simulated against predicted, cell by cell. A cell is clear when the prediction is the same at
/// the eight points `margin` (a fraction of each axis's span) around it: it lies farther than
/// that from every boundary of the energy argument.
struct BasinComparison {
    std::size_t cells = 0;
    std::size_t clear = 0, clear_disagree = 0;  ///< clear cells, and those where the two differ
    std::size_t near = 0, near_disagree = 0;    ///< the others
};
BasinComparison compare_basin(const BasinEnergy& energy, const CellModel& free, const BasinGrid& grid,
                              std::span<const std::uint8_t> simulated, std::span<const std::uint8_t> predicted,
                              double margin);

}  // namespace rocksweep
