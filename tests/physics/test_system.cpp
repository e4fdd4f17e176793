// The seams of the kernel (issue 8): the system (system.hpp) is the one source of the equation
// of motion and the anchorage law, and the event stepper locates events of any system it is
// handed, knowing no physics.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>

#include "../../src/physics/event_stepper.hpp"
#include "rocksweep/physics/spring_law.hpp"
#include "rocksweep/physics/system.hpp"

namespace rocksweep {
namespace {

std::uint64_t bits(double x) { return std::bit_cast<std::uint64_t>(x); }

// The base reactions evaluate the equation on phi = s theta as side +1 under the mirrored
// ground (s ax, ay); the kernel evaluates it on side s. Mirror symmetry (physics.md §2) must
// hold to the bit, or the friction demand would use another equation than the motion.
TEST(System, TheMirrorImageIsTheSameEquationToTheBit) {
    std::mt19937_64 rng(8);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const double p2 = 5.283, alpha = 0.2171;
    for (int linear = 0; linear <= 1; ++linear)
        for (int i = 0; i < 20000; ++i) {
            const int side = u(rng) > 0.0 ? 1 : -1;
            const double kappa = i % 3 == 0 ? 0.0 : 40.0 * (1.0 + u(rng));
            const double theta = side * 1.5 * std::abs(u(rng)), ax = 3.0 * u(rng), ay = 0.5 * u(rng);
            const auto k = rocking::SpringLaw::coef(kappa);
            const double on_side =
                rocking::theta_ddot<rocking::SpringLaw>(rocking::coef(p2, alpha, side, linear), k, Ground{ax, ay}, theta, 0.0);
            const double mirrored = rocking::theta_ddot<rocking::SpringLaw>(rocking::coef(p2, alpha, 1, linear), k,
                                                                            Ground{side * ax, ay}, side * theta, 0.0);
            ASSERT_EQ(bits(side * on_side), bits(mirrored)) << "theta " << theta << " side " << side;
        }
}

// The energy decision's potential slope uses the C library's sine and its Newton iteration the
// sin(phi/4) form of the spring law: the same law to rounding.
TEST(System, TheFormsOfTheSpringLawAgreeToRounding) {
    const double kappa = 37.0;
    for (double phi = 0.0; phi <= M_PI / 2; phi += 1e-3) {
        double v, moment;
        using rocking::SpringLaw;
        SpringLaw::potential_and_moment(kappa, phi, v, moment);
        EXPECT_NEAR(moment, kappa * SpringLaw::shape(0.5 * phi, 0.0, 1.0), 4e-16 * kappa);
        EXPECT_NEAR(moment, kappa * SpringLaw::shape<rocking::LibmTrig>(0.5 * phi, 0.0, 1.0), 4e-16 * kappa);
        EXPECT_NEAR(v, SpringLaw::potential(kappa, phi, false), 4e-16 * kappa);
        EXPECT_NEAR(v, 2.0 * kappa * (1.0 - std::cos(0.5 * phi)), 1e-13 * kappa);
    }
}

// ---- The event stepper on systems that are not a rocking block.

/// y'' = -y from (1, 0): the "RK4 step" of length d is the exact solution, so the located
/// root is the event function's own, and the stepper's accuracy is measured alone.
struct Oscillator {
    static void step(double d, double& y, double& v) {
        y = std::cos(d);
        v = -std::sin(d);
    }
};

/// Events of the oscillator: `impact` at y = 0; `fracture` at y = fracture_at on the way up; turning
/// points (v = 0) are `turn`. grazes() flags every step that turns.
struct ToyEvents {
    double fracture_at = 2.0;  ///< above the motion: no fracture
    double y0 = 1.0, v0 = 0.0;
    double g(kernel::Event e, double, double y, double v) const {
        switch (e) {
            case kernel::Event::impact: return y;
            case kernel::Event::fracture: return fracture_at - y;
            case kernel::Event::turn: return v;
            default: return 1.0;
        }
    }
    kernel::Event earliest(double d, double y, double v, double& g_min) const {
        g_min = g(kernel::Event::impact, d, y, v);
        kernel::Event which = kernel::Event::impact;
        if (const double gf = g(kernel::Event::fracture, d, y, v); gf < g_min) {
            g_min = gf;
            which = kernel::Event::fracture;
        }
        return which;
    }
    bool grazes(double, double, double v1) const { return v0 > 0.0 && v1 < 0.0; }
    double level(kernel::Event e) const {
        return e == kernel::Event::impact ? 0.0 : e == kernel::Event::fracture ? fracture_at : NAN;
    }
    double acceleration(double, double y, double) const { return -y; }
    bool only(kernel::Event e, double d, double y, double v) const {
        for (kernel::Event o : {kernel::Event::impact, kernel::Event::fracture})
            if (o != e && g(o, d, y, v) <= 0.0) return false;
        return true;
    }
};

struct Accepted {
    double dt = NAN, y = NAN, v = NAN;
    kernel::Event event = kernel::Event::none;
    bool interior = false;
    int trials = 0;
};

/// Runs trial steps from (y0, v0) = the motion `f` at `t0` until the stepper accepts one.
template <class Motion>
Accepted run_step(const ToyEvents& ev, double t0, double dt, Motion&& f) {
    kernel::EventStepper stepper;
    Accepted a;
    double y1, v1;
    for (double d = dt; a.trials < 200; d = stepper.trial()) {
        ++a.trials;
        f(t0 + d, y1, v1);
        bool done = false;
        stepper.finish(ev, t0, ev.y0, ev.v0, d, y1, v1, [&](double h, double y, double v, kernel::Event e, bool interior) {
            a = {h, y, v, e, interior, a.trials};
            done = true;
        });
        if (done) return a;
        EXPECT_TRUE(stepper.searching());
    }
    ADD_FAILURE() << "no step accepted";
    return a;
}

TEST(EventStepper, AStepWithoutEventsIsAcceptedWhole) {
    const ToyEvents ev;
    const Accepted a = run_step(ev, 0.0, 1.0, [](double t, double& y, double& v) { Oscillator::step(t, y, v); });
    EXPECT_EQ(a.trials, 1);
    EXPECT_EQ(a.event, kernel::Event::none);
    EXPECT_FALSE(a.interior);
    EXPECT_EQ(a.dt, 1.0);
}

TEST(EventStepper, LocatesTheEarliestRootOfTheFunctionsItIsHanded) {
    const ToyEvents ev;  // y = cos t crosses 0 at pi/2
    const Accepted a = run_step(ev, 0.0, 2.5, [](double t, double& y, double& v) { Oscillator::step(t, y, v); });
    EXPECT_EQ(a.event, kernel::Event::impact);
    EXPECT_NEAR(a.dt, M_PI / 2, 1e-12 * M_PI / 2);  // the bracket's final width: 1e-12 of the root
    EXPECT_LE(a.y, 0.0);  // the accepted end is on the far side: the event has happened
    EXPECT_LT(a.trials, 40);
}

// A step of the size the kernel takes (0.05 of a period of 2 pi): the first re-run goes to the
// root of the cubic Hermite interpolant, and the second-order Taylor step from there lands on
// the level: the root to rounding, in one re-run.
TEST(EventStepper, AnEventAtALevelIsProjectedOntoItInOneReRun) {
    const double t0 = M_PI / 2 - 0.2;
    ToyEvents ev;
    Oscillator::step(t0, ev.y0, ev.v0);
    const Accepted a = run_step(ev, t0, 0.3, [](double t, double& y, double& v) { Oscillator::step(t, y, v); });
    EXPECT_EQ(a.event, kernel::Event::impact);
    EXPECT_NEAR(t0 + a.dt, M_PI / 2, 1e-14);
    EXPECT_EQ(a.y, 0.0);
    EXPECT_NEAR(a.v, -1.0, 1e-12);  // O(delta^2): theta''' delta^2 / 2, delta ~ 1e-6
    EXPECT_EQ(a.trials, 2) << "1 whole step + 1 re-run";
}

// Where the interpolant is poor (a step of 0.4 of a period), the projection would be large: the
// re-runs bracket the root to 1e-12 of the step instead.
TEST(EventStepper, ALongStepFindsItsRootInAFewReRuns) {
    const double t0 = M_PI / 2 - 1.2;
    ToyEvents ev;
    Oscillator::step(t0, ev.y0, ev.v0);
    const Accepted a = run_step(ev, t0, 2.5, [](double t, double& y, double& v) { Oscillator::step(t, y, v); });
    EXPECT_EQ(a.event, kernel::Event::impact);
    EXPECT_NEAR(t0 + a.dt, M_PI / 2, 4e-12 * 2.5);
    EXPECT_LE(a.y, 0.0);
    EXPECT_GT(a.trials, 2) << "not projected";
    EXPECT_LE(a.trials, 8) << "1 whole step + the re-runs";
}

// theta computed as y0 + (a small increment) rounds to exactly 0 near an impact: a trial on
// which the function is 0 is a root, and the search ends there instead of bisecting on to the
// tolerance (regula falsi cannot move off an end whose value is 0). Here the motion rounds to a
// grid of 1e-9, so a whole interval around the crossing reads 0.
TEST(EventStepper, ATrialOnWhichTheFunctionIsZeroEndsTheSearch) {
    const double t0 = M_PI / 2 - 0.2;
    ToyEvents ev;
    Oscillator::step(t0, ev.y0, ev.v0);
    const Accepted a = run_step(ev, t0, 0.3, [](double t, double& y, double& v) {
        Oscillator::step(t, y, v);
        y = std::round(y * 1e9) / 1e9;
    });
    EXPECT_EQ(a.event, kernel::Event::impact);
    EXPECT_EQ(a.y, 0.0);
    EXPECT_NEAR(t0 + a.dt, M_PI / 2, 1e-9);
    EXPECT_LE(a.trials, 8);
}

// A peak inside the step above the fracture level, with both ends below it: the stepper
// locates the turning point, finds the fracture function <= 0 there and locates the fracture
// in (0, peak].
TEST(EventStepper, AGrazingPeakIsCheckedAtItsTurningPoint) {
    ToyEvents ev;
    ev.fracture_at = 0.99;
    ev.y0 = 0.0;
    ev.v0 = 1.0;  // y = sin t: peak 1 at pi/2, y(3) = 0.14
    const Accepted a = run_step(ev, 0.0, 3.0, [](double t, double& y, double& v) {
        y = std::sin(t);
        v = std::cos(t);
    });
    EXPECT_EQ(a.event, kernel::Event::fracture);
    EXPECT_NEAR(a.dt, std::asin(0.99), 1e-10);
    // Below the peak the spring holds: the step ends at the turning point, inside the step.
    ev.fracture_at = 1.001;
    const Accepted b = run_step(ev, 0.0, 3.0, [](double t, double& y, double& v) {
        y = std::sin(t);
        v = std::cos(t);
    });
    EXPECT_EQ(b.event, kernel::Event::none);
    EXPECT_TRUE(b.interior);
    EXPECT_NEAR(b.dt, M_PI / 2, 1e-10);
}

}  // namespace
}  // namespace rocksweep
