#pragma once
/// What an anchorage law is to the kernel (issue 8, seam 2): one type that the lane, its event
/// functions, its observers and the W-lane RK4 batch are templated on, so that a new law (a
/// spring of another shape, a viscous damper) is a new type and no change to the event stepper
/// or the batch. The shipped law is Eq. 8's elastic-brittle spring, constant or adaptive
/// (kernel::Springs, src/physics/springs.hpp, on spring_law.hpp); integrate_cells picks a law
/// per cell from its AnchorageKind (with_law, src/physics/integrator.cpp).
/// docs/physics_kernel.md, "Anchorage laws", says how one is added.
///
/// An object of the law is one cell's anchorage: built from the cell, it keeps what changes over
/// the run (a broken spring, the adaptive law's K) and answers for the side the block rocks on
/// (side = +-1; 0 at rest, where no anchorage acts).
#include <concepts>
#include <cstdint>

#include "rocksweep/physics/energy.hpp"
#include "rocksweep/physics/model.hpp"
#include "rocksweep/physics/step.hpp"

namespace rocksweep {

template <class L>
concept AnchorageLaw = std::constructible_from<L, const CellModel&> &&
    requires(L& law, const L& c, const typename L::Coef& k, typename L::template Soa<1>& soa, const CellModel& m,
             int side, double x, bool acting, double (*ax)(), const StepEnds& step) {
    // ---- The kernel (branch-free, the same bits per lane alone and in a vector).
    // Coef: a lane's coefficients as doubles, equality-comparable (a change is a jump of the
    // force: the observers start a new phase); Soa<W>: W of them as the lane loop holds them.
    { c.coef(side) } -> std::same_as<typename L::Coef>;
    { k == k } -> std::same_as<bool>;
    soa.store(0, k);
    { soa.load(0) } -> std::same_as<typename L::Coef>;
    // The law's term r of theta'' = gravity's - r on side s at (theta, theta_dot), per unit I0
    // [1/s^2], signed (system.hpp); linear, nl = 1 - linear select the linearised equations.
    // term<false> is called when no lane of the batch acts(): it may skip its work.
    { L::template term<true>(k, x, x, x, x, x) } -> std::same_as<double>;
    { L::template term<false>(k, x, x, x, x, x) } -> std::same_as<double>;
    { L::acts(k) } -> std::same_as<bool>;
    // Its fastest time scale [rad/s] (the step is a fraction of the cell's fastest).
    { L::omega(m) } -> std::convertible_to<double>;

    // ---- Events it brings (rocking_events.hpp): fracture where its function break_angle() -
    // s theta reaches 0 while intact(side); a turning point when turn_armed(), then at_turn().
    { c.intact(side) } -> std::same_as<bool>;
    { c.broken(side) } -> std::same_as<bool>;
    { c.break_angle() } -> std::convertible_to<double>;
    law.fracture(side);
    { c.turn_armed(side, x, acting) } -> std::same_as<bool>;
    law.at_turn(side, x);
    // Its own switches: at uplift from rest, at a start from a given state, after every
    // accepted step (ax(): the ground over the coming interval, asked only if needed), and the
    // paper's one-step-behind variant. switches_at_ground_zeros(): steps end at zeros of ax.
    { c.switches_at_ground_zeros() } -> std::same_as<bool>;
    law.at_uplift();
    law.at_start(side, x, x, acting, ax);
    law.follow_law(side, x, x, acting, ax);
    law.follow_law_lagged(side, x, x, acting, ax);

    // ---- What the observers and the energy decision ask.
    { c.anchored() } -> std::same_as<bool>;                    ///< a peak force is reported
    { c.force_ratio(x) } -> std::convertible_to<double>;        ///< F / F_u at |theta| = x
    { c.broken_bits() } -> std::same_as<std::uint8_t>;
    { c.switch_energy() } -> std::convertible_to<double>;       ///< [J] put in by its switches
    { c.stiffness_n_m(side) } -> std::convertible_to<double>;   ///< for histories
    // The pivot's reactions (model.hpp) at (theta, theta_dot) under (ax, ay).
    { c.reactions(side, x, x, x, x) } -> std::same_as<BaseReactions>;
    // Its work over [step.t0, t] of one step [J], with the ground's.
    { c.works(side, step, x) } -> std::same_as<Works>;
    // After the excitation: the fate of the block moving outward on side at speed x just
    // after an impact, from the law's potential; undecided when it has none.
    { c.free_fate(side, x) } -> std::same_as<FreeFate>;
};

}  // namespace rocksweep
