#include "rocksweep/physics/energy.hpp"

#include <algorithm>
#include <cmath>

#include "rocksweep/physics/fastmath.hpp"
#include "rocksweep/physics/spring_law.hpp"

namespace rocksweep {

namespace {

bool linear(const CellModel& m) { return m.equations == Equations::linearised; }

/// dV/dphi of gravity plus a spring of coefficient kappa: the restoring acceleration on the
/// ground at rest, -theta'' at theta = phi > 0. With the C library's sine, as this was defined
/// (first_maximum's bisection ends on its last bits).
double potential_slope(const CellModel& m, double kappa, double phi) {
    using rocking::SpringLaw;
    return -rocking::theta_ddot<SpringLaw, true, rocking::LibmTrig>(rocking::coef(m.p2, m.alpha, 1, linear(m)),
                                                                    SpringLaw::coef(kappa), Ground{}, phi, 0.0);
}

double potential(const CellModel& m, double kappa, double phi) {
    return gravity_potential(m, phi) + spring_potential(m, kappa, phi);
}

/// V and dV/dphi together, from one sincos of (alpha - phi) and one of phi/4: the Newton
/// iteration of a swing's peak calls this, and it is the energy decision's main cost.
void potential_and_slope(const CellModel& m, double kappa, double phi, double& v, double& dv) {
    if (linear(m)) {
        v = potential(m, kappa, phi);
        dv = potential_slope(m, kappa, phi);
        return;
    }
    // Gravity's slope p^2 sin(alpha - phi) is potential_slope's, from the sines V needs anyway.
    double sa, ca, vs, moment;
    fastmath::sincos(m.alpha - phi, sa, ca);
    rocking::SpringLaw::potential_and_moment(kappa, phi, vs, moment);
    v = m.p2 * (ca - m.cos_alpha) + vs;
    dv = m.p2 * sa + moment;
}

}  // namespace

double gravity_potential(const CellModel& m, double phi) {
    if (linear(m)) return m.p2 * (m.alpha * phi - 0.5 * phi * phi);
    return m.p2 * (std::cos(m.alpha - phi) - m.cos_alpha);
}

double spring_potential(const CellModel& m, double kappa, double phi) {
    return rocking::SpringLaw::potential(kappa, phi, linear(m));
}

namespace {

/// The first maximum of V (gravity and a spring kappa) on [0, cap]: V rises on [0, alpha], and
/// without a spring it falls after; a spring can keep it rising past alpha.
double first_maximum(const CellModel& m, double kappa_out, double cap) {
    double lim = cap;
    if (kappa_out == 0.0) {
        lim = std::min(cap, m.alpha);
    } else if (m.alpha < cap && potential_slope(m, kappa_out, cap) < 0.0) {
        double lo = m.alpha, hi = cap;
        constexpr int scan = 32;  // V' may dip and rise: take its first zero
        for (int i = 1; i <= scan; ++i) {
            const double x = m.alpha + (cap - m.alpha) * i / scan;
            if (potential_slope(m, kappa_out, x) < 0.0) { hi = x; break; }
            lo = x;
        }
        for (int i = 0; i < 100 && hi - lo > 1e-15; ++i) {
            const double mid = 0.5 * (lo + hi);
            (potential_slope(m, kappa_out, mid) > 0.0 ? lo : hi) = mid;
        }
        lim = lo;
    }
    return lim;
}

}  // namespace

Swing outward_swing(const CellModel& m, double ke, double kappa_out, double kappa_in,
                    double break_angle) {
    Swing sw;
    const double cap = std::min(break_angle, M_PI / 2);
    // A block that turns before the first maximum never meets what lies beyond it.
    const double lim = first_maximum(m, kappa_out, cap);
    if (!(ke < potential(m, kappa_out, lim))) return sw;
    // V(peak) = ke on [0, lim], where V rises: Newton from the small-angle estimate, kept
    // inside a shrinking bracket (bisection when a Newton step leaves it).
    double lo = 0.0, hi = lim;
    const double a = m.p2 * m.alpha, c = 0.5 * m.p2 - 0.25 * kappa_out;  // V ~ a phi - c phi^2
    double x = (c > 0.0 && a * a > 4.0 * c * ke) ? 2.0 * ke / (a + std::sqrt(a * a - 4.0 * c * ke)) : ke / a;
    if (!(x > lo && x < hi)) x = 0.5 * (lo + hi);
    for (int i = 0; i < 100; ++i) {
        double v, slope;
        potential_and_slope(m, kappa_out, x, v, slope);
        const double f = v - ke;
        (f < 0.0 ? lo : hi) = x;
        double next = slope > 0.0 ? x - f / slope : 0.5 * (lo + hi);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        const bool converged = std::abs(next - x) <= 4e-16 * x || hi - lo <= 4e-16 * hi;
        x = next;
        if (converged) break;
    }
    // An adaptive spring that turns the block back with K_min must be able to: past the first
    // maximum of the K_min potential (possible when K_max's spring breaks beyond it, e.g.
    // theta_f = 2 alpha) the weaker spring lets gravity win, and the law then switches and
    // chatters on its surface. Energy alone cannot tell the end: leave it to the integration.
    if (kappa_in != kappa_out && !(x < first_maximum(m, kappa_in, cap))) return sw;
    sw.bounded = true;
    sw.peak = x;
    // Coming back with kappa_in: the spring releases only what K_min stores at the peak.
    sw.ke_return = ke + spring_potential(m, kappa_in, sw.peak) - spring_potential(m, kappa_out, sw.peak);
    return sw;
}

Works step_works(const CellModel& m, double k_n_m, const StepEnds& step, double t) {
    return step_works(m, k_n_m, step, step.t0, t);
}

Works step_works(const CellModel& m, double k_n_m, const StepEnds& step, double ta, double t) {
    Works w;
    // Gauss-Legendre nodes on [-1, 1]: 0, +-sqrt(3/5), weights 8/9, 5/9, on each piece of the
    // step where the ground is smooth: a step may cross a record's samples.
    constexpr double x[3] = {-0.7745966692414834, 0.0, 0.7745966692414834};
    constexpr double wt[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
    const double b = m.half_width_m, t_end = m.pulse.end_time();
    for (double a = ta; a < t;) {
        const double e = std::min(t, a < t_end ? std::min(m.pulse.next_kink(a), t_end) : INFINITY);
        const double h = e - a;
        Works piece;
        for (int i = 0; i < 3; ++i) {
            const double tn = a + 0.5 * h * (1.0 + x[i]);
            double th, thd;
            step.at(tn, th, thd);
            const double phi = std::abs(th), sgn = th > 0.0 ? 1.0 : (th < 0.0 ? -1.0 : 0.0);
            const double ax = tn < t_end ? m.pulse.ax(tn) : 0.0;
            piece.excitation_j += wt[i] * (-m.mass_kg * ax * m.gravity * m.radius_m * std::cos(m.alpha - phi) * thd);
            piece.anchorage_j += wt[i] * (-rocking::SpringLaw::moment_nm(b, k_n_m, phi) * sgn * thd);
        }
        w.excitation_j += piece.excitation_j * 0.5 * h;
        w.anchorage_j += piece.anchorage_j * 0.5 * h;
        a = e;
    }
    return w;
}

FreeFate free_fate(const CellModel& m, int side, double v, bool left_intact, bool right_intact) {
    FreeFate f;
    const bool anchored = m.anchorage != AnchorageKind::free;
    auto spring = [&](int s, double& k_out, double& k_in, double& brk, double& fcoef) {
        const bool intact = anchored && (s > 0 ? left_intact : right_intact);
        k_out = intact ? m.kappa_max : 0.0;
        k_in = intact ? m.kappa_min : 0.0;
        brk = intact ? m.break_max : INFINITY;
        fcoef = intact ? m.force_max : 0.0;
    };
    double ke = 0.5 * v * v;
    int s = side;
    bool last_nearly = false;
    for (int swing = 0; swing < 1'000'000; ++swing) {
        double k_out, k_in, brk, fcoef;
        spring(s, k_out, k_in, brk, fcoef);
        const double ke_in = ke;
        const Swing sw = outward_swing(m, ke, k_out, k_in, brk);
        if (!sw.bounded) return f;
        f.max_phi = std::max(f.max_phi, sw.peak);
        f.peak_force = std::max(f.peak_force, rocking::SpringLaw::force_ratio(fcoef, sw.peak));
        // A swing returns at most the speed it was launched with (K_min <= K_max on the way
        // back): launched below the threshold, it ends in a settling impact whatever rounding
        // makes of a return energy near 0 (a near-plastic e, e^2 ke below the smallest double,
        // once left a NaN here and 10^6 swings; physics.md, "Impacts, rest and outcomes").
        const bool launched_settling = ke < 0.5 * m.v_threshold * m.v_threshold;
        const double v_ret = std::sqrt(2.0 * std::max(sw.ke_return, 0.0));
        ++f.impacts_total;
        if (launched_settling || v_ret < m.v_threshold) {
            f.decided = true;
            return f;
        }
        ++f.impacts;
        ke = m.e * m.e * sw.ke_return;
        s = -s;
        // Once both sides have swung and the swings are conservative, every later swing is
        // smaller than the last on its side and the approach speeds fall as v_ret e^k. An
        // adaptive spring's switch loses energy ~ (K_max - K_min) phi^2 per swing, a vanishing
        // fraction as the swings shrink: below 1e-3 of the swing's energy the sum of what is
        // left moves the count by well under one impact, so the tail is taken as geometric.
        double ko2, ki2, b2, f2;
        spring(s, ko2, ki2, b2, f2);
        const bool conservative = k_out == k_in && ko2 == ki2;
        const bool nearly = ke_in - sw.ke_return <= 1e-3 * ke_in;  // this side's swing
        const bool both_nearly = nearly && last_nearly;            // and the other side's
        last_nearly = nearly;
        if (swing >= 1 && (conservative || both_nearly)) {
            const double ratio = v_ret / m.v_threshold;
            auto n = static_cast<std::int32_t>(std::floor(std::log(ratio) / -std::log(m.e)));
            while (n > 0 && v_ret * std::pow(m.e, n) < m.v_threshold) --n;
            while (v_ret * std::pow(m.e, n + 1) >= m.v_threshold) ++n;
            f.impacts += n;
            f.impacts_total += n + 1;
            f.decided = true;
            return f;
        }
    }
    return f;
}

}  // namespace rocksweep
