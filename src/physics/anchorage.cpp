#include "rocksweep/physics/anchorage.hpp"

#include <cmath>

#include "rocksweep/core/errors.hpp"

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
std::string to_string(AdaptiveLaw l) { return l == AdaptiveLaw::paper ? "paper" : "passive"; }

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
    require_open("anchorage.strength", strength_n, 0.0, INFINITY, "a finite strength F_u > 0 N");
}

Anchorage constant_anchorage(const Block& b, double strength_n, double theta_f_rad) {
    check_strength(strength_n);
    require_open("anchorage.theta_f", theta_f_rad, 0.0, M_PI, "0 < theta_f < pi rad");
    Anchorage a;
    a.kind = AnchorageKind::constant;
    a.strength_n = strength_n;
    a.theta_f_rad = theta_f_rad;
    a.k_max = a.k_min = stiffness_from_strength(b, strength_n, theta_f_rad);
    return a;
}

Anchorage constant_anchorage_k(const Block& b, double strength_n, double k) {
    check_strength(strength_n);
    require_open("anchorage.stiffness", k, 0.0, INFINITY, "a finite K > 0 N/m");
    const double theta_f = fracture_angle(b, strength_n, k);
    // So soft a spring that F_u is reached only at theta = pi never breaks: refuse it as K.
    if (!(theta_f < M_PI))
        throw InputError("anchorage.stiffness", format_number(k),
                         "K large enough that theta_f = 2 atan(F_u / (4 b K)) < pi rad (F_u = " + format_number(strength_n) + " N)");
    return constant_anchorage(b, strength_n, theta_f);
}

Anchorage adaptive_anchorage(const Block& b, double strength_n, double theta_f_rad, double rho,
                             BreakRule rule, AdaptiveLaw law) {
    if (!(rho > 0.0 && rho <= 1.0)) throw InputError("anchorage.kmin_ratio", format_number(rho), "0 < K_min / K_max <= 1");
    Anchorage a = constant_anchorage(b, strength_n, theta_f_rad);
    a.kind = AnchorageKind::adaptive;
    a.k_min = rho * a.k_max;
    a.break_rule = rule;
    a.law = law;
    return a;
}

}  // namespace rocksweep
