#include "rocksweep/physics/basin_map.hpp"

#include <algorithm>
#include <stdexcept>

namespace rocksweep {

CellModel free_rocking_cell(const Block& block, const Anchorage& anchorage, Equations equations,
                            double impact_threshold) {
    Pulse rest;
    rest.kind = PulseKind::constant;
    rest.ax_g = 0.0;
    rest.duration_s = 0.0;
    return make_cell_model(block, anchorage, rest, equations, impact_threshold);
}

CellModel basin_cell(const CellModel& free, const BasinGrid& grid, std::size_t index) {
    CellModel c = free;
    c.theta0 = grid.theta_ratio.at(index % grid.theta_ratio.points) * free.alpha;
    c.theta_dot0 = grid.theta_dot_ratio.at(index / grid.theta_ratio.points) * free.p();
    return c;
}

std::vector<std::uint8_t> simulate_basin(const CellModel& free, const BasinGrid& grid,
                                         const IntegratorSettings& settings, int lanes) {
    std::vector<CellModel> cells(grid.size());
    for (std::size_t i = 0; i < cells.size(); ++i) cells[i] = basin_cell(free, grid, i);
    std::vector<CellResult> results(cells.size());
    integrate_cells(cells, results, settings, lanes);
    std::vector<std::uint8_t> codes(results.size());
    std::transform(results.begin(), results.end(), codes.begin(),
                   [](const CellResult& r) { return static_cast<std::uint8_t>(r.outcome); });
    return codes;
}

std::vector<std::uint8_t> predict_basin(const BasinEnergy& energy, const CellModel& free, const BasinGrid& grid) {
    std::vector<std::uint8_t> codes(grid.size());
    for (std::size_t i = 0; i < codes.size(); ++i) {
        const CellModel c = basin_cell(free, grid, i);
        codes[i] = static_cast<std::uint8_t>(energy.outcome(c.theta0, c.theta_dot0));
    }
    return codes;
}

double rest_fraction(std::span<const std::uint8_t> codes) {
    if (codes.empty()) return 0.0;
    const auto safe = std::count(codes.begin(), codes.end(), static_cast<std::uint8_t>(Outcome::safe));
    return static_cast<double>(safe) / static_cast<double>(codes.size());
}

BasinComparison compare_basin(const BasinEnergy& energy, const CellModel& free, const BasinGrid& grid,
                              std::span<const std::uint8_t> simulated, std::span<const std::uint8_t> predicted,
                              double margin) {
    if (simulated.size() != grid.size() || predicted.size() != grid.size())
        throw std::invalid_argument("compare_basin: maps and grid differ in size");
    const double d_theta = margin * (grid.theta_ratio.hi - grid.theta_ratio.lo) * free.alpha;
    const double d_rate = margin * (grid.theta_dot_ratio.hi - grid.theta_dot_ratio.lo) * free.p();
    BasinComparison c;
    c.cells = grid.size();
    for (std::size_t i = 0; i < grid.size(); ++i) {
        const CellModel cell = basin_cell(free, grid, i);
        bool clear = true;
        for (int a = -1; a <= 1 && clear; ++a)
            for (int b = -1; b <= 1 && clear; ++b) {
                const double th = cell.theta0 + a * d_theta;
                // The prediction needs |theta| < pi/2; a margin that reaches past it is not clear.
                clear = std::abs(th) < M_PI / 2 &&
                        static_cast<std::uint8_t>(energy.outcome(th, cell.theta_dot0 + b * d_rate)) == predicted[i];
            }
        const bool differ = simulated[i] != predicted[i];
        (clear ? c.clear : c.near) += 1;
        (clear ? c.clear_disagree : c.near_disagree) += differ ? 1 : 0;
    }
    return c;
}

}  // namespace rocksweep
