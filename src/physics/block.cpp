#include "rocksweep/physics/block.hpp"

#include <cmath>

#include "rocksweep/core/errors.hpp"

namespace rocksweep {

double housner_e(double alpha_rad, double inertia_ratio) {
    const double s = std::sin(alpha_rad);
    return 1.0 - 2.0 * s * s / inertia_ratio;
}

double Block::p() const { return std::sqrt(gravity / (inertia_ratio * radius_m)); }
double Block::half_width_m() const { return radius_m * std::sin(alpha_rad); }
double Block::half_height_m() const { return radius_m * std::cos(alpha_rad); }
double Block::inertia() const { return inertia_ratio * mass_kg * radius_m * radius_m; }
double Block::housner_e() const { return rocksweep::housner_e(alpha_rad, inertia_ratio); }

namespace {

/// The block of equivalent_block after its angle is checked (rectangular_block checks h/b instead).
Block block_of_angle(double radius_m, double alpha_rad, double inertia_ratio, double mass_kg, double gravity,
                     std::optional<double> e) {
    // I0 about a corner is at least m R^2 (all mass at the centre of mass).
    require_closed("block.inertia_ratio", inertia_ratio, 1.0, max_inertia_ratio, "1 <= I0/(m R^2) <= 1e4");
    require_open("block.mass", mass_kg, 0.0, INFINITY, "a finite mass > 0 kg");
    require_open("block.gravity", gravity, 0.0, INFINITY, "a finite acceleration > 0 m/s^2");
    Block b{radius_m, alpha_rad, inertia_ratio, mass_kg, gravity, 0.0};
    const double eh = b.housner_e();
    if (!(eh > 0.0))
        throw InputError("block.alpha", format_number(alpha_rad),
                         "a block that can rock: Housner's e = 1 - 2 sin^2(alpha) m R^2 / I0 = " +
                             format_number(eh) + " must be > 0 (the block is too squat)");
    if (e) {
        if (!(*e > 0.0 && *e <= eh))
            throw InputError("block.restitution", format_number(*e), "0 < e <= Housner's value " + format_number(eh));
        b.e = *e;
    } else {
        b.e = eh;
    }
    return b;
}

}  // namespace

Block equivalent_block(double radius_m, double alpha_rad, double inertia_ratio, double mass_kg,
                       double gravity, std::optional<double> e) {
    require_open("block.radius", radius_m, 0.0, INFINITY, "a finite length > 0 m");
    if (!(alpha_rad >= min_alpha_rad && alpha_rad < M_PI / 2))
        throw InputError("block.alpha", format_number(alpha_rad), "an angle in [atan(1e-4), pi/2) rad (h/b <= 1e4)");
    return block_of_angle(radius_m, alpha_rad, inertia_ratio, mass_kg, gravity, e);
}

Block rectangular_block(double b_m, double h_m, double mass_kg, double gravity, std::optional<double> e) {
    require_open("block.half_width", b_m, 0.0, INFINITY, "a finite length > 0 m");
    require_open("block.half_height", h_m, 0.0, INFINITY, "a finite length > 0 m");
    const double alpha = std::atan2(b_m, h_m);
    // The ratio itself, as documented: atan2 of an h/b of exactly 1e4 may round below min_alpha_rad.
    if (!(h_m / b_m <= max_height_to_width))
        throw InputError("block.half_height", format_number(h_m) + " (with b = " + format_number(b_m) + " m)",
                         "h / b <= 1e4 (a slenderness angle atan(b/h) >= atan(1e-4))");
    if (!(housner_e(alpha, 4.0 / 3.0) > 0.0))
        throw InputError("block.half_width", format_number(b_m) + " (with h = " + format_number(h_m) + " m)",
                         "a block that can rock: b/h < sqrt(2) (Housner's e = 1 - 3/2 sin^2(alpha) = " +
                             format_number(housner_e(alpha, 4.0 / 3.0)) + " must be > 0)");
    return block_of_angle(std::hypot(b_m, h_m), alpha, 4.0 / 3.0, mass_kg, gravity, e);
}

double inertia_ratio_from_p(double p, double radius_m, double gravity) {
    require_open("block.p", p, 0.0, INFINITY, "a finite p > 0 rad/s");
    return gravity / (p * p * radius_m);
}

}  // namespace rocksweep
