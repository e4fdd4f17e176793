#include "rocksweep/physics/model.hpp"

#include <algorithm>
#include <cmath>

#include "rocksweep/physics/fastmath.hpp"
#include "rocksweep/physics/spring_law.hpp"

namespace rocksweep {

std::string to_string(Equations e) { return e == Equations::nonlinear ? "nonlinear" : "linearised"; }

double CellModel::p() const { return std::sqrt(p2); }

/// Under the linearised equations theta'' at rest is p^2 (alpha (1 + ay) - |ax|): the
/// threshold that keeps uplift consistent with the motion is alpha, not tan(alpha).
double CellModel::uplift_slope() const { return equations == Equations::linearised ? alpha : std::tan(alpha); }

bool CellModel::uplifts(double t, double slope) const { return lifts(pulse.ax(t), pulse.ay(t), slope); }

bool CellModel::never_uplifts() const {
    return pulse.peak_ax() <= (1.0 - pulse.peak_ay()) * uplift_slope();
}

double CellModel::omega_max() const {
    // Rocking: the linearised growth rate p, raised by a strong ground motion through the
    // cos(alpha - theta) term. The anchorage law adds its own (AnchorageLaw::omega).
    const double w = std::sqrt(p2 * (1.0 + pulse.peak_ax() + pulse.peak_ay()));
    return std::max(w, pulse.time_scale());
}

double rocking_acceleration(const CellModel& m, int side, double kappa, double ax, double ay, double theta) {
    return rocking::theta_ddot<rocking::SpringLaw>(rocking::coef(m.p2, m.alpha, side, m.equations == Equations::linearised),
                                                   rocking::SpringLaw::coef(kappa), Ground{ax, ay}, theta, 0.0);
}

BaseReactions base_reactions(const CellModel& m, int side, double kappa, double k_n_m, double ax, double ay,
                             double theta, double theta_dot) {
    // Centre of mass about the pivot at x = s b: x = s b - s R sin(alpha - phi),
    // y = R cos(alpha - phi), phi = s theta; f = m (a_ground + a_cm) - spring - weight.
    const double s = side, phi = side * theta;
    double sa, ca, sh, ch;
    fastmath::sincos(m.alpha - phi, sa, ca);
    fastmath::sincos(0.5 * phi, sh, ch);
    const bool lin = m.equations == Equations::linearised;
    // phi'' = s theta'' is theta'' of the mirror image (physics.md §2): side +1 under the
    // ground (s ax, ay). The equation of motion, fed the sines the kinematics need anyway; the
    // spring's term on side +1 is kappa sin(phi/2) (spring_law.hpp).
    const double phidd = rocking::theta_ddot_from(rocking::coef(m.p2, m.alpha, 1, lin), Ground{s * ax, ay},
                                                  lin ? m.alpha - phi : sa, lin ? 1.0 : ca, kappa * (lin ? 0.5 * phi : sh));
    const double w2 = theta_dot * theta_dot, r_g = m.radius_m / m.gravity;
    BaseReactions f;
    f.fx = ax + s * r_g * (ca * phidd + sa * w2);
    f.fy = 1.0 + ay + r_g * (sa * phidd - ca * w2);
    if (k_n_m != 0.0) {
        // The spring pulls the lifted corner back towards its anchor, along (-s sin(phi/2),
        // -cos(phi/2)): the pivot carries the opposite, F cos(phi/2) down and F sin(phi/2)
        // towards the lifted side. F = 4 b k tan(phi/2), so F cos(phi/2) = 4 b k sin(phi/2).
        const double f_mg = 4.0 * m.half_width_m * k_n_m / (m.mass_kg * m.gravity);
        f.fy += f_mg * sh;
        f.fx += s * f_mg * sh * (sh / ch);
    }
    return f;
}

CellModel make_cell_model(const Block& block, const Anchorage& a, const Pulse& pulse,
                          Equations equations, double impact_threshold) {
    CellModel m;
    m.p2 = block.p() * block.p();
    m.alpha = block.alpha_rad;
    m.cos_alpha = std::cos(block.alpha_rad);
    m.e = block.e;
    m.equations = equations;
    m.anchorage = a.kind;
    m.adaptive_law = a.law;
    m.pulse = pulse;
    m.mass_kg = block.mass_kg;
    m.radius_m = block.radius_m;
    m.gravity = block.gravity;
    m.half_width_m = block.half_width_m();
    m.inertia = block.inertia();
    m.v_threshold = impact_threshold * block.p() * block.alpha_rad;
    if (a.kind != AnchorageKind::free) {
        const double b = m.half_width_m;
        m.kappa_max = 8.0 * b * b * a.k_max / m.inertia;
        m.kappa_min = 8.0 * b * b * a.k_min / m.inertia;
        m.break_max = a.break_angle(a.k_max);
        m.break_min = a.break_angle(a.k_min);
        m.force_max = a.k_max * 4.0 * b / a.strength_n;
        m.force_min = a.k_min * 4.0 * b / a.strength_n;
        m.k_max_n_m = a.k_max;
        m.k_min_n_m = a.k_min;
    } else {
        m.break_max = m.break_min = INFINITY;
    }
    return m;
}

}  // namespace rocksweep
