#pragma once
/// Recorded ground motions from two-column text files (time [s], horizontal acceleration).
#include <string>

#include "rocksweep/excitation.hpp"

namespace rocksweep {

/// Reads `path` as a record pulse for a block under gravity `gravity` [m/s^2]. `units` is the
/// unit of the second column, "g" (standard gravity, 9.80665 m/s^2) or "m/s^2": it is never
/// guessed. Samples must start at t = 0 and be evenly spaced. Throws InputError naming the
/// file and line for anything else.
Pulse read_record(const std::string& path, const std::string& units, double scale, double gravity);

}  // namespace rocksweep
