#pragma once
/// The rocking block as an ODE system (physics.md §3-4): the equation of motion and the law of
/// its anchorage, written once. The W-lane kernel, the scalar right-hand side
/// (rocking_acceleration), the base reactions and the energy decision all evaluate these
/// functions, so that what the integration conserves and what the energy argument assumes
/// cannot drift apart.
///
/// Branch-free on purpose: selects are exact arithmetic on 0/1 factors (x * 1 = x,
/// x * 0 + y = y for finite x and y != 0), so that GCC vectorises the kernel's lane loop (a
/// ternary between computed values would put the sin/cos under a branch) and a lane gives the
/// same bits alone and in a vector. Values the scalar code set to 0.0 are made exactly +0.0 by
/// adding +0.0.
#include <cmath>

#include "rocksweep/physics/excitation/ground.hpp"
#include "rocksweep/physics/fastmath.hpp"

namespace rocksweep::rocking {

/// The kernel's sines: branch-free, the same bits in a scalar and in a vector loop.
struct FastTrig {
    [[gnu::always_inline]] static inline double sin(double x) { return fastmath::sin(x); }
    [[gnu::always_inline]] static inline void sincos(double x, double& s, double& c) { fastmath::sincos(x, s, c); }
};
/// The C library's, for callers whose results were defined with it (the energy decision's
/// potential slope): swapping the sine would move their last bits.
struct LibmTrig {
    static double sin(double x) { return std::sin(x); }
    static void sincos(double x, double& s, double& c) {
        s = std::sin(x);
        c = std::cos(x);
    }
};

/// Coefficients of the equation of motion as doubles: side s = +-1, flags 0/1.
/// kappa = 8 b^2 K / I0 of the working spring [1/s^2], 0 when broken or free; spring = 1 iff
/// kappa != 0; linear = 1 for the linearised equations.
struct Coef {
    double p2, alpha, kappa, side, linear, spring;
};

inline Coef coef(double p2, double alpha, double kappa, int side, bool linear) {
    return {p2, alpha, kappa, static_cast<double>(side), linear ? 1.0 : 0.0, kappa == 0.0 ? 0.0 : 1.0};
}

// ---- The anchorage law (Eq. 8): the working spring's moment magnitude per unit I0 at
// phi = |theta| is kappa sin(phi/2); linearised, kappa phi/2.

/// sin(phi/2) of Eq. 8 (or phi/2 under the linearised equations, linear = 1, nl = 1 - linear).
template <class Trig = FastTrig>
[[gnu::always_inline]] inline double spring_shape(double half_phi, double linear, double nl) {
    return half_phi * linear + Trig::sin(half_phi) * nl;
}

/// The spring's potential per unit I0, the integral of the moment kappa sin(phi/2):
/// 2 kappa (1 - cos(phi/2)), written as 4 kappa sin^2(phi/4) (no cancellation); linearised
/// kappa phi^2 / 4. Not the strain energy 1/2 K (4b tan(phi/2))^2, which agrees to O(phi^4)
/// but is not what the integrated equation conserves (docs/physics.md, "Anchorage").
template <class Trig = LibmTrig>
inline double spring_potential(double kappa, double phi, bool linear) {
    if (kappa == 0.0) return 0.0;
    if (linear) return 0.25 * kappa * phi * phi;
    const double s = Trig::sin(0.25 * phi);
    return 4.0 * kappa * s * s;
}

/// The spring's potential and moment (its slope) together from one sincos of phi/4, the
/// nonlinear law only: sin(phi/2) = 2 sin(phi/4) cos(phi/4). For the energy decision's Newton
/// iteration, where this is the main cost.
inline void spring_potential_and_moment(double kappa, double phi, double& v, double& moment) {
    double sq, cq;
    fastmath::sincos(0.25 * phi, sq, cq);
    v = 4.0 * kappa * sq * sq;
    moment = kappa * 2.0 * sq * cq;
}

/// The anchorage's moment magnitude in N m, 8 b^2 K sin(phi/2) (Eq. 8 as printed; = I0 kappa
/// sin(phi/2)), for the work of Eq. 24.
inline double anchorage_moment_nm(double b_m, double k_n_m, double phi) {
    return 8.0 * b_m * b_m * k_n_m * std::sin(0.5 * phi);
}

/// The working spring's force over its strength, K 4b tan(phi/2) / F_u, with
/// force_coef = 4 b K / F_u.
inline double spring_force_ratio(double force_coef, double phi) { return force_coef * std::tan(0.5 * phi); }

// ---- The equation of motion (physics.md §3, Eq. 7 and 9 with the restoring factor s):
// theta'' = -p^2 [(1 + ay) sin(s alpha - theta) + ax cos(s alpha - theta)] - s kappa sin(s theta / 2).

/// theta'' from the values of the trigonometric terms: sn = sin(s alpha - theta), cs =
/// cos(s alpha - theta) (or s alpha - theta and 1, linearised), shape = spring_shape(s theta / 2)
/// times the spring flag. Callers that already hold these sines (the base reactions) use this.
[[gnu::always_inline]] inline double theta_ddot_from(const Coef& c, const Ground& g, double sn, double cs, double shape) {
    return -c.p2 * ((1.0 + g.ay) * sn + g.ax * cs) - c.side * c.kappa * shape;
}

/// theta'' on side s at rotation theta [rad] under the ground g [g]. Written on s theta rather
/// than |theta| so that a trial step just past theta = 0 stays smooth; on the side where the
/// equation is used the two are equal. with_spring = false: the spring term is +0 (a batch
/// with no spring skips its sine; same bits).
template <bool with_spring = true, class Trig = FastTrig>
[[gnu::always_inline]] inline double theta_ddot(const Coef& c, const Ground& g, double theta) {
    const double s = c.side;
    const double a = s * c.alpha - theta;
    const double nl = 1.0 - c.linear;
    double sa, ca;
    Trig::sincos(a, sa, ca);
    const double sn = a * c.linear + sa * nl;
    const double cs = c.linear + ca * nl;
    double shape = 0.0;  // kappa = 0: +0, as the scalar code
    if constexpr (with_spring) shape = spring_shape<Trig>(0.5 * s * theta, c.linear, nl) * c.spring + 0.0;
    return theta_ddot_from(c, g, sn, cs, shape);
}

}  // namespace rocksweep::rocking
