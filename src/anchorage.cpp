#include "rocksweep/anchorage.hpp"

#include <cmath>

#include "rocksweep/errors.hpp"

namespace rocksweep {

std::string to_string(AnchorageKind k) {
    switch (k) {
        case AnchorageKind::free: return "free";
        case AnchorageKind::constant: return "constant";
        case AnchorageKind::adaptive: return "adaptive";
    }
    return "?";
}

std::string to_string(BreakRule r) { return r == BreakRule::angle ? "angle" : "force"; }

double stiffness_from_strength(const Block& b, double strength_n, double theta_f_rad) {
    return strength_n / (4.0 * b.half_width_m() * std::tan(theta_f_rad / 2.0));
}

double fracture_angle(const Block& b, double strength_n, double k) {
    return 2.0 * std::atan(strength_n / (4.0 * b.half_width_m() * k));
}

double Anchorage::break_angle(double k) const {
    if (kind == AnchorageKind::free) return INFINITY;
    if (kind == AnchorageKind::adaptive && break_rule == BreakRule::angle) return theta_f_rad;
    // Force reaches F_u: K 4b tan(theta/2) = F_u, with k_max's angle as reference.
    return 2.0 * std::atan(std::tan(theta_f_rad / 2.0) * k_max / k);
}

bool adaptive_uses_kmax(bool excitation_acting, double ax, double theta, double theta_dot, bool previous) {
    const double x = excitation_acting ? -ax * theta : theta * theta_dot;
    if (x > 0.0) return true;
    if (x < 0.0) return false;
    return previous;
}

Anchorage free_anchorage() { return Anchorage{}; }

static void check_strength(double strength_n) {
    require_open("strength-ratio", strength_n, 0.0, INFINITY, "F_u / (m g) > 0");
}

Anchorage constant_anchorage(const Block& b, double strength_n, double theta_f_rad) {
    check_strength(strength_n);
    require_open("theta-f-ratio", theta_f_rad / b.alpha_rad, 0.0, M_PI / b.alpha_rad,
                 "0 < theta_f / alpha < pi / alpha (theta_f below pi rad)");
    Anchorage a;
    a.kind = AnchorageKind::constant;
    a.strength_n = strength_n;
    a.theta_f_rad = theta_f_rad;
    a.k_max = a.k_min = stiffness_from_strength(b, strength_n, theta_f_rad);
    return a;
}

Anchorage constant_anchorage_k(const Block& b, double strength_n, double k) {
    check_strength(strength_n);
    require_open("stiffness", k, 0.0, INFINITY, "K > 0 N/m");
    return constant_anchorage(b, strength_n, fracture_angle(b, strength_n, k));
}

Anchorage adaptive_anchorage(const Block& b, double strength_n, double theta_f_rad, double rho,
                             BreakRule rule) {
    require_closed("kmin-ratio", rho, 0.0, 1.0, "0 < K_min / K_max <= 1");
    if (!(rho > 0.0)) throw InputError("kmin-ratio", format_number(rho), "0 < K_min / K_max <= 1");
    Anchorage a = constant_anchorage(b, strength_n, theta_f_rad);
    a.kind = AnchorageKind::adaptive;
    a.k_min = rho * a.k_max;
    a.break_rule = rule;
    return a;
}

}  // namespace rocksweep
