#pragma once
/// `rocksweep info`: the block's derived values (alpha, p, e, ...), the grid with its parameter
/// axes, and every scenario's anchorage (K, F_u, theta_f), for the config as given.
#include <ostream>

#include "rocksweep/app/options.hpp"

namespace rocksweep {

/// Writes the report to `out`. Throws InputError as make_sweep_spec.
void print_info(const Options& o, std::ostream& out);

}  // namespace rocksweep
