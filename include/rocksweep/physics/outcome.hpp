#pragma once
/// What one run of one cell tells (physics.md §5).
#include <bit>
#include <cstdint>
#include <string>

namespace rocksweep {

enum class Outcome : std::uint8_t {
    safe = 0,
    overturned_impact = 1,     ///< mode 1: at least one impact before overturning
    overturned_no_impact = 2,  ///< mode 2: overturned without impact
    not_converged = 255,       ///< hit the step cap; a runaway cell, not a result
};
std::string to_string(Outcome o);

/// Bits of CellResult::broken.
inline constexpr std::uint8_t broken_left = 1;   ///< spring working for theta > 0
inline constexpr std::uint8_t broken_right = 2;  ///< spring working for theta < 0

/// Trivially copyable: the scheduler moves these as bytes.
struct CellResult {
    double max_rotation = 0.0;      ///< max |theta| / alpha
    double t_overturn_s = 0.0;      ///< time |theta| reached pi/2; NaN if it did not
    double peak_force_ratio = 0.0;  ///< max anchorage force / F_u; NaN without anchorage
    double mu_required = 0.0;       ///< max |f_x / f_y| at the base: friction needed to rock without sliding
    std::int32_t impacts = 0;       ///< impacts with approach speed above the threshold
    std::int32_t impacts_total = 0; ///< every impact integrated, settling ones included
    std::int64_t steps = 0;         ///< RK4 steps taken (trial steps of event searches included)
    Outcome outcome = Outcome::safe;
    std::uint8_t broken = 0;        ///< broken_left | broken_right
    std::uint8_t pivot_uplift = 0;  ///< 1 if the pivot's vertical reaction went negative (model invalid)
    /// 1: a rerun perturbed in its input changed the outcome or damage state. Never set by the
    /// integrator: the suite's --check-sensitivity sets it (records/suite_sweep.hpp).
    std::uint8_t sensitive = 0;
};

/// True if every field holds the same bits (NaN included): what "identical results" means.
inline bool bitwise_equal(const CellResult& a, const CellResult& b) {
    auto bits = [](double x) { return std::bit_cast<std::uint64_t>(x); };
    return bits(a.max_rotation) == bits(b.max_rotation) && bits(a.t_overturn_s) == bits(b.t_overturn_s) &&
           bits(a.peak_force_ratio) == bits(b.peak_force_ratio) && a.impacts == b.impacts &&
           a.impacts_total == b.impacts_total && a.steps == b.steps && a.outcome == b.outcome && a.broken == b.broken &&
           bits(a.mu_required) == bits(b.mu_required) && a.pivot_uplift == b.pivot_uplift &&
           a.sensitive == b.sensitive;
}

}  // namespace rocksweep
