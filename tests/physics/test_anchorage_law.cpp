// The anchorage-law seam (issue 8, seam 2; anchorage_law.hpp): a law the library does not ship,
// a linear viscous damper, defined only here and run through the same lane, event stepper, RK4
// batch and observers as Eq. 8's spring. If any of them still assumed the spring, the damped
// motion below would not follow its closed form, or would not lose what the damper dissipates.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "../../src/physics/lane.hpp"
#include "rocksweep/physics/anchorage_law.hpp"
#include "rocksweep/physics/energy.hpp"
#include "smatteo_case.hpp"

namespace rocksweep {
namespace {

/// A rotational viscous damper between block and ground: a moment per unit I0 of c theta_dot
/// against the motion, on either side; no fracture, no switches, no potential.
struct Damper {
    static constexpr double c = 0.6;  ///< [1/s], about 0.26 p for S. Matteo
    struct Coef {
        double c = 0.0;  ///< 0 at rest
        bool operator==(const Coef&) const = default;
    };
    template <int W>
    struct Soa {
        alignas(64) double c[W];
        void store(int i, const Coef& k) { c[i] = k.c; }
        Coef load(int i) const { return {c[i]}; }
    };
    template <bool active = true, class Trig = rocking::FastTrig>
    static double term(const Coef& k, double, double, double theta_dot, double, double) {
        return active ? k.c * theta_dot : 0.0;
    }
    static bool acts(const Coef& k) { return k.c != 0.0; }
    static double omega(const CellModel&) { return c; }

    explicit Damper(const CellModel& m) : m_(m) {}
    Coef coef(int side) const { return {side == 0 ? 0.0 : c}; }

    bool intact(int) const { return false; }  // nothing to break
    bool broken(int) const { return false; }
    double break_angle() const { return INFINITY; }
    void fracture(int) {}
    bool turn_armed(int, double, bool) const { return false; }
    void at_turn(int, double) {}
    bool switches_at_ground_zeros() const { return false; }
    void at_uplift() {}
    template <class Ax> void at_start(int, double, double, bool, Ax&&) {}
    template <class Ax> void follow_law(int, double, double, bool, Ax&&) {}
    template <class Ax> void follow_law_lagged(int, double, double, bool, Ax&&) {}

    bool anchored() const { return false; }
    double force_ratio(double) const { return 0.0; }
    std::uint8_t broken_bits() const { return 0; }
    double switch_energy() const { return 0.0; }
    double stiffness_n_m(int) const { return 0.0; }
    /// A couple between block and ground adds no force at the pivot; it changes the reactions
    /// only through theta'': phi'' gains -c phi_dot, the centre of mass's acceleration with it.
    BaseReactions reactions(int side, double ax, double ay, double theta, double theta_dot) const {
        BaseReactions f = base_reactions(m_, side, 0.0, 0.0, ax, ay, theta, theta_dot);
        const double phi = side * theta, d_phidd = -c * side * theta_dot, r_g = m_.radius_m / m_.gravity;
        f.fx += side * r_g * std::cos(m_.alpha - phi) * d_phidd;
        f.fy += r_g * std::sin(m_.alpha - phi) * d_phidd;
        return f;
    }
    /// The ground's work (energy.hpp) and the damper's, -I0 c integral of theta_dot^2, by the
    /// same 3-point Gauss-Legendre rule on the step's Hermite interpolant.
    Works works(int side, const StepEnds& step, double t) const {
        Works w = step_works(m_, 0.0, step, t);
        const double h = t - step.t0;
        if (side == 0 || !(h > 0.0)) return w;
        constexpr double x[3] = {-0.7745966692414834, 0.0, 0.7745966692414834};
        constexpr double wt[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
        for (int i = 0; i < 3; ++i) {
            double th, thd;
            step.at(step.t0 + 0.5 * h * (1.0 + x[i]), th, thd);
            w.anchorage_j -= 0.5 * h * wt[i] * m_.inertia * c * thd * thd;
        }
        return w;
    }
    FreeFate free_fate(int, double) const { return {}; }  // no potential: integrate to rest

private:
    const CellModel& m_;
};
static_assert(AnchorageLaw<Damper>);

/// The S. Matteo block on still ground, released from theta0 at rest.
CellModel released(double theta0, Equations eq) {
    CellModel m = make_cell_model(testing::kSMatteo, free_anchorage(), Pulse{}, eq);
    m.theta0 = theta0;
    return m;
}

std::vector<StepRecord> history(const CellModel& m, double steps_per_period) {
    IntegratorSettings s;
    s.steps_per_period = steps_per_period;
    std::vector<StepRecord> steps;
    const StepObserver obs = [&](const StepRecord& r) { steps.push_back(r); };
    CellResult r;
    kernel::run_lanes<1, Damper>(std::span(&m, 1), std::span(&r, 1), s, &obs);
    EXPECT_EQ(r.outcome, Outcome::safe);
    return steps;
}

/// One swing of the linearised damped block, phi'' = p^2 (phi - alpha) - c phi_dot on the side
/// it rocks on (u = phi - alpha: u'' + c u' - p^2 u = 0), from (phi0, phi_dot0) to its return to
/// phi = 0: u = A e^{r1 t} + B e^{r2 t}. Returns the time taken and the approach speed.
struct Swing {
    double t, speed;
};
Swing linear_swing(double p2, double alpha, double phi0, double w0) {
    const double c = Damper::c, d = std::sqrt(c * c + 4.0 * p2);
    const double r1 = 0.5 * (-c + d), r2 = 0.5 * (-c - d), u0 = phi0 - alpha;
    const double a = (w0 - r2 * u0) / (r1 - r2), b = (r1 * u0 - w0) / (r1 - r2);
    auto phi = [&](double t) { return alpha + a * std::exp(r1 * t) + b * std::exp(r2 * t); };
    // The turning point (u' = 0), or 0 when released at rest; phi falls monotonically after it.
    const double lo0 = w0 > 0.0 ? std::log(-b * r2 / (a * r1)) / (r1 - r2) : 0.0;
    double lo = lo0, hi = lo0 + 1.0;
    while (phi(hi) > 0.0) hi += 1.0;
    for (int i = 0; i < 200 && hi - lo > 0.0; ++i) {
        const double mid = 0.5 * (lo + hi);
        if (mid == lo || mid == hi) break;
        (phi(mid) > 0.0 ? lo : hi) = mid;
    }
    return {hi, -(a * r1 * std::exp(r1 * hi) + b * r2 * std::exp(r2 * hi))};
}

// Linearised, the damped swing has a closed form; the kernel's impacts (times and approach
// speeds, the velocity ratio e applied in between) must follow it to the RK4 error, and fall
// as h^4: the law's term reaches every RK4 stage with the stage's velocity.
TEST(AnchorageLaw, AViscousDamperFollowsTheClosedFormOfDampedRocking) {
    const CellModel m = released(0.6 * testing::kSMatteo.alpha_rad, Equations::linearised);
    auto worst_error = [&](double steps_per_period, int& compared) {
        const std::vector<StepRecord> steps = history(m, steps_per_period);
        double t = 0.0, phi0 = std::abs(m.theta0), w0 = 0.0, worst = 0.0;
        compared = 0;
        for (std::size_t i = 1; i < steps.size() && compared < 6; ++i) {
            const StepRecord& r = steps[i];
            if (!(r.theta0 == 0.0 && r.theta_dot0 != 0.0)) continue;  // the step after an impact
            const Swing sw = linear_swing(m.p2, m.alpha, phi0, w0);
            t += sw.t;
            worst = std::max({worst, std::abs(r.t0 - t) * std::sqrt(m.p2),
                              std::abs(std::abs(steps[i - 1].theta_dot1) - sw.speed) / sw.speed,
                              std::abs(std::abs(r.theta_dot0) - m.e * sw.speed) / sw.speed});
            phi0 = 0.0;
            w0 = m.e * sw.speed;
            ++compared;
        }
        return worst;
    };
    int n_coarse = 0, n_fine = 0;
    const double coarse = worst_error(96.0, n_coarse), fine = worst_error(192.0, n_fine);
    EXPECT_EQ(n_coarse, 6);
    EXPECT_EQ(n_fine, 6);
    EXPECT_LT(fine, 3e-7);  // relative; times in units of 1/p (measured: 1.1e-7)
    EXPECT_GT(coarse / fine, 12.0);  // fourth order: 2^4 (measured: 17.1)
}

// Nonlinear: between impacts the block's energy I0 (theta_dot^2 / 2 + V_g) changes only by the
// damper's work, I0 c times the integral of theta_dot^2, to 1e-8 of that work; and the damper
// takes a real share of the energy (a law whose term the kernel dropped would fail both).
TEST(AnchorageLaw, AViscousDamperDissipatesTheIntegralOfCThetaDotSquared) {
    const CellModel m = released(0.9 * testing::kSMatteo.alpha_rad, Equations::nonlinear);
    const std::vector<StepRecord> steps = history(m, 800.0);
    auto energy = [&](double theta, double theta_dot) {
        return m.inertia * (0.5 * theta_dot * theta_dot + gravity_potential(m, std::abs(theta)));
    };
    double residual = 0.0, work = 0.0, prev_work = 0.0;
    for (const StepRecord& r : steps) {
        const double w = r.work_anchorage - prev_work;
        prev_work = r.work_anchorage;
        residual += energy(r.theta1, r.theta_dot1) - energy(r.theta0, r.theta_dot0) - w;
        work += w;
    }
    const double e0 = energy(m.theta0, 0.0);
    EXPECT_LT(work, -0.2 * e0);  // measured: -0.64 e0
    EXPECT_LT(std::abs(residual), 1e-8 * std::abs(work));  // measured: 5.5e-10
}

// The damper's coefficients take the batch's structure of arrays: a lane gives the same bits
// alone and among three others, whatever they hold.
TEST(AnchorageLaw, ALaneOfABatchGivesTheBitsOfALaneAlone) {
    std::vector<CellModel> cells;
    for (double f : {0.2, 0.5, -0.7, 0.95, 1.3, -0.4, 0.0})
        cells.push_back(released(f * testing::kSMatteo.alpha_rad, Equations::nonlinear));
    cells.back().theta_dot0 = 0.8;  // from theta = 0, moving outward
    const IntegratorSettings s;
    std::vector<CellResult> alone(cells.size()), batch(cells.size());
    kernel::run_lanes<1, Damper>(cells, alone, s, nullptr);
    kernel::run_lanes<4, Damper>(cells, batch, s, nullptr);
    for (std::size_t i = 0; i < cells.size(); ++i) {
        EXPECT_TRUE(bitwise_equal(alone[i], batch[i])) << "cell " << i;
        EXPECT_GT(alone[i].steps, 10);
    }
    EXPECT_EQ(alone[4].outcome, Outcome::overturned_no_impact);  // released past alpha
}

}  // namespace
}  // namespace rocksweep
