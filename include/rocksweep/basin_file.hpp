#pragma once
/// The HDF5 file of `rocksweep basin` (docs/hdf5.md, "Basin files"): per scenario the simulated
/// and predicted outcome maps over (theta_dot / p, theta / alpha) and the energy boundaries.
#include <string>
#include <vector>

#include "rocksweep/basin_map.hpp"
#include "rocksweep/sweep.hpp"

namespace rocksweep {

/// One anchorage's basin map.
struct BasinScenario {
    Scenario scenario;
    CellModel cell;                     ///< free rocking, the state unset
    std::vector<std::uint8_t> simulated, predicted;  ///< outcome codes, [theta_dot][theta]
    std::vector<double> no_impact, impact;  ///< boundaries / p at each curve_theta_ratio
    BasinComparison comparison;
};

struct BasinFile {
    Block block{};
    Equations equations = Equations::nonlinear;
    IntegratorSettings settings;
    double impact_threshold = 1e-3;  ///< fraction of p alpha
    BasinGrid grid;
    Axis curve_theta_ratio;          ///< where the boundaries are given, theta / alpha
    double margin = 0.01;            ///< BasinComparison's margin, a fraction of each axis
    std::vector<BasinScenario> scenarios;
    std::string config_text, version;
};

/// Writes `f` to `path` through a file built in memory and renamed into place (hdf5.hpp's
/// publish_h5_atomically): no partial file is ever left. Throws like publish_h5_atomically.
void write_basin_file(const std::string& path, const BasinFile& f);

}  // namespace rocksweep
