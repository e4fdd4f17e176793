#pragma once
/// Unilateral elastic-brittle anchorages at the two base corners (physics.md §4).
#include <string>

#include "rocksweep/physics/block.hpp"

namespace rocksweep {

enum class AnchorageKind { free, constant, adaptive };
/// When an adaptive restrainer breaks: at the K_max spring's fracture angle (default), or when
/// the force K(t) 4b tan(|theta|/2) reaches F_u.
enum class BreakRule { angle, force };
/// Which adaptive law drives K (physics.md, "Anchorage"): the paper's Eq. 21-22, or the passive
/// variant that makes every K_min -> K_max switch wait until the spring is slack (theta = 0),
/// so that the controller never puts energy into the spring.
enum class AdaptiveLaw { paper, passive };

std::string to_string(AnchorageKind k);
std::string to_string(BreakRule r);
std::string to_string(AdaptiveLaw l);

/// Stiffness K in N/m (vertical spring at each corner), strength F_u in N, angles in rad.
struct Anchorage {
    AnchorageKind kind = AnchorageKind::free;
    double k_max = 0.0;         ///< K for constant, K_max for adaptive [N/m]
    double k_min = 0.0;         ///< K_min = rho K_max for adaptive [N/m]; = k_max otherwise
    double strength_n = 0.0;    ///< F_u [N]
    double theta_f_rad = 0.0;   ///< fracture angle of the k_max spring
    BreakRule break_rule = BreakRule::angle;
    AdaptiveLaw law = AdaptiveLaw::paper;

    /// Angle at which a spring of stiffness k breaks under this anchorage's rule.
    double break_angle(double k) const;
};

/// K from strength and fracture angle: K = F_u / (4 b tan(theta_f / 2)).
double stiffness_from_strength(const Block& b, double strength_n, double theta_f_rad);
/// Fracture angle of a spring of stiffness K and strength F_u: 2 atan(F_u / (4 b K)).
double fracture_angle(const Block& b, double strength_n, double k);

/// The adaptive law in continuous time: true for K_max. While the excitation acts (Eq. 21)
/// K_max where ax theta < 0 and K_min where ax theta > 0; in free oscillation (Eq. 22) K_max
/// while |theta| grows (theta theta_dot > 0), K_min while it shrinks. On the switching
/// surface itself (a product of 0) the previous value stays. Only signs matter.
bool adaptive_uses_kmax(bool excitation_acting, double ax, double theta, double theta_dot, bool previous);

Anchorage free_anchorage();
/// Constant stiffness from F_u and theta_f. Throws InputError for theta_f <= 0 or F_u <= 0.
Anchorage constant_anchorage(const Block& b, double strength_n, double theta_f_rad);
/// Constant stiffness given directly; theta_f follows from F_u.
Anchorage constant_anchorage_k(const Block& b, double strength_n, double k);
/// Adaptive: K_max from F_u and theta_f, K_min = rho K_max with 0 < rho <= 1.
Anchorage adaptive_anchorage(const Block& b, double strength_n, double theta_f_rad, double rho,
                             BreakRule rule = BreakRule::angle, AdaptiveLaw law = AdaptiveLaw::paper);

}  // namespace rocksweep
