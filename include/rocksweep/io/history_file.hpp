#pragma once
/// One time history on disk: HDF5 (datasets with units, `t` as dimension scale) or CSV.
/// Layout: docs/hdf5.md.
#include <string>
#include <utility>
#include <vector>

#include "rocksweep/physics/history.hpp"

namespace rocksweep {

/// Writes `h` to `path` (via path + ".tmp" and a rename): datasets t, theta, theta_dot, k_left,
/// k_right, ground_acc, w_excitation, w_anchorage with `units` attributes, `t` attached as the
/// dimension scale of the others; root attributes with h.result; then `string_attrs` and
/// `number_attrs` as root attributes (a caller's attribute replaces one of ours of the same
/// name). Throws std::invalid_argument if the columns differ in length, InputError for an
/// output location that cannot be written, Hdf5Error otherwise.
void write_history_h5(const std::string& path, const History& h,
                      const std::vector<std::pair<std::string, std::string>>& string_attrs,
                      const std::vector<std::pair<std::string, double>>& number_attrs);

/// Writes `h` as CSV (via path + ".tmp" and a rename): a header naming each column with its
/// unit (t_s,theta_rad,...), then one row per sample at full precision (%.17g; NaN as "nan").
/// Throws std::invalid_argument if the columns differ in length, InputError if `path` cannot
/// be created, std::runtime_error ("cannot write PATH: ...") if writing fails.
void write_history_csv(const std::string& path, const History& h);

}  // namespace rocksweep
