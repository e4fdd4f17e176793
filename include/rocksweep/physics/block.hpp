#pragma once
/// The rigid block: geometry, mass distribution and impact law (physics.md §1).
#include <optional>

namespace rocksweep {

/// An equivalent rectangular block. Angles in rad, lengths in m, mass in kg.
struct Block {
    double radius_m;       ///< R: pivot corner to centre of mass
    double alpha_rad;      ///< slenderness angle, atan(b/h)
    double inertia_ratio;  ///< I0 / (m R^2); 4/3 for a uniform rectangle
    double mass_kg;
    double gravity;        ///< g [m/s^2]
    double e;              ///< angular-velocity ratio at impact, 0 < e <= Housner's

    double p() const;               ///< frequency parameter sqrt(m g R / I0) [rad/s]
    double half_width_m() const;    ///< b = R sin(alpha)
    double half_height_m() const;   ///< h = R cos(alpha)
    double inertia() const;         ///< I0 [kg m^2]
    double housner_e() const;       ///< 1 - 2 sin^2(alpha) / inertia_ratio (Eq. 14)
};

/// Above this height-to-width ratio h/b (a needle) the uplift threshold and the settling
/// speed, both proportional to alpha, approach the rounding of theta: refused, not integrated.
inline constexpr double max_height_to_width = 1e4;
/// The same bound as a slenderness angle, atan(1 / max_height_to_width) = atan(1e-4), which
/// differs from 1e-4 in its ninth digit (a bound of exactly 1e-4 refused h/b = 1e4 itself).
inline constexpr double min_alpha_rad = 9.999999966666667e-05;
/// I0/(m R^2) above this puts nearly all the mass far outside the block's outline; it also
/// keeps p = sqrt(g / (ratio R)) away from 0, where every pulse would look infinitely fast.
inline constexpr double max_inertia_ratio = 1e4;

/// Housner's e for a block of this slenderness and mass distribution.
double housner_e(double alpha_rad, double inertia_ratio);

/// Rectangle of half-width b and half-height h. `e` defaults to Housner's value.
/// Throws InputError if a size is not positive and finite, alpha < min_alpha_rad, e exceeds
/// Housner's, or Housner's e <= 0. Field ids are neutral ("block.half_width", "block.alpha",
/// ...): the app layer names the option the user wrote.
Block rectangular_block(double b_m, double h_m, double mass_kg, double gravity = 9.81,
                        std::optional<double> e = std::nullopt);

/// Equivalent block from R, alpha and I0/(mR^2). Same checks as rectangular_block.
Block equivalent_block(double radius_m, double alpha_rad, double inertia_ratio, double mass_kg,
                       double gravity = 9.81, std::optional<double> e = std::nullopt);

/// I0/(mR^2) that gives frequency parameter p for a block of radius R.
double inertia_ratio_from_p(double p, double radius_m, double gravity);

}  // namespace rocksweep
