// Cost of a cell against omega_p/p and a_p0/(alpha g), total cost against grid size with and
// without boundary refinement, and how full the batches stay. One thread; wall clock.
//   build/benchmarks/cost_scaling [--quick]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include "rocksweep/physics/anchorage.hpp"
#include "rocksweep/physics/integrator.hpp"
#include "rocksweep/grid/refine.hpp"
#include "rocksweep/grid/sweep.hpp"

using namespace rocksweep;
using Clock = std::chrono::steady_clock;

namespace {

SweepSpec spectrum(const Block& b, const Anchorage& a, double w0, double w1, std::size_t nw, double a0, double a1,
                   std::size_t na) {
    SweepSpec s;
    s.block = b;
    s.omega_ratio = Axis{w0, w1, nw};
    s.amplitude_ratio = Axis{a0, a1, na};
    s.scenarios.push_back({"cell", a, 0.0, 1.0});
    return s;
}

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

/// Seconds for the cells of `idx` (all cells if empty); returns outcomes through `out`.
double run(const SweepSpec& s, const std::vector<std::size_t>& idx, std::vector<CellResult>& out, int lanes = 8,
           BatchStats* stats = nullptr) {
    std::vector<CellModel> cells;
    cells.reserve(idx.size());
    for (std::size_t i : idx) cells.push_back(s.cell(i));
    out.assign(cells.size(), CellResult{});
    const auto t0 = Clock::now();
    integrate_cells(cells, out, IntegratorSettings{}, lanes, stats);
    return seconds_since(t0);
}

std::vector<std::size_t> all(const SweepSpec& s) {
    std::vector<std::size_t> v(s.cell_count());
    for (std::size_t i = 0; i < v.size(); ++i) v[i] = i;
    return v;
}

}  // namespace

int main(int argc, char** argv) {
    const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
    const Block b = rectangular_block(0.30, 1.36, 3361.0);
    const double fu = 0.4 * b.mass_kg * b.gravity;
    struct Named { const char* name; Anchorage a; };
    const Named kinds[] = {{"free", free_anchorage()}, {"adaptive_rho0.1", adaptive_anchorage(b, fu, b.alpha_rad, 0.1)}};

    std::printf("== cost per cell [us] against omega_p/p (columns) and a_p0/(alpha g) (rows), 20x20 cells per bin\n");
    for (const Named& k : kinds) {
        std::printf("%s\n      a\\w", k.name);
        for (int j = 0; j < 9; ++j) std::printf(" %6.0f-%-3.0f", 1.0 + j, 2.0 + j);
        std::printf("\n");
        for (int i = 0; i < 7; ++i) {
            const double a0 = 1.0 + 3.0 * i;
            std::printf("%4.0f-%-4.0f", a0, a0 + 3.0);
            for (int j = 0; j < 9; ++j) {
                const SweepSpec s = spectrum(b, k.a, 1.0 + j, 2.0 + j, 20, a0, a0 + 3.0, 20);
                std::vector<CellResult> r;
                const double t = run(s, all(s), r);
                std::printf(" %10.1f", 1e6 * t / s.cell_count());
            }
            std::printf("\n");
        }
    }

    std::printf("\n== total cost against grid size: free spectrum, omega_p/p in [1,10] x a_p0/(alpha g) in [1,10]\n");
    std::printf("%8s %10s %12s %14s %12s %12s %10s\n", "N x N", "cells", "full [s]", "refined [s]", "computed", "fraction",
                "agree");
    for (std::size_t n : quick ? std::vector<std::size_t>{100, 200} : std::vector<std::size_t>{125, 250, 500, 1000}) {
        const SweepSpec s = spectrum(b, free_anchorage(), 1.0, 10.0, n, 1.0, 10.0, n);
        std::vector<CellResult> full;
        const double t_full = n <= 500 || !quick ? run(s, all(s), full) : NAN;
        // Refinement from a spacing of about n/32 cells, to the full grid.
        std::size_t stride = 2;
        while (stride * 64 < n) stride *= 2;
        const Refinement ref(n, n, stride);
        std::vector<std::uint8_t> outcome(n * n, 0), done(n * n, cell_pending);
        std::size_t computed = 0;
        double t_ref = 0.0;
        for (int k = 0; k < ref.passes(); ++k) {
            const std::vector<std::size_t> idx = ref.cells_for_pass(k, outcome.data(), done.data());
            std::vector<CellResult> r;
            t_ref += run(s, idx, r);
            for (std::size_t q = 0; q < idx.size(); ++q) {
                outcome[idx[q]] = static_cast<std::uint8_t>(r[q].outcome);
                done[idx[q]] = cell_computed;
            }
            computed += idx.size();
        }
        ref.fill(outcome.data(), done.data());
        std::size_t agree = 0;
        for (std::size_t i = 0; i < n * n; ++i) agree += outcome[i] == static_cast<std::uint8_t>(full[i].outcome);
        std::printf("%8zu %10zu %12.3f %14.3f %12zu %11.2f%% %9.4f%%\n", n, n * n, t_full, t_ref, computed,
                    100.0 * computed / (n * n), 100.0 * agree / (n * n));
    }

    std::printf("\n== lane utilisation (busy lane-steps / all lane-steps) and time, S. Matteo free + adaptive, 200 x 200\n");
    for (int lanes : {1, 4, 8, 16}) {
        double t = 0;
        BatchStats st;
        for (const Named& k : kinds) {
            const SweepSpec s = spectrum(b, k.a, 1.0, 10.0, 200, 1.0, 22.0, 200);
            std::vector<CellResult> r;
            t += run(s, all(s), r, lanes, &st);
        }
        std::printf("lanes %2d: utilisation %6.2f%%  %.3f s  (%.0f cells/s)\n", lanes, 100.0 * st.utilisation(), t,
                    80000.0 / t);
    }
    return 0;
}
