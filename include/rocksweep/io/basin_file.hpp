#pragma once
/// The HDF5 file of `rocksweep basin`:
///   /axes/theta_ratio, theta_dot_ratio, curve_theta_ratio   dimension scales (units "1")
///   /basins/<scenario>/outcome, outcome_predicted   uint8 [n_theta_dot][n_theta], flag_values
///   /basins/<scenario>/no_impact_boundary, impact_boundary   theta_dot / p at curve_theta_ratio
///   /provenance   version and the effective config
/// Root attributes: the block (p_rad_s, alpha_rad, e, ...) and the numerics; scenario attributes:
/// the anchorage, rest_fraction and the counts of the cell-by-cell comparison.
#include <string>
#include <vector>

#include "rocksweep/physics/basin_map.hpp"
#include "rocksweep/grid/sweep.hpp"

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
