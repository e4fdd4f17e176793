// Throughput and accuracy of sin / cos implementations on the argument ranges of the RK4 kernel,
// and whether each vector implementation gives the same bits as its scalar use.
//   rhs:    sin, cos of a = s alpha - theta,  |a| <= 2
//   ground: sin(omega t + phase),             [-2 pi, 4 pi]
//   spring: sin(s theta / 2),                 |x| <= 0.8
// Variants: glibc scalar; SLEEF scalar (Sleef_sin_u10 ...), SSE2 (2 lanes) and AVX2 (4 lanes),
// u10 and u35; rocksweep::fastmath in a scalar loop, auto-vectorised at SSE2 and at AVX2.
// Build flags as the project (-O2 -ffp-contract=off). Times: min over repeats, ns per element.
// Usage: bench_trig [reps]
#include <immintrin.h>
#include <sleef.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "rocksweep/physics/fastmath.hpp"

// sleef.h declares the AVX2 entry points only when compiling with -mavx (__AVX__); this file is
// built for baseline x86-64 and calls them behind a CPU check, so it declares them itself.
#ifndef __AVX__
struct Sleef___m256d_2 {
    __m256d x, y;
};
extern "C" {
__m256d Sleef_sind4_u10avx2(__m256d);
__m256d Sleef_cosd4_u10avx2(__m256d);
__m256d Sleef_sind4_u35avx2(__m256d);
__m256d Sleef_cosd4_u35avx2(__m256d);
Sleef___m256d_2 Sleef_sincosd4_u10avx2(__m256d);
Sleef___m256d_2 Sleef_sincosd4_u35avx2(__m256d);
}
#endif

namespace fm = rocksweep::fastmath;
using Fn = void (*)(const double*, double*, double*, std::size_t);  // x -> (sin, cos); either may be unused

namespace {

// Keeps a value in a register as a scalar: the loop around it cannot be vectorised.
inline double opaque(double x) {
    asm volatile("" : "+x"(x));
    return x;
}

// ---- glibc ----
void glibc_sin(const double* x, double* s, double*, std::size_t n) { for (std::size_t i = 0; i < n; ++i) s[i] = std::sin(x[i]); }
void glibc_cos(const double* x, double*, double* c, std::size_t n) { for (std::size_t i = 0; i < n; ++i) c[i] = std::cos(x[i]); }
void glibc_sincos(const double* x, double* s, double* c, std::size_t n) { for (std::size_t i = 0; i < n; ++i) ::sincos(x[i], &s[i], &c[i]); }

// ---- SLEEF scalar ----
void sl_sin_u10(const double* x, double* s, double*, std::size_t n) { for (std::size_t i = 0; i < n; ++i) s[i] = Sleef_sin_u10(x[i]); }
void sl_cos_u10(const double* x, double*, double* c, std::size_t n) { for (std::size_t i = 0; i < n; ++i) c[i] = Sleef_cos_u10(x[i]); }
void sl_sincos_u10(const double* x, double* s, double* c, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) { const Sleef_double2 r = Sleef_sincos_u10(x[i]); s[i] = r.x; c[i] = r.y; }
}
void sl_sin_u35(const double* x, double* s, double*, std::size_t n) { for (std::size_t i = 0; i < n; ++i) s[i] = Sleef_sin_u35(x[i]); }
void sl_cos_u35(const double* x, double*, double* c, std::size_t n) { for (std::size_t i = 0; i < n; ++i) c[i] = Sleef_cos_u35(x[i]); }
void sl_sincos_u35(const double* x, double* s, double* c, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) { const Sleef_double2 r = Sleef_sincos_u35(x[i]); s[i] = r.x; c[i] = r.y; }
}
void sl_sin_u10purec(const double* x, double* s, double*, std::size_t n) { for (std::size_t i = 0; i < n; ++i) s[i] = Sleef_sind1_u10purec(x[i]); }

// ---- SLEEF SSE2, 2 lanes (n even) ----
#define SSE2_1(name, f, out)                                                                \
    void name(const double* x, double* s, double* c, std::size_t n) {                       \
        (void)s; (void)c;                                                                  \
        for (std::size_t i = 0; i < n; i += 2) _mm_storeu_pd(out + i, f(_mm_loadu_pd(x + i))); \
    }
SSE2_1(sl2_sin_u10, Sleef_sind2_u10sse2, s)
SSE2_1(sl2_cos_u10, Sleef_cosd2_u10sse2, c)
SSE2_1(sl2_sin_u35, Sleef_sind2_u35sse2, s)
SSE2_1(sl2_cos_u35, Sleef_cosd2_u35sse2, c)
void sl2_sincos_u10(const double* x, double* s, double* c, std::size_t n) {
    for (std::size_t i = 0; i < n; i += 2) {
        const Sleef___m128d_2 r = Sleef_sincosd2_u10sse2(_mm_loadu_pd(x + i));
        _mm_storeu_pd(s + i, r.x); _mm_storeu_pd(c + i, r.y);
    }
}
void sl2_sincos_u35(const double* x, double* s, double* c, std::size_t n) {
    for (std::size_t i = 0; i < n; i += 2) {
        const Sleef___m128d_2 r = Sleef_sincosd2_u35sse2(_mm_loadu_pd(x + i));
        _mm_storeu_pd(s + i, r.x); _mm_storeu_pd(c + i, r.y);
    }
}

// ---- SLEEF AVX2, 4 lanes (n % 4 == 0); only called when the CPU has AVX2 ----
#define AVX2_1(name, f, out)                                                                        \
    __attribute__((target("avx2,fma"))) void name(const double* x, double* s, double* c, std::size_t n) { \
        (void)s; (void)c;                                                                          \
        for (std::size_t i = 0; i < n; i += 4) _mm256_storeu_pd(out + i, f(_mm256_loadu_pd(x + i)));   \
    }
AVX2_1(sl4_sin_u10, Sleef_sind4_u10avx2, s)
AVX2_1(sl4_cos_u10, Sleef_cosd4_u10avx2, c)
AVX2_1(sl4_sin_u35, Sleef_sind4_u35avx2, s)
AVX2_1(sl4_cos_u35, Sleef_cosd4_u35avx2, c)
__attribute__((target("avx2,fma"))) void sl4_sincos_u10(const double* x, double* s, double* c, std::size_t n) {
    for (std::size_t i = 0; i < n; i += 4) {
        const Sleef___m256d_2 r = Sleef_sincosd4_u10avx2(_mm256_loadu_pd(x + i));
        _mm256_storeu_pd(s + i, r.x); _mm256_storeu_pd(c + i, r.y);
    }
}
__attribute__((target("avx2,fma"))) void sl4_sincos_u35(const double* x, double* s, double* c, std::size_t n) {
    for (std::size_t i = 0; i < n; i += 4) {
        const Sleef___m256d_2 r = Sleef_sincosd4_u35avx2(_mm256_loadu_pd(x + i));
        _mm256_storeu_pd(s + i, r.x); _mm256_storeu_pd(c + i, r.y);
    }
}

// ---- rocksweep::fastmath ----
// scalar: one element at a time (the W = 1 use)
void fm1_sin(const double* x, double* s, double*, std::size_t n) { for (std::size_t i = 0; i < n; ++i) s[i] = fm::sin(opaque(x[i])); }
void fm1_cos(const double* x, double*, double* c, std::size_t n) { for (std::size_t i = 0; i < n; ++i) c[i] = fm::cos(opaque(x[i])); }
void fm1_sincos(const double* x, double* s, double* c, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) fm::sincos(opaque(x[i]), s[i], c[i]);
}
// auto-vectorised, baseline x86-64 (SSE2, 2 lanes)
void fm2_sin(const double* x, double* s, double*, std::size_t n) { fm::sin(x, s, n); }
void fm2_cos(const double* x, double*, double* c, std::size_t n) { fm::cos(x, c, n); }
void fm2_sincos(const double* x, double* s, double* c, std::size_t n) { fm::sincos(x, s, c, n); }
// auto-vectorised, AVX2 (4 lanes; no FMA: -ffp-contract=off and target avx2 only). The loops are
// written out here: the array forms in the header are separate (SSE2) functions.
#define FM_BLOCKS(stmt)                                                       \
    for (std::size_t i = 0; i < n; i += 8)                                    \
        for (std::size_t k = 0; k < 8; ++k) {                                 \
            const std::size_t j = i + k;                                      \
            stmt;                                                             \
        }
__attribute__((target("avx2"))) void fm4_sin(const double* __restrict x, double* __restrict s, double*, std::size_t n) {
    FM_BLOCKS(s[j] = fm::sin(x[j]))
}
__attribute__((target("avx2"))) void fm4_cos(const double* __restrict x, double*, double* __restrict c, std::size_t n) {
    FM_BLOCKS(c[j] = fm::cos(x[j]))
}
__attribute__((target("avx2"))) void fm4_sincos(const double* __restrict x, double* __restrict s, double* __restrict c,
                                                std::size_t n) {
    FM_BLOCKS(fm::sincos(x[j], s[j], c[j]))
}

struct Range {
    const char* name;
    double lo, hi;
};
constexpr Range kRanges[] = {{"rhs |x|<=2", -2.0, 2.0}, {"ground [-2pi,4pi]", -2 * M_PI, 4 * M_PI}, {"spring |x|<=0.8", -0.8, 0.8}};

enum Out { S = 1, C = 2, SC = 3 };
struct Variant {
    const char* name;
    Fn fn;
    Out out;
    bool avx2;
    const char* scalar_twin;  ///< the scalar variant whose bits it should reproduce, or ""
};

const Variant kVariants[] = {
    {"glibc sin", glibc_sin, S, false, ""},
    {"glibc cos", glibc_cos, C, false, ""},
    {"glibc sincos", glibc_sincos, SC, false, ""},
    {"sleef scalar sin u10", sl_sin_u10, S, false, ""},
    {"sleef scalar cos u10", sl_cos_u10, C, false, ""},
    {"sleef scalar sincos u10", sl_sincos_u10, SC, false, ""},
    {"sleef scalar sin u35", sl_sin_u35, S, false, ""},
    {"sleef scalar cos u35", sl_cos_u35, C, false, ""},
    {"sleef scalar sincos u35", sl_sincos_u35, SC, false, ""},
    {"sleef purec sind1 u10", sl_sin_u10purec, S, false, "sleef scalar sin u10"},
    {"sleef sse2 sin u10", sl2_sin_u10, S, false, "sleef scalar sin u10"},
    {"sleef sse2 cos u10", sl2_cos_u10, C, false, "sleef scalar cos u10"},
    {"sleef sse2 sincos u10", sl2_sincos_u10, SC, false, "sleef scalar sincos u10"},
    {"sleef sse2 sin u35", sl2_sin_u35, S, false, "sleef scalar sin u35"},
    {"sleef sse2 cos u35", sl2_cos_u35, C, false, "sleef scalar cos u35"},
    {"sleef sse2 sincos u35", sl2_sincos_u35, SC, false, "sleef scalar sincos u35"},
    {"sleef avx2 sin u10", sl4_sin_u10, S, true, "sleef scalar sin u10"},
    {"sleef avx2 cos u10", sl4_cos_u10, C, true, "sleef scalar cos u10"},
    {"sleef avx2 sincos u10", sl4_sincos_u10, SC, true, "sleef scalar sincos u10"},
    {"sleef avx2 sin u35", sl4_sin_u35, S, true, "sleef scalar sin u35"},
    {"sleef avx2 cos u35", sl4_cos_u35, C, true, "sleef scalar cos u35"},
    {"sleef avx2 sincos u35", sl4_sincos_u35, SC, true, "sleef scalar sincos u35"},
    {"fastmath scalar sin", fm1_sin, S, false, ""},
    {"fastmath scalar cos", fm1_cos, C, false, ""},
    {"fastmath scalar sincos", fm1_sincos, SC, false, ""},
    {"fastmath sse2 sin", fm2_sin, S, false, "fastmath scalar sin"},
    {"fastmath sse2 cos", fm2_cos, C, false, "fastmath scalar cos"},
    {"fastmath sse2 sincos", fm2_sincos, SC, false, "fastmath scalar sincos"},
    {"fastmath avx2 sin", fm4_sin, S, true, "fastmath scalar sin"},
    {"fastmath avx2 cos", fm4_cos, C, true, "fastmath scalar cos"},
    {"fastmath avx2 sincos", fm4_sincos, SC, true, "fastmath scalar sincos"},
};

const Variant* find(const std::string& name) {
    for (const Variant& v : kVariants)
        if (name == v.name) return &v;
    return nullptr;
}

double ulp_of(long double ref) {
    const double r = static_cast<double>(ref);
    if (r == 0.0) return std::ldexp(1.0, -1074);
    return std::ldexp(1.0, std::ilogb(r) - 52);
}

struct Accuracy {
    double max_ulp = 0.0, max_abs = 0.0;
};
void accumulate(Accuracy& a, double got, long double ref) {
    const long double e = std::fabs(static_cast<long double>(got) - ref);
    a.max_abs = std::max(a.max_abs, static_cast<double>(e));
    a.max_ulp = std::max(a.max_ulp, static_cast<double>(e / ulp_of(ref)));
}

}  // namespace

int main(int argc, char** argv) {
    const int reps = argc > 1 ? std::atoi(argv[1]) : 2000;
    const bool have_avx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    constexpr std::size_t kN = 4096;        // timing array
    constexpr std::size_t kM = 1 << 20;     // accuracy / bitwise samples per range
    std::mt19937_64 rng(12345);

    std::printf("# ns/element: min over 7 trials of %d passes over %zu doubles; accuracy on %zu uniform samples\n"
                "# (+ x = 0, +-lo, +-hi) vs long double sinl/cosl. 'bits' = identical to the scalar twin on every sample.\n",
                reps, kN, kM);
    std::printf("%-26s %-18s %8s %10s %10s %10s %10s  %s\n", "variant", "range", "ns/elem", "ulp(sin)", "abs(sin)",
                "ulp(cos)", "abs(cos)", "bits==scalar twin");
    for (const Range& r : kRanges) {
        std::uniform_real_distribution<double> dist(r.lo, r.hi);
        std::vector<double> xa(kM);
        for (double& x : xa) x = dist(rng);
        xa[0] = 0.0; xa[1] = -0.0; xa[2] = r.lo; xa[3] = r.hi; xa[4] = -r.lo; xa[5] = -r.hi;
        std::vector<long double> rs(kM), rc(kM);
        for (std::size_t i = 0; i < kM; ++i) { rs[i] = sinl(static_cast<long double>(xa[i])); rc[i] = cosl(static_cast<long double>(xa[i])); }
        std::vector<double> xt(xa.begin(), xa.begin() + kN), st(kN), ct(kN);

        struct Result { std::vector<double> s, c; };
        std::vector<Result> results(std::size(kVariants));
        for (std::size_t v = 0; v < std::size(kVariants); ++v) {
            const Variant& var = kVariants[v];
            if (var.avx2 && !have_avx2) continue;
            // timing
            double best = 1e300;
            for (int trial = 0; trial < 7; ++trial) {
                const auto t0 = std::chrono::steady_clock::now();
                for (int k = 0; k < reps; ++k) {
                    var.fn(xt.data(), st.data(), ct.data(), kN);
                    asm volatile("" ::"r"(st.data()), "r"(ct.data()) : "memory");
                }
                const auto t1 = std::chrono::steady_clock::now();
                best = std::min(best, std::chrono::duration<double, std::nano>(t1 - t0).count() / (double(reps) * kN));
            }
            // accuracy
            Result& res = results[v];
            res.s.assign(kM, 0.0); res.c.assign(kM, 0.0);
            var.fn(xa.data(), res.s.data(), res.c.data(), kM);
            Accuracy as, ac;
            for (std::size_t i = 0; i < kM; ++i) {
                if (var.out & S) accumulate(as, res.s[i], rs[i]);
                if (var.out & C) accumulate(ac, res.c[i], rc[i]);
            }
            // bitwise against the scalar twin
            std::string bits = "-";
            if (*var.scalar_twin) {
                const Variant* tw = find(var.scalar_twin);
                const Result& tr = results[static_cast<std::size_t>(tw - kVariants)];
                std::size_t diff = 0;
                for (std::size_t i = 0; i < kM; ++i) {
                    if ((var.out & S) && std::memcmp(&res.s[i], &tr.s[i], sizeof(double)) != 0) ++diff;
                    else if ((var.out & C) && std::memcmp(&res.c[i], &tr.c[i], sizeof(double)) != 0) ++diff;
                }
                bits = diff == 0 ? "yes" : "NO (" + std::to_string(diff) + " differ)";
            }
            // symmetry of the fastmath functions: sin(-x) == -sin(x), cos(-x) == cos(x) bitwise
            if (std::string(var.name).rfind("fastmath", 0) == 0 && (var.out & S)) {
                std::vector<double> xn(kM), sn(kM), cn(kM);
                for (std::size_t i = 0; i < kM; ++i) xn[i] = -xa[i];
                var.fn(xn.data(), sn.data(), cn.data(), kM);
                std::size_t bad = 0;
                for (std::size_t i = 0; i < kM; ++i) {
                    const double ms = -res.s[i];
                    if (std::memcmp(&sn[i], &ms, sizeof(double)) != 0) ++bad;
                    if ((var.out & C) && std::memcmp(&cn[i], &res.c[i], sizeof(double)) != 0) ++bad;
                }
                bits += bad == 0 ? ", odd/even exact" : ", SYMMETRY BROKEN (" + std::to_string(bad) + ")";
            }
            auto col = [&](bool on, double x, const char* fmt) {
                char buf[32];
                if (on) std::snprintf(buf, sizeof buf, fmt, x); else std::snprintf(buf, sizeof buf, "%s", "-");
                return std::string(buf);
            };
            std::printf("%-26s %-18s %8.2f %10s %10s %10s %10s  %s\n", var.name, r.name, best,
                        col(var.out & S, as.max_ulp, "%.3f").c_str(), col(var.out & S, as.max_abs, "%.2e").c_str(),
                        col(var.out & C, ac.max_ulp, "%.3f").c_str(), col(var.out & C, ac.max_abs, "%.2e").c_str(),
                        bits.c_str());
            std::fflush(stdout);
        }
    }
    return 0;
}
