#pragma once
/// The anchorage law of the paper (Eq. 8, physics.md §4): a vertical tension-only spring at the
/// uplifting corner whose moment magnitude per unit I0 at phi = |theta| is kappa sin(phi/2),
/// kappa = 8 b^2 K / I0 [1/s^2]; linearised, kappa phi/2. Its moment, potential and force are
/// written here once: the kernel (through kernel::Springs, the law as a lane runs it), the
/// energy decision, the base reactions and the basins all evaluate these.
#include <cmath>

#include "rocksweep/physics/system.hpp"

namespace rocksweep::rocking {

struct SpringLaw {
    /// A lane's coefficients: kappa of the working spring, 0 when broken, free or at rest;
    /// spring = 1 iff kappa != 0 (a 0/1 factor, so the lane loop needs no branch).
    struct Coef {
        double kappa = 0.0, spring = 0.0;
        bool operator==(const Coef&) const = default;
    };
    static Coef coef(double kappa) { return {kappa, kappa == 0.0 ? 0.0 : 1.0}; }
    /// Acts in a lane: a batch in which no lane does skips the spring's sine (same bits).
    static bool acts(const Coef& k) { return k.kappa != 0.0; }

    /// The coefficients as the lane loop holds them, structure of arrays.
    template <int W>
    struct Soa {
        alignas(64) double kappa[W], spring[W];
        void store(int i, const Coef& k) { kappa[i] = k.kappa; spring[i] = k.spring; }
        [[gnu::always_inline]] Coef load(int i) const { return {kappa[i], spring[i]}; }
    };

    /// sin(phi/2) of Eq. 8 (or phi/2 under the linearised equations, linear = 1, nl = 1 - linear).
    template <class Trig = FastTrig>
    [[gnu::always_inline]] static inline double shape(double half_phi, double linear, double nl) {
        return half_phi * linear + Trig::sin(half_phi) * nl;
    }

    /// The spring's term of theta'' on side s, s kappa sin(s theta / 2) (system.hpp). Written on
    /// s theta rather than |theta| so that a trial step just past theta = 0 stays smooth.
    /// active = false (no lane of the batch has a spring): +0 times s kappa, as the scalar code.
    template <bool active = true, class Trig = FastTrig>
    [[gnu::always_inline]] static inline double term(const Coef& k, double side, double theta, double /*theta_dot*/,
                                                     double linear, double nl) {
        double sh = 0.0;
        if constexpr (active) sh = shape<Trig>(0.5 * side * theta, linear, nl) * k.spring + 0.0;
        return side * k.kappa * sh;
    }

    /// The spring's potential per unit I0, the integral of the moment kappa sin(phi/2):
    /// 2 kappa (1 - cos(phi/2)), written as 4 kappa sin^2(phi/4) (no cancellation); linearised
    /// kappa phi^2 / 4. Not the strain energy 1/2 K (4b tan(phi/2))^2, which agrees to O(phi^4)
    /// but is not what the integrated equation conserves (docs/physics.md, "Anchorage").
    template <class Trig = LibmTrig>
    static double potential(double kappa, double phi, bool linear) {
        if (kappa == 0.0) return 0.0;
        if (linear) return 0.25 * kappa * phi * phi;
        const double s = Trig::sin(0.25 * phi);
        return 4.0 * kappa * s * s;
    }

    /// The potential and the moment (its slope) together from one sincos of phi/4, the
    /// nonlinear law only: sin(phi/2) = 2 sin(phi/4) cos(phi/4). For the energy decision's
    /// Newton iteration, where this is the main cost.
    static void potential_and_moment(double kappa, double phi, double& v, double& moment) {
        double sq, cq;
        fastmath::sincos(0.25 * phi, sq, cq);
        v = 4.0 * kappa * sq * sq;
        moment = kappa * 2.0 * sq * cq;
    }

    /// The moment magnitude in N m, 8 b^2 K sin(phi/2) (Eq. 8 as printed; = I0 kappa
    /// sin(phi/2)), for the work of Eq. 24.
    static double moment_nm(double b_m, double k_n_m, double phi) { return 8.0 * b_m * b_m * k_n_m * std::sin(0.5 * phi); }

    /// The force over the strength, K 4b tan(phi/2) / F_u, with force_coef = 4 b K / F_u.
    static double force_ratio(double force_coef, double phi) { return force_coef * std::tan(0.5 * phi); }
};

}  // namespace rocksweep::rocking
