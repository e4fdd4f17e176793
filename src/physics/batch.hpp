#pragma once
// The W-lane RK4 step of the kernel: one classical RK4 step per lane over a batch of cells, of
// the equation of motion in system.hpp. Knows the ground only through the families' lane()
// functions (excitation/*.hpp), or for a nodal family (a record) through the values at the
// step's nodes that its lane hands in, and the anchorage only through its law's term (Law, an
// AnchorageLaw); where a step ends and what its end means is the event stepper's and the
// cell's business (event_stepper.hpp, lane.hpp).
#include <array>
#include <cstdlib>
#include <type_traits>

#include "rocksweep/physics/anchorage_law.hpp"
#include "rocksweep/physics/excitation.hpp"
#include "rocksweep/physics/fastmath.hpp"
#include "rocksweep/physics/system.hpp"

namespace rocksweep::kernel {

// The lane loop is branch-free so that GCC vectorises it and a lane gives the same bits alone
// and in a vector: the equation of motion (system.hpp) is written so; sin/cos are
// rocksweep::fastmath (odd/even bitwise).

/// Per-lane coefficients of one step (as Lane writes them).
template <AnchorageLaw Law>
struct RhsLane {
    double p2, alpha;
    typename Law::Coef law;  ///< the anchorage law's
    double t_cut;  ///< ground moves at stage times t < t_cut
    int side;
    bool linear;
    const Pulse* pulse = nullptr;  ///< its family and kind
    GroundLane ground;             ///< its family's lane coefficients
    std::array<Ground, 3> nodes{}; ///< a nodal family's ground at t, t + h/2, t + h (set by the lane)
};

/// A batch whose lanes are not all of one vectorised family: each lane takes its own family's
/// ground, outside the vector loop, with the same lane() (or nodes) as alone.
struct PerLane {};

/// One classical RK4 step per lane; y = (theta, theta_dot). The lane loop is branch-free
/// and vectorised for one analytic family; every lane computes the same operation sequence
/// as W = 1.
template <int W, AnchorageLaw Law>
struct Batch {
    std::array<RhsLane<Law>, W> c{};  ///< written by Lane::prepare
    std::array<double, W> t0{}, y0{}, v0{}, dt{}, y1{}, v1{}, a0{};
    /// A record's steps only (nodal families): the local error of (y1, v1) as estimated by the
    /// embedded third-order pair of RK4 with the end's slope, h/6 (k4 - f(t + h, y1)) (its
    /// weights 1/6, 1/3, 1/3, 0, 1/6 meet the four third-order conditions). The theta part is
    /// free (k4's theta is v + h k3v, f's is v1); the theta_dot part costs a fifth evaluation.
    std::array<double, W> err_y{}, err_v{};

    /// The coefficients as structure of arrays, and the in-pulse factors of the stage times.
    struct Soa {
        alignas(64) double p2[W], alpha[W], side[W], linear[W];
        typename Law::template Soa<W> law;
        alignas(64) double ax_g[W], ay_g[W], omega[W], phase[W], phase_y[W], t_ref[W];
        alignas(64) double in0[W], inm[W], in1[W];
        alignas(64) double ax_node[3][W], ay_node[3][W];  ///< a nodal family's ground
    } k{};

    /// Batch-uniform shortcuts, which give the same bits per lane as the full computation:
    /// no lane in the pulse (every ground value +0), no lane with a vertical component (ay +0),
    /// no lane where the anchorage acts (its term<false>). Lanes of any records share a batch.
    void step() {
        bool any_in = false, any_y = false, any_acts = false, mixed = false;
        int first_i = 0;  // the first lane that ever held a cell
        for (int i = W - 1; i >= 0; --i)
            if (c[i].pulse) first_i = i;
        const Pulse* first = c[first_i].pulse;
        for (int i = 0; i < W; ++i) {
            const rocking::Coef l = rocking::coef(c[i].p2, c[i].alpha, c[i].side, c[i].linear);
            k.p2[i] = l.p2; k.alpha[i] = l.alpha; k.side[i] = l.side; k.linear[i] = l.linear;
            k.law.store(i, c[i].law);
            const GroundLane& g = c[i].ground;
            k.ax_g[i] = g.ax_g; k.ay_g[i] = g.ay_g; k.omega[i] = g.omega;
            k.phase[i] = g.phase; k.phase_y[i] = g.phase_y; k.t_ref[i] = g.t_ref;
            for (int j = 0; j < 3; ++j) {
                k.ax_node[j][i] = c[i].nodes[j].ax;
                k.ay_node[j][i] = c[i].nodes[j].ay;
            }
            const double h = dt[i], t = t0[i];
            k.in0[i] = t < c[i].t_cut ? 1.0 : 0.0;
            k.inm[i] = t + 0.5 * h < c[i].t_cut ? 1.0 : 0.0;
            k.in1[i] = t + h < c[i].t_cut ? 1.0 : 0.0;
            any_in |= t < c[i].t_cut;  // dt >= 0: the later stage times are not earlier
            any_y |= g.ay_g != 0.0;
            any_acts |= Law::acts(c[i].law);
            mixed |= c[i].pulse && c[i].pulse->kind != first->kind;
        }
        if (mixed) return lanes<PerLane, true, true, true>(*this);
        visit(*first, [&](const auto& e) {
            using F = std::decay_t<decltype(e)>;
            if constexpr (F::vectorised) family<F>(any_in, any_in && any_y, any_acts);
            else lanes<PerLane, true, true, true>(*this);
        });
    }

    template <class F>
    void family(bool in, bool y, bool acts) {
        switch ((in ? 1 : 0) + (y ? 2 : 0) + (acts ? 4 : 0)) {
            case 0: return run<F, false, false, false>();
            case 1: return run<F, true, false, false>();
            case 3: return run<F, true, true, false>();
            case 4: return run<F, false, false, true>();
            case 5: return run<F, true, false, true>();
            default: return run<F, true, true, true>();
        }
    }

    /// Same operations either way (AVX2 without FMA, -ffp-contract=off): same bits.
    template <class F, bool pulse, bool with_y, bool acts>
    void run() {
        if (use_avx2()) lanes_avx2<F, pulse, with_y, acts>(*this);
        else lanes<F, pulse, with_y, acts>(*this);
    }

    static bool use_avx2() {
#if defined(__x86_64__) || defined(__i386__)
        static const bool yes = W > 1 && __builtin_cpu_supports("avx2") && !std::getenv("ROCKSWEEP_NO_AVX2");
        return yes;
#else
        return false;
#endif
    }

    /// The ground of lane i at node j (0, 1, 2: t, t + h/2, t + h) at time t; `in` = 0 outside the
    /// pulse's window.
    template <class F, bool with_y>
    [[gnu::always_inline]] inline Ground ground(int i, int j, const GroundLane& g, double t, double in) const {
        if constexpr (std::is_same_v<F, PerLane>) {
            if (!c[i].pulse) return Ground{};  // a lane that never held a cell
            return visit(*c[i].pulse, [&](const auto& e) {
                using G = std::decay_t<decltype(e)>;
                if constexpr (G::nodal) return c[i].nodes[j];
                else return G::template lane<true>(c[i].ground, t, in);
            });
        } else if constexpr (F::nodal) {
            return Ground{k.ax_node[j][i], k.ay_node[j][i]};
        } else {
            return F::template lane<with_y>(g, t, in);
        }
    }

    /// The error estimate is made where steps follow it: under records (and in mixed batches).
    template <class F>
    static constexpr bool estimates_of() {
        if constexpr (std::is_same_v<F, PerLane>) return true;
        else return F::nodal;
    }
    template <class F>
    static constexpr bool estimates = estimates_of<F>();

    template <class F, bool pulse, bool with_y, bool acts>
    [[gnu::always_inline]] static inline void lanes_body(Batch& b) {
        for (int i = 0; i < W; ++i) {
            const rocking::Coef l{b.k.p2[i], b.k.alpha[i], b.k.side[i], b.k.linear[i]};
            const typename Law::Coef lk = b.k.law.load(i);
            GroundLane gl;
            gl.ax_g = b.k.ax_g[i]; gl.ay_g = b.k.ay_g[i]; gl.omega = b.k.omega[i];
            gl.phase = b.k.phase[i]; gl.phase_y = b.k.phase_y[i]; gl.t_ref = b.k.t_ref[i];
            const double h = b.dt[i], t = b.t0[i], y = b.y0[i], v = b.v0[i];
            // The ground at t, t + h/2 (shared by k2 and k3) and t + h.
            Ground g0, gm, g1;
            if constexpr (pulse) {
                g0 = b.template ground<F, with_y>(i, 0, gl, t, b.k.in0[i]);
                gm = b.template ground<F, with_y>(i, 1, gl, t + 0.5 * h, b.k.inm[i]);
                g1 = b.template ground<F, with_y>(i, 2, gl, t + h, b.k.in1[i]);
            }
            // k1 = f(t, y)
            const double k1y = v, k1v = rocking::theta_ddot<Law, acts>(l, lk, g0, y, k1y);
            // k2 = f(t + h/2, y + h/2 k1)
            const double k2y = v + 0.5 * h * k1v, k2v = rocking::theta_ddot<Law, acts>(l, lk, gm, y + 0.5 * h * k1y, k2y);
            // k3 = f(t + h/2, y + h/2 k2)
            const double k3y = v + 0.5 * h * k2v, k3v = rocking::theta_ddot<Law, acts>(l, lk, gm, y + 0.5 * h * k2y, k3y);
            // k4 = f(t + h, y + h k3)
            const double k4y = v + h * k3v, k4v = rocking::theta_ddot<Law, acts>(l, lk, g1, y + h * k3y, k4y);
            b.y1[i] = y + h / 6.0 * (k1y + 2.0 * k2y + 2.0 * k3y + k4y);
            b.v1[i] = v + h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
            b.a0[i] = k1v;
            if constexpr (estimates<F>) {
                const double y1 = b.y1[i], v1 = b.v1[i];
                const double k5v = rocking::theta_ddot<Law, acts>(l, lk, g1, y1, v1);
                b.err_y[i] = h / 6.0 * (k4y - v1);
                b.err_v[i] = h / 6.0 * (k4v - k5v);
            }
        }
    }
    template <class F, bool pulse, bool with_y, bool acts>
    static void lanes(Batch& b) {
        lanes_body<F, pulse, with_y, acts>(b);
    }
    // The same loop compiled for AVX2 (no FMA: the bits stay those of the baseline build).
#if defined(__x86_64__) || defined(__i386__)
    template <class F, bool pulse, bool with_y, bool acts>
    __attribute__((target("avx2"))) static void lanes_avx2(Batch& b) {
        lanes_body<F, pulse, with_y, acts>(b);
    }
#else
    template <class F, bool pulse, bool with_y, bool acts>
    static void lanes_avx2(Batch& b) {
        lanes_body<F, pulse, with_y, acts>(b);
    }
#endif
};

}  // namespace rocksweep::kernel
