// The record suite the suite benchmarks compute: configs/suite_smatteo.toml's (S. Matteo, the
// shared records of a suite CSV, PGA levels 0.05-1.5 g, block sizes R = 0.39-3.89 m at its
// slenderness, free / constant theta_f = alpha / adaptive rho = 0.1, F_u = 0.4 m g), built in
// code so that a driver times the cells and nothing else. Shared by suite_lanes.cpp (old tree
// against new) and suite_peers.cpp (methods against each other).
#pragma once

#include <string>
#include <vector>

#include "rocksweep/physics/anchorage.hpp"
#include "rocksweep/records/suite_sweep.hpp"

namespace rocksweep::bench {

/// `levels` PGA levels and `radii` block sizes (1: the block's own R = 1.3927 m).
inline SuiteSpec smatteo_suite(const std::string& records_csv, std::size_t levels, std::size_t radii) {
    const Block b = rectangular_block(0.30, 1.36, 3361.0);
    const double fu = 0.4 * b.mass_kg * b.gravity;
    std::vector<Scenario> scenarios{{"free", free_anchorage(), 0.0, 1.0},
                                    {"constant_tf1", constant_anchorage(b, fu, b.alpha_rad), 1.0, 1.0},
                                    {"adaptive_rho0.1", adaptive_anchorage(b, fu, b.alpha_rad, 0.1), 1.0, 0.1}};
    const Axis radius{0.392695228684288, 3.892695228684288, radii};
    std::vector<double> r_m = radii == 1 ? std::vector<double>{b.radius_m} : radius.values();
    return make_suite_spec(records_csv, b, scenarios, IntensityMeasure::pga_g, Axis{0.05, 1.5, levels}, r_m);
}

}  // namespace rocksweep::bench
