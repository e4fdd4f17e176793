#pragma once
/// The anchorage parameters a point of a grid may set (sweep --axis), each unset where no axis
/// sets it: the scenario's own value then holds (block_family.hpp applies them).
#include <optional>

namespace rocksweep {

/// What a grid point sets of every anchorage, where an axis sets it (sweep --axis).
struct AnchorageSetting {
    std::optional<double> strength_ratio;  ///< F_u / (m g)
    std::optional<double> theta_f_ratio;   ///< theta_f / alpha of the (K_max) spring
    std::optional<double> kmin_ratio;      ///< K_min / K_max of an adaptive anchorage
    std::optional<double> stiffness_n_m;   ///< K (K_max of an adaptive one) [N/m]; theta_f follows from F_u
    bool any() const { return strength_ratio || theta_f_ratio || kmin_ratio || stiffness_n_m; }
};

}  // namespace rocksweep
