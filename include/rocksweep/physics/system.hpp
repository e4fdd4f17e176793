#pragma once
/// The rocking block as an ODE system (physics.md §3-4): the equation of motion, written once
/// for any anchorage law (anchorage_law.hpp). The W-lane kernel, the scalar right-hand side
/// (rocking_acceleration), the base reactions and the energy decision all evaluate it, so that
/// what the integration conserves and what the energy argument assumes cannot drift apart.
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

/// Coefficients of the equation of motion without its anchorage, as doubles: side s = +-1,
/// linear = 1 for the linearised equations.
struct Coef {
    double p2, alpha, side, linear;
};

inline Coef coef(double p2, double alpha, int side, bool linear) {
    return {p2, alpha, static_cast<double>(side), linear ? 1.0 : 0.0};
}

// ---- The equation of motion (physics.md §3, Eq. 7 and 9 with the restoring factor s):
// theta'' = -p^2 [(1 + ay) sin(s alpha - theta) + ax cos(s alpha - theta)] - r(theta, theta_dot),
// r the anchorage law's term (anchorage_law.hpp; Eq. 8's spring: s kappa sin(s theta / 2)).

/// theta'' from the values of the trigonometric terms: sn = sin(s alpha - theta), cs =
/// cos(s alpha - theta) (or s alpha - theta and 1, linearised), and the law's term r. Callers
/// that already hold these sines (the base reactions) use this.
[[gnu::always_inline]] inline double theta_ddot_from(const Coef& c, const Ground& g, double sn, double cs, double r) {
    return -c.p2 * ((1.0 + g.ay) * sn + g.ax * cs) - r;
}

/// theta'' on side s at rotation theta [rad] and angular velocity theta_dot [rad/s] under the
/// ground g [g], with the anchorage law Law of coefficients k (Law::term). with_law = false:
/// the batch has no lane where the law acts, and Law::term<false> skips its work (same bits).
template <class Law, bool with_law = true, class Trig = FastTrig>
[[gnu::always_inline]] inline double theta_ddot(const Coef& c, const typename Law::Coef& k, const Ground& g,
                                                double theta, double theta_dot) {
    const double s = c.side;
    const double a = s * c.alpha - theta;
    const double nl = 1.0 - c.linear;
    double sa, ca;
    Trig::sincos(a, sa, ca);
    const double sn = a * c.linear + sa * nl;
    const double cs = c.linear + ca * nl;
    return theta_ddot_from(c, g, sn, cs, Law::template term<with_law, Trig>(k, s, theta, theta_dot, c.linear, nl));
}

}  // namespace rocksweep::rocking
