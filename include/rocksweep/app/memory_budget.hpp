#pragma once
/// Refusing up front what would not fit in memory: estimate, compare, say both figures.
#include <cstdint>
#include <string>

namespace rocksweep {

/// Half of this machine's physical memory [bytes]: what one run may plan to hold, leaving the
/// rest to the system, other ranks on the node and the HDF5 library's buffers.
double memory_budget_bytes();

/// 412e9 -> "412 GB", 1.5e6 -> "1.5 MB" (decimal units, 3 significant figures).
std::string format_bytes(double bytes);

/// Throws InputError(field, value, "... needs about X, more than half of this machine's Y")
/// when `bytes` exceeds memory_budget_bytes(). `what` says what would be held ("1e11
/// samples of 8 columns").
void require_memory(const std::string& field, const std::string& value, double bytes, const std::string& what);

}  // namespace rocksweep
