#pragma once
// The event functions of a rocking block (physics.md §3-5), handed to the event stepper for one
// step: overturning (|theta| = pi/2), impact (theta = 0), and those its anchorage law brings:
// fracture of the working anchorage and the law's turning point (anchorage_law.hpp). Each is
// positive before its event and <= 0 once it has happened, on the side the step runs on.
#include <algorithm>
#include <cmath>

#include "rocksweep/physics/anchorage_law.hpp"
#include "rocksweep/physics/model.hpp"
#include "rocksweep/physics/system.hpp"
#include "event_stepper.hpp"

namespace rocksweep::kernel {

template <AnchorageLaw Law>
struct RockingEvents {
    const Law& law;
    int side;                   ///< the side the step runs on, +-1
    double theta0, theta_dot0;  ///< the step's start
    bool acting;                ///< the ground moves at the step's start
    const CellModel& m;
    double t0;                  ///< the step's start time [s]

    double g(Event e, double d, double y, double v) const {
        const double s = side;
        switch (e) {
            case Event::overturn: return M_PI / 2 - s * y;
            case Event::fracture: return law.break_angle() - s * y;
            case Event::impact:
                // theta starts at 0 after an impact or uplift: divide out the trivial root.
                if (theta0 != 0.0) return s * y;
                return s * theta_dot0 > 0.0 ? s * y / d : s * y / (d * d);
            case Event::turn: return s * v;
            case Event::trough: return -s * v;
            case Event::none: break;
        }
        return 1.0;
    }

    /// The theta at which e happens, or NaN for an event that is not a level of theta (turn).
    double level(Event e) const {
        const double s = side;
        switch (e) {
            case Event::overturn: return s * M_PI / 2;
            case Event::fracture: return s * law.break_angle();
            case Event::impact: return 0.0;
            case Event::turn:
            case Event::trough:
            case Event::none: break;
        }
        return NAN;
    }

    /// theta'' at time d into the step, in the state (y, v).
    double acceleration(double d, double y, double v) const {
        const double t = t0 + d;
        const Ground g = acting ? Ground{m.pulse.ax(t), m.pulse.ay(t)} : Ground{};
        return rocking::theta_ddot<Law>(rocking::coef(m.p2, m.alpha, side, m.equations == Equations::linearised),
                                        law.coef(side), g, y, v);
    }

    /// No armed event other than e has happened in the state (y, v) at d.
    bool only(Event e, double d, double y, double v) const {
        bool clear = true;
        auto check = [&](Event o) { clear &= o == e || g(o, d, y, v) > 0.0; };
        check(Event::overturn);
        if (law.intact(side)) check(Event::fracture);
        check(Event::impact);
        if (law.turn_armed(side, theta_dot0, acting)) check(Event::turn);
        return clear;
    }

    Event earliest(double d, double y, double v, double& g_min) const {
        Event which = Event::none;
        g_min = INFINITY;
        auto consider = [&](Event e) {
            const double ge = g(e, d, y, v);
            if (ge < g_min) { g_min = ge; which = e; }
        };
        consider(Event::overturn);
        if (law.intact(side)) consider(Event::fracture);
        consider(Event::impact);
        if (law.turn_armed(side, theta_dot0, acting)) consider(Event::turn);
        return which;
    }

    /// |theta| can pass theta_f and come back within one step, unseen at its ends. True if the
    /// step turns (s theta_dot from > 0 to < 0) and the cubic Hermite peak comes within a
    /// margin of the fracture angle: the interpolant's O(dt^4) error, covered by a tenth of the
    /// peak's rise above the ends (O(dt^2)), and the RK4 states' own; the located turning point
    /// then decides.
    bool grazes(double dt, double y1, double v1) const {
        if (!law.intact(side)) return false;
        const double s = side, v0 = theta_dot0, y0 = theta0;
        if (!(s * v0 > 0.0 && s * v1 < 0.0)) return false;
        const double peak = s * hermite_peak(dt, y0, v0, y1, v1);
        const double ends = std::max(s * y0, s * y1);
        const double brk = law.break_angle();
        return peak >= brk - (1e-4 * brk + 0.1 * (peak - ends));
    }

    /// theta can pass 0 and come back within one step, unseen at its ends (both on the step's
    /// side): true if s theta turns from falling to rising inside the step (not from theta = 0,
    /// where the trivial root is the start) and the cubic Hermite trough comes within a tenth of
    /// its dip below the ends of 0, the same margin as grazes(); the located trough decides.
    bool dips(double dt, double y1, double v1) const {
        const double s = side, v0 = theta_dot0, y0 = theta0;
        if (y0 == 0.0 || !(s * v0 < 0.0 && s * v1 > 0.0)) return false;
        const double trough = s * hermite_peak(dt, y0, v0, y1, v1);
        const double ends = std::min(s * y0, s * y1);
        return trough <= 0.1 * (ends - trough);
    }
};

}  // namespace rocksweep::kernel
