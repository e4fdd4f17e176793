#include "rocksweep/block.hpp"

#include <cmath>

#include "rocksweep/errors.hpp"

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

Block equivalent_block(double radius_m, double alpha_rad, double inertia_ratio, double mass_kg,
                       double gravity, std::optional<double> e) {
    require_open("radius", radius_m, 0.0, INFINITY, "a length > 0 m");
    require_open("alpha", alpha_rad, 0.0, M_PI / 2, "an angle in (0, pi/2) rad");
    // I0 about a corner is at least m R^2 (all mass at the centre of mass).
    require_closed("inertia-ratio", inertia_ratio, 1.0, INFINITY, "I0/(m R^2) >= 1");
    require_open("mass", mass_kg, 0.0, INFINITY, "a mass > 0 kg");
    require_open("gravity", gravity, 0.0, INFINITY, "an acceleration > 0 m/s^2");
    Block b{radius_m, alpha_rad, inertia_ratio, mass_kg, gravity, 0.0};
    const double eh = b.housner_e();
    if (!(eh > 0.0))
        throw InputError("alpha", format_number(alpha_rad),
                         "a block that can rock: Housner's e = 1 - 2 sin^2(alpha) m R^2 / I0 = " +
                             format_number(eh) + " must be > 0 (the block is too squat)");
    if (e) {
        require_closed("restitution", *e, 0.0, eh,
                       "0 < e <= Housner's value " + format_number(eh));
        if (!(*e > 0.0)) throw InputError("restitution", format_number(*e), "0 < e <= " + format_number(eh));
        b.e = *e;
    } else {
        b.e = eh;
    }
    return b;
}

Block rectangular_block(double b_m, double h_m, double mass_kg, double gravity, std::optional<double> e) {
    require_open("half-width", b_m, 0.0, INFINITY, "a length > 0 m");
    require_open("half-height", h_m, 0.0, INFINITY, "a length > 0 m");
    const double alpha = std::atan2(b_m, h_m);
    if (!(housner_e(alpha, 4.0 / 3.0) > 0.0))
        throw InputError("half-width", format_number(b_m) + " (with half-height " + format_number(h_m) + ")",
                         "a block that can rock: b/h < sqrt(2) (Housner's e = 1 - 3/2 sin^2(alpha) = " +
                             format_number(housner_e(alpha, 4.0 / 3.0)) + " must be > 0)");
    return equivalent_block(std::hypot(b_m, h_m), alpha, 4.0 / 3.0, mass_kg, gravity, e);
}

double inertia_ratio_from_p(double p, double radius_m, double gravity) {
    require_open("frequency-parameter", p, 0.0, INFINITY, "p > 0 rad/s");
    return gravity / (p * p * radius_m);
}

}  // namespace rocksweep
