// Is a floor motion, computed exactly at its samples and read linear between them, as good as the
// floor motion itself? For each shared record and floor, at the record's own samples (m = 1) and
// at the floor_oversampling the engine uses: (1) the largest gap between that interpolation and
// the floor's exact acceleration at 4 times as many samples, over the PFA; (2) what the
// S. Matteo block (free-standing) makes of the two at PFA levels 0.2-1.0 g: the largest
// |theta_max/alpha| difference among cells that stand in both, and outcome flips. The finer
// motion is the same ground (linear between its samples) sampled finer and filtered exactly there.
//   build/benchmarks/floor_interpolation configs/records_suite.csv
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "rocksweep/motion/floor_filter.hpp"
#include "rocksweep/physics/integrator.hpp"
#include "rocksweep/records/record_suite.hpp"

using namespace rocksweep;

namespace {

double peak(const std::vector<double>& y) {
    double m = 0.0;
    for (double x : y) m = std::max(m, std::abs(x));
    return m;
}

CellResult run(const Block& b, const std::vector<double>& a, double dt, double scale) {
    Record r;
    r.ax_g = a;
    r.dt_s = dt;
    Pulse p = to_pulse(r, b.gravity);
    p.record_scale = scale;
    return integrate_cell(make_cell_model(b, free_anchorage(), p), IntegratorSettings{});
}

// The floor of `g` at m samples per record step, read linear between them, against the floor
// exact at 4 m: the largest gap over the PFA, and what the block makes of the two.
struct Gap {
    double over_pfa = 0.0, dtheta = 0.0;
    int flips = 0, cells = 0;
};
Gap compare(const Block& b, const Record& g, const motion::Floor& f, int m) {
    const int k = 4;
    const std::vector<double> read = motion::floor_motion(f, motion::oversample(g.ax_g, m), g.dt_s / m);
    const std::vector<double> exact = motion::floor_motion(f, motion::oversample(g.ax_g, k * m), g.dt_s / (k * m));
    const double pfa = peak(read);
    Gap gap;
    for (std::size_t i = 0; i + 1 < read.size(); ++i)
        for (int j = 0; j < k; ++j)
            gap.over_pfa = std::max(gap.over_pfa, std::abs(read[i] + (read[i + 1] - read[i]) * j / k - exact[i * k + j]) / pfa);
    for (double level = 0.2; level <= 1.0 + 1e-9; level += 0.1) {
        const CellResult a = run(b, read, g.dt_s / m, level / pfa), e = run(b, exact, g.dt_s / (k * m), level / pfa);
        ++gap.cells;
        if (a.outcome != e.outcome) ++gap.flips;
        else if (a.outcome == Outcome::safe) gap.dtheta = std::max(gap.dtheta, std::abs(a.max_rotation - e.max_rotation));
    }
    return gap;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: floor_interpolation SUITE.csv\n");
        return 2;
    }
    const Block b = rectangular_block(0.30, 1.36, 3361.0);
    const char* floors[] = {"T0.1: 0.1 0.05 1", "T0.3: 0.3 0.05 1", "T1: 1.0 0.05 1", "plinth: 0.5 0.05 1.3 > 2.5 0.15 1"};
    std::printf("record,floor,dt_s,m,interp_error_over_pfa,max_dtheta_ratio,flips,cells\n");
    for (const SuiteRecord& entry : read_record_suite(argv[1]).records) {
        const Record g = read_record(entry.source);
        for (const char* text : floors) {
            const motion::Floor f = motion::parse_floor("floor", text);
            for (int m : {1, motion::floor_oversampling(f, g.dt_s)}) {
                const Gap gap = compare(b, g, f, m);
                std::printf("%s,%s,%g,%d,%.3g,%.3g,%d,%d\n", entry.name.c_str(), f.name.c_str(), g.dt_s, m, gap.over_pfa,
                            gap.dtheta, gap.flips, gap.cells);
            }
        }
    }
    return 0;
}
