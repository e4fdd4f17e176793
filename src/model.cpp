#include "rocksweep/model.hpp"

#include <algorithm>
#include <cmath>

namespace rocksweep {

std::string to_string(Equations e) { return e == Equations::nonlinear ? "nonlinear" : "linearised"; }

double CellModel::p() const { return std::sqrt(p2); }

namespace {
/// Under the linearised equations theta'' at rest is p^2 (alpha (1 + ay) - |ax|): the
/// threshold that keeps uplift consistent with the motion is alpha, not tan(alpha).
double uplift_slope(const CellModel& m) {
    return m.equations == Equations::linearised ? m.alpha : std::tan(m.alpha);
}
}  // namespace

bool CellModel::uplifts(double t) const {
    return std::abs(pulse.ax(t)) > (1.0 + pulse.ay(t)) * uplift_slope(*this);
}

bool CellModel::never_uplifts() const {
    return pulse.peak_ax() <= (1.0 - std::abs(pulse.ay_g)) * uplift_slope(*this);
}

double CellModel::omega_max() const {
    // Rocking: the linearised growth rate p, raised by a strong ground motion through the
    // cos(alpha - theta) term; spring: small-angle frequency sqrt(kappa / 2).
    double w = std::sqrt(p2 * (1.0 + pulse.peak_ax() + std::abs(pulse.ay_g)));
    if (pulse.kind == PulseKind::sine) w = std::max(w, pulse.omega);
    w = std::max(w, std::sqrt(p2 + 0.5 * kappa_max));
    return w;
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
