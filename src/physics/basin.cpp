#include "rocksweep/physics/basin.hpp"

#include <algorithm>
#include <cmath>

#include "rocksweep/physics/energy.hpp"
#include "rocksweep/physics/integrator.hpp"

namespace rocksweep {

namespace {

constexpr double kHalfPi = M_PI / 2;

/// Energy an outward swing from phi needs to overturn on a side whose spring (the potential V)
/// breaks at `brk`: over V's barrier before the fracture, or, once the spring has broken and
/// taken its stored energy V - V_gravity with it, over gravity's barrier beyond (physics.md
/// "Basins": the two conditions of a spring that breaks before alpha).
double outward_barrier(const SwingPotential& v, const SwingPotential& gravity, double brk, double phi) {
    const double cap = std::min(brk, kHalfPi);
    double b = v.max_on(phi, std::max(phi, cap));
    if (brk < kHalfPi && phi < brk) b = std::max(b, v(brk) - gravity(brk) + gravity.max_on(brk, kHalfPi));
    return b;
}

}  // namespace

SwingPotential::SwingPotential(const CellModel& m, double kappa) : m_(&m), kappa_(kappa) {
    // Gravity and a spring give a potential with few extrema on [0, pi/2]: a fine scan finds
    // each, golden-section search pins it down.
    constexpr int n = 1024;
    const double h = kHalfPi / n;
    knots_.push_back(0.0);
    double prev = (*this)(0.0), cur = (*this)(h);
    for (int i = 1; i < n; ++i) {
        const double next = (*this)((i + 1) * h);
        const double sign = cur > prev && cur >= next ? 1.0 : (cur < prev && cur <= next ? -1.0 : 0.0);
        if (sign != 0.0) {
            double lo = (i - 1) * h, hi = (i + 1) * h;
            const double g = 0.5 * (std::sqrt(5.0) - 1.0);
            for (int it = 0; it < 80 && hi - lo > 1e-15; ++it) {
                const double a = hi - g * (hi - lo), b = lo + g * (hi - lo);
                if (sign * (*this)(a) > sign * (*this)(b)) hi = b;
                else lo = a;
            }
            knots_.push_back(0.5 * (lo + hi));
        }
        prev = cur;
        cur = next;
    }
    knots_.push_back(kHalfPi);
}

double SwingPotential::operator()(double phi) const {
    return gravity_potential(*m_, phi) + spring_potential(*m_, kappa_, phi);
}

double SwingPotential::max_on(double a, double b) const {
    double v = std::max((*this)(a), (*this)(b));
    for (double k : knots_)
        if (k > a && k < b) v = std::max(v, (*this)(k));
    return v;
}

double SwingPotential::first_reach(double from, double to, double energy) const {
    // The potential is monotone between knots: the first piece whose far end reaches the energy
    // holds the crossing.
    std::vector<double> ends;
    for (double k : knots_)
        if (to > from ? k > from && k < to : k < from && k > to) ends.push_back(k);
    if (to < from) std::reverse(ends.begin(), ends.end());
    ends.push_back(to);
    double x0 = from;
    for (double x1 : ends) {
        if ((*this)(x1) >= energy) {
            double below = x0, above = x1;
            for (int it = 0; it < 200 && std::abs(above - below) > 1e-15 * std::max(1.0, std::abs(above)); ++it) {
                const double mid = 0.5 * (below + above);
                ((*this)(mid) >= energy ? above : below) = mid;
            }
            return above;
        }
        x0 = x1;
    }
    return NAN;
}

bool SwingPotential::restoring_at(double phi) const {
    const auto it = std::upper_bound(knots_.begin(), knots_.end(), phi);
    if (it == knots_.begin() || it == knots_.end()) return it == knots_.begin();
    return (*this)(*it) > (*this)(*(it - 1));
}

BasinEnergy::BasinEnergy(const CellModel& m)
    : m_(m),
      gravity_(m, 0.0),
      stiff_(m, m.anchorage == AnchorageKind::free ? 0.0 : m.kappa_max),
      soft_(m, m.anchorage == AnchorageKind::free ? 0.0 : m.kappa_min) {
    const bool anchored = m.anchorage != AnchorageKind::free;
    barrier_from_rest_ = anchored ? outward_barrier(stiff_, gravity_, m.break_max, 0.0) : gravity_.max_on(0.0, kHalfPi);
    // A swing from theta = 0 below this energy turns before any maximum of its potential and
    // before its fracture angle, and (adaptive) turns where K_min still pulls it back.
    bounded_below_ = gravity_(gravity_.first_peak());
    if (anchored) bounded_below_ = std::min(bounded_below_, stiff_(std::min(stiff_.first_peak(), m.break_max)));
    if (m.anchorage == AnchorageKind::adaptive) bounded_below_ = std::min(bounded_below_, stiff_(soft_.first_peak()));
}

Outcome BasinEnergy::outcome(double theta, double theta_dot) const {
    if (theta == 0.0 && theta_dot == 0.0) return Outcome::safe;
    const bool anchored = m_.anchorage != AnchorageKind::free, adaptive = m_.anchorage == AnchorageKind::adaptive;
    int side = (theta != 0.0 ? theta : theta_dot) > 0.0 ? 1 : -1;
    double phi = std::abs(theta), u = side * theta_dot;  // u > 0: outward
    bool intact[2] = {anchored, anchored};               // [0]: the spring of theta > 0
    // Moving outward the law wants K_max; the passive law raises K only at theta = 0.
    bool k_max = !adaptive || (u > 0.0 && (m_.adaptive_law == AdaptiveLaw::paper || theta == 0.0));
    int impacts = 0;
    auto spring = [&]() -> bool& { return intact[side > 0 ? 0 : 1]; };
    auto brk = [&]() { return spring() ? (k_max ? m_.break_max : m_.break_min) : INFINITY; };
    auto potential = [&]() -> const SwingPotential& { return !spring() ? gravity_ : (k_max ? stiff_ : soft_); };
    if (spring() && phi >= brk()) spring() = false;
    // Balanced at rest on the potential's peak (theta = alpha of a free block): it stays there
    // for ever, which the kernel reports as not converged.
    const double kappa = !spring() ? 0.0 : (k_max ? m_.kappa_max : m_.kappa_min);
    if (u == 0.0 && rocking_acceleration(m_, side, kappa, 0.0, 0.0, theta) == 0.0) return Outcome::not_converged;
    for (int phase = 0; phase < 1'000'000; ++phase) {
        const SwingPotential& v = potential();
        const double energy = 0.5 * u * u + v(phi);
        if (u > 0.0 || (u == 0.0 && !v.restoring_at(phi))) {
            const double cap = std::min(brk(), kHalfPi);
            const double turn = v.first_reach(phi, cap, energy);
            if (!std::isnan(turn)) {
                phi = turn;
                u = 0.0;
                if (adaptive && spring()) k_max = false;  // the law's switch at the turning point
                continue;
            }
            if (cap < kHalfPi) {  // the spring breaks; its energy goes with it
                u = std::sqrt(2.0 * std::max(0.0, energy - v(cap)));
                phi = cap;
                spring() = false;
                continue;
            }
            return impacts > 0 ? Outcome::overturned_impact : Outcome::overturned_no_impact;
        }
        const double turn = v.first_reach(phi, 0.0, energy);
        if (!std::isnan(turn)) {  // turns back outward beyond the barrier; K stays as it is
            phi = turn;
            u = 0.0;
            continue;
        }
        const double speed = std::sqrt(2.0 * energy);
        if (speed < m_.v_threshold) return Outcome::safe;  // settling, as the integrator counts it
        ++impacts;
        side = -side;
        phi = 0.0;
        u = m_.e * speed;
        k_max = true;
        if (0.5 * u * u < bounded_below_) return Outcome::safe;
    }
    return Outcome::not_converged;
}

BasinBoundary BasinEnergy::boundary(double theta) const {
    const bool anchored = m_.anchorage != AnchorageKind::free;
    const double phi = std::abs(theta);
    // Outward the spring works with K (K_max); inward with K (K_min). A state beyond a fracture
    // angle has lost that spring, as the integrator starts it.
    const bool out_intact = anchored && phi < m_.break_max, in_intact = anchored && phi < m_.break_min;
    const SwingPotential& vo = out_intact ? stiff_ : gravity_;
    const SwingPotential& vi = in_intact ? soft_ : gravity_;
    const double b = outward_barrier(vo, gravity_, out_intact ? m_.break_max : INFINITY, phi);
    const double past = std::max(0.0, vi.max_on(0.0, phi) - vi(phi));  // inward, back over the barrier
    BasinBoundary r;
    r.no_impact = b > vo(phi) ? std::sqrt(2.0 * (b - vo(phi))) : -std::sqrt(2.0 * past);
    const double need = std::max(vi.max_on(0.0, phi), barrier_from_rest_ / (m_.e * m_.e)) - vi(phi);
    r.impact = -std::sqrt(2.0 * std::max(0.0, need));
    if (theta < 0.0) {
        r.no_impact = -r.no_impact;
        r.impact = -r.impact;
    }
    return r;
}

}  // namespace rocksweep
