#pragma once
/// A checksum of a file's result datasets, stored when the run that wrote them finishes, so that
/// `merge` can tell a part whose data changed since (an edit, a bad copy) from one it can trust.
/// FNV-1a over bytes: the same cells give the same value whatever the rank count or chunking.
#include <cstddef>
#include <cstdint>

#include "rocksweep/grid/sweep.hpp"

namespace rocksweep {

/// The scenario group's int64 attribute holding the checksum's 64 bits (two's complement);
/// 0: none (a run that has not finished, or a file from before it was stored).
inline constexpr const char* results_checksum_attribute = "results_fnv1a64";

/// 64-bit FNV-1a (Fowler, Noll, Vo), fed bytes in order.
class Fnv1a64 {
public:
    void add(const void* data, std::size_t bytes) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < bytes; ++i) hash_ = (hash_ ^ p[i]) * 0x100000001b3ULL;
    }
    std::uint64_t value() const { return hash_; }
    /// As stored: the same bits as an int64.
    std::int64_t stored() const { return static_cast<std::int64_t>(hash_); }

private:
    std::uint64_t hash_ = 0xcbf29ce484222325ULL;
};

/// The checksum of cells [first, first + count) (one scenario's): the bytes of each result
/// column in turn, in the file's order (outcome, max_rotation, impacts, impacts_total,
/// t_overturn, peak_force_ratio, broken, mu_required, pivot_uplift, done), as stored.
std::int64_t results_checksum(const SweepResults& r, std::size_t first, std::size_t count);

}  // namespace rocksweep
