#pragma once
/// Branch-free sin / cos for the RK4 kernel, written so that GCC auto-vectorises loops that call
/// them and so that a value is the same bits in a scalar loop and in a vector loop.
///
/// Why the bits agree: the functions use only IEEE +, -, * and fabs (no branches, no library
/// calls, no integer conversion, no table look-ups). With -ffp-contract=off no a*b+c is fused,
/// so each vector lane performs exactly the scalar operation sequence; round-to-nearest is the
/// only rounding mode assumed. Do not build this with -ffast-math, -Ofast,
/// -fassociative-math or -ffp-contract=fast: the magic-number rounding below (v + M) - M and
/// the evaluation order must survive as written.
///
/// Method: x = k pi/2 + r with k = nearest integer to x 2/pi (ties to even, via the 1.5*2^52
/// trick, hence symmetric: k(-x) = -k(x)), r from a three-part Cody-Waite reduction
/// (|r| <= pi/4 (1 + eps)); sin r and cos r from minimax-type polynomials (weighted least-squares
/// fits refined by Lawson iterations, fitted for this file; relative error < 4e-18 for sin,
/// absolute < 5e-20 for cos on |r| <= pi/4), and the quadrant q = k mod 4 applied by exact
/// arithmetic (no selects, no branches).
///
/// Properties:
///  * sin(-x) == -sin(x) and cos(-x) == cos(x) bitwise (r, k are negated exactly; the sine
///    polynomial is odd in r, the cosine even);
///  * sin(+-0) = +-0; finite results for finite x;
///  * valid for |x| < 2^20 pi/2 (k pi/2 hi part exact); accuracy measured by
///    benchmarks/bench_trig.cpp: about 1 ULP on |x| <= 2 and on [-2 pi, 4 pi];
///  * no errno, no exceptions beyond inexact.
#include <cmath>
#include <cstddef>

namespace rocksweep::fastmath {

namespace detail {
inline constexpr double kRound = 0x1.8p52;            // (v + kRound) - kRound = nearest integer
inline constexpr double kTwoOverPi = 0x1.45f306dc9c883p-1;
inline constexpr double kPio2_1 = 0x1.921fb54400000p+0;  // pi/2, 33 significant bits
inline constexpr double kPio2_2 = 0x1.0b4611a600000p-34; // next 33 bits
inline constexpr double kPio2_3 = 0x1.3198a2e037073p-69; // the rest
// sin r = r + r^3 (S1 + z S2 + ... + z^5 S6), z = r^2
inline constexpr double S1 = -0x1.5555555555549p-3, S2 = 0x1.111111110f880p-7,
                        S3 = -0x1.a01a019c125fep-13, S4 = 0x1.71de35786bd85p-19,
                        S5 = -0x1.ae5e66ced6b3ep-26, S6 = 0x1.5d932daa083dfp-33;
// cos r = 1 - z/2 + z^2 (C1 + z C2 + ... + z^5 C6)
inline constexpr double C1 = 0x1.555555555554cp-5, C2 = -0x1.6c16c16c15184p-10,
                        C3 = 0x1.a01a019cb25eap-16, C4 = -0x1.27e4f80a6b90dp-22,
                        C5 = 0x1.1ee9ec40e91d7p-29, C6 = -0x1.8faecbe570c68p-37;

/// The reduced argument's polynomials and the quadrant q = k mod 4 in {-2, -1, 0, 1, 2}.
[[gnu::always_inline]] inline void kernel(double x, double& ps, double& pc, double& q) {
    const double k = (x * kTwoOverPi + kRound) - kRound;
    const double r = ((x - k * kPio2_1) - k * kPio2_2) - k * kPio2_3;
    const double z = r * r;
    // copysign: sin r has the sign of r, and so has the sum except at r = -0 (-0 + +0 = +0);
    // this keeps sin(-0) = -0. Bit operations, vectorised.
    ps = std::copysign(r + r * z * (S1 + z * (S2 + z * (S3 + z * (S4 + z * (S5 + z * S6))))), r);
    const double hz = 0.5 * z;
    const double w = 1.0 - hz;
    // 1 - z/2 + tail, with the rounding error of 1 - z/2 added back in (exact: Sterbenz).
    pc = w + (((1.0 - w) - hz) + z * z * (C1 + z * (C2 + z * (C3 + z * (C4 + z * (C5 + z * C6))))));
    q = k - 4.0 * ((k * 0.25 + kRound) - kRound);  // exact, symmetric in k
}

/// The quadrant by arithmetic, with no selects at all: x = r + q pi/2, so
///   sin x = sin r cos(q pi/2) + cos r sin(q pi/2),  cos x = cos r cos(q pi/2) - sin r sin(q pi/2),
/// with cq = cos(q pi/2) = 1 - |q| and sq = sin(q pi/2) = q (2 - |q|) for q in {-2..2}: one of
/// them is +-1 and the other +-0, so each product and the sum are exact. (A ternary between
/// two computed values would let GCC sink one operand's arithmetic into a branch; with
/// -ftrapping-math, the default, the loop then does not vectorise.) nsq = -sq with +0 for 0,
/// so that sin(-0) = -0 and sin stays exactly odd.
[[gnu::always_inline]] inline double quadrant_sin(double q, double ps, double pc) {
    const double aq = std::fabs(q);
    const double nsq = ((0.0 - q) * (2.0 - aq)) + 0.0;
    return ps * (1.0 - aq) - pc * nsq;
}
[[gnu::always_inline]] inline double quadrant_cos(double q, double ps, double pc) {
    const double aq = std::fabs(q);
    return pc * (1.0 - aq) - ps * (q * (2.0 - aq));
}
}  // namespace detail

/// sin x; branch-free.
[[gnu::always_inline]] inline double sin(double x) {
    double ps, pc, q;
    detail::kernel(x, ps, pc, q);
    return detail::quadrant_sin(q, ps, pc);
}

/// cos x; branch-free.
[[gnu::always_inline]] inline double cos(double x) {
    double ps, pc, q;
    detail::kernel(x, ps, pc, q);
    return detail::quadrant_cos(q, ps, pc);
}

/// sin x and cos x from one reduction; branch-free.
[[gnu::always_inline]] inline void sincos(double x, double& s, double& c) {
    double ps, pc, q;
    detail::kernel(x, ps, pc, q);
    s = detail::quadrant_sin(q, ps, pc);
    c = detail::quadrant_cos(q, ps, pc);
}

/// Array forms: blocks of 8 with a fixed trip count, which GCC vectorises even at -O2 (GCC 12's
/// "very cheap" cost model), then a scalar tail (same bits).
inline void sin(const double* __restrict x, double* __restrict y, std::size_t n) {
    std::size_t i = 0;
    for (; i + 8 <= n; i += 8)
        for (std::size_t j = 0; j < 8; ++j) y[i + j] = fastmath::sin(x[i + j]);
    for (; i < n; ++i) y[i] = fastmath::sin(x[i]);
}
inline void cos(const double* __restrict x, double* __restrict y, std::size_t n) {
    std::size_t i = 0;
    for (; i + 8 <= n; i += 8)
        for (std::size_t j = 0; j < 8; ++j) y[i + j] = fastmath::cos(x[i + j]);
    for (; i < n; ++i) y[i] = fastmath::cos(x[i]);
}
inline void sincos(const double* __restrict x, double* __restrict s, double* __restrict c, std::size_t n) {
    std::size_t i = 0;
    for (; i + 8 <= n; i += 8)
        for (std::size_t j = 0; j < 8; ++j) fastmath::sincos(x[i + j], s[i + j], c[i + j]);
    for (; i < n; ++i) fastmath::sincos(x[i], s[i], c[i]);
}

}  // namespace rocksweep::fastmath
