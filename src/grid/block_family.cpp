#include "rocksweep/grid/block_family.hpp"

#include <algorithm>
#include <cmath>

namespace rocksweep {

Block reshaped_block(const Block& configured, double alpha_rad, double radius_m) {
    const Block& c = configured;
    if (alpha_rad == c.alpha_rad && radius_m == c.radius_m) return c;
    const double f = radius_m / c.radius_m;
    const double mass = c.mass_kg * f * f * f * std::sin(2.0 * alpha_rad) / std::sin(2.0 * c.alpha_rad);
    const double eh = housner_e(alpha_rad, c.inertia_ratio);
    const double e = alpha_rad == c.alpha_rad ? c.e : std::min(eh, c.e / c.housner_e() * eh);
    return equivalent_block(radius_m, alpha_rad, c.inertia_ratio, mass, c.gravity, e);
}

Anchorage anchorage_on(const Scenario& s, const Block& configured, const Block& b, const AnchorageSetting& set) {
    const Anchorage& a = s.anchorage;
    if (a.kind == AnchorageKind::free) return free_anchorage();
    // F_u as configured on the configured block (the same bits as its scenario's), else its ratio.
    const bool same_weight = b.mass_kg == configured.mass_kg && b.gravity == configured.gravity;
    const double ratio = set.strength_ratio ? *set.strength_ratio : a.strength_n / (configured.mass_kg * configured.gravity);
    const double strength = same_weight && !set.strength_ratio ? a.strength_n : ratio * b.mass_kg * b.gravity;
    const double rho = set.kmin_ratio ? *set.kmin_ratio : s.kmin_ratio;
    if (set.stiffness_n_m && a.kind == AnchorageKind::constant) return constant_anchorage_k(b, strength, *set.stiffness_n_m);
    const double theta_f = set.stiffness_n_m   ? fracture_angle(b, strength, *set.stiffness_n_m)
                           : set.theta_f_ratio ? *set.theta_f_ratio * b.alpha_rad
                                               : s.theta_f_ratio * b.alpha_rad;
    if (a.kind == AnchorageKind::constant) return constant_anchorage(b, strength, theta_f);
    return adaptive_anchorage(b, strength, theta_f, rho, a.break_rule, a.law);
}

}  // namespace rocksweep
