// What a synthetic motion costs beside the runs it feeds: the model fitted to a record, then
// (1) motions generated per second, (2) one run per motion (the S. Matteo block, free, one PGA
// level: a `simulate` of the motion, cells computed as `suite` computes them) and (3) a suite's
// share: `--levels` x `--radii` x 3 anchorages per motion, in chunks of 64 as the ranks take
// them (each chunk makes its motions again). Prints one line per measure; times are CPU time.
// With --startup N: what `suite --synthetic-count N` spends before its first cell, item by item
// (the fit, making each motion, its measures, Sa, the floor's motion, the floor spectra), and
// make_suite_spec itself on the writer and on a worker (docs/synthetic.md, "Cost and scale").
//   synthetic_cost [--record FILE --units U] [--motions N] [--levels N] [--radii N]
//   synthetic_cost [--record FILE --units U] --startup N [--floor TEXT]
#include <ctime>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "rocksweep/motion/floor_filter.hpp"
#include "rocksweep/motion/response_spectrum.hpp"
#include "rocksweep/physics/anchorage.hpp"
#include "rocksweep/physics/integrator.hpp"
#include "rocksweep/records/suite_sweep.hpp"
#include "rocksweep/synthetic/fit.hpp"
#include "rocksweep/synthetic/model_motions.hpp"

using namespace rocksweep;

namespace {

// CPU seconds of this process: the machine is shared, its wall clock is not ours.
double cpu_now() {
    timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

SuiteSpec smatteo(std::shared_ptr<const MotionSource> motions, bool all_anchorages, std::size_t levels, std::size_t radii) {
    const Block b = rectangular_block(0.30, 1.36, 3361.0);
    const double fu = 0.4 * b.mass_kg * b.gravity;
    std::vector<Scenario> scenarios{{"free", free_anchorage(), 0.0, 1.0}};
    if (all_anchorages) {
        scenarios.push_back({"constant_tf1", constant_anchorage(b, fu, b.alpha_rad), 1.0, 1.0});
        scenarios.push_back({"adaptive_rho0.1", adaptive_anchorage(b, fu, b.alpha_rad, 0.1), 1.0, 0.1});
    }
    const std::vector<double> r_m = radii == 1 ? std::vector<double>{b.radius_m} : Axis{0.392695228684288, 3.892695228684288, radii}.values();
    SuiteMotions made;
    made.made = std::move(motions);
    return make_suite_spec("", b, scenarios, IntensityMeasure::pga_g, Axis{levels == 1 ? 0.3 : 0.05, levels == 1 ? 0.3 : 1.5, levels},
                           r_m, {}, std::move(made));
}

double run_cells(const SuiteSpec& spec) {
    std::vector<CellResult> out(spec.cell_count());
    const double t0 = cpu_now();
    for (std::size_t first = 0; first < out.size(); first += 64)
        compute_suite_cells(spec, IntegratorSettings{}, first, std::min<std::size_t>(64, out.size() - first), out.data() + first);
    return cpu_now() - t0;
}

// The start-up of a suite of `count` motions of `gen`, item by item, per motion.
void startup(const synthetic::Generator& gen, std::size_t count, const std::string& floor_text) {
    std::vector<motion::Floor> floors{motion::Floor{}};
    if (!floor_text.empty()) floors.push_back(motion::parse_floor("floor", floor_text));
    const std::vector<double> periods = motion::floor_spectrum_periods();
    double make = 0, measures = 0, sa = 0, on_floors = 0, spectra = 0, t0 = 0;
    for (std::size_t i = 0; i < count; ++i) {
        t0 = cpu_now();
        const Record r = gen.record(1, i);
        make += cpu_now() - t0;
        t0 = cpu_now();
        volatile double pga = intensity_measures(r).pga_g;
        (void)pga;
        measures += cpu_now() - t0;
        t0 = cpu_now();
        volatile double s = motion::spectral_acceleration(r.ax_g, r.dt_s, motion::Oscillator{1.0, 0.05});
        (void)s;
        sa += cpu_now() - t0;
        for (const motion::Floor& f : floors) {
            t0 = cpu_now();
            const Record on = on_floor(r, f);
            on_floors += cpu_now() - t0;
            t0 = cpu_now();
            volatile double s0 = motion::response_spectrum(on.ax_g, on.dt_s, periods, 0.05)[0];
            (void)s0;
            spectra += cpu_now() - t0;
        }
    }
    const double n = static_cast<double>(count);
    std::printf("per motion (%zu motions, floors: ground%s): make %.3f ms, measures %.3f ms, Sa(1 s) %.3f ms, "
                "on the floors %.3f ms, floor spectra (%zu x %zu periods) %.3f ms; total %.3f ms\n",
                count, floor_text.empty() ? "" : (" and " + floors.back().name).c_str(), 1e3 * make / n, 1e3 * measures / n,
                1e3 * sa / n, 1e3 * on_floors / n, floors.size(), periods.size(), 1e3 * spectra / n,
                1e3 * (make + measures + sa + on_floors + spectra) / n);
    for (const bool writer : {true, false}) {
        SuiteMotions made;
        made.floors = floors;
        made.made = std::make_shared<synthetic::ModelMotions>(gen, 1, count);
        if (!writer) made.measures = SuiteMotions::Measures::none;
        const Block b = rectangular_block(0.30, 1.36, 3361.0);
        t0 = cpu_now();
        const SuiteSpec spec = make_suite_spec("", b, {{"free", free_anchorage(), 0.0, 1.0}}, IntensityMeasure::pga_g,
                                               Axis{0.05, 1.5, 25}, {}, {}, std::move(made));
        std::printf("make_suite_spec on %s: %.3f s\n", writer ? "the writer (every measure)" : "a worker", cpu_now() - t0);
    }
}

}  // namespace

int main(int argc, char** argv) {
    std::string path = "tests/data/loma_prieta_1989.dat", units = "m/s^2";
    std::size_t motions = 200, levels = 25, radii = 4, startup_count = 0;
    std::string floor_text;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string k = argv[i], v = argv[i + 1];
        if (k == "--record") path = v;
        else if (k == "--units") units = v;
        else if (k == "--motions") motions = std::stoul(v);
        else if (k == "--levels") levels = std::stoul(v);
        else if (k == "--radii") radii = std::stoul(v);
        else if (k == "--startup") startup_count = std::stoul(v);
        else if (k == "--floor") floor_text = v;
        else { std::fprintf(stderr, "synthetic_cost: unknown option %s\n", k.c_str()); return 2; }
    }
    RecordSource source;
    source.path = path;
    source.units = units;
    const Record r = read_record(source);
    double t0 = cpu_now();
    const synthetic::FitResult fit = synthetic::fit_model(r.ax_g, r.dt_s);
    std::printf("fit %s: %.3f s; %s\n", path.c_str(), cpu_now() - t0, synthetic::describe(fit.params).c_str());
    t0 = cpu_now();
    const synthetic::Generator gen(fit.params, r.dt_s, synthetic::default_duration_s(fit.params));
    const double setup_s = cpu_now() - t0;
    t0 = cpu_now();
    const synthetic::Generator without_gain(fit.params, r.dt_s, synthetic::default_duration_s(fit.params),
                                            synthetic::Stages{.keep_arias = false});
    std::printf("set up the model: %.1f ms, of which the high-pass gain %.1f ms (dt %.4g s)\n", 1e3 * setup_s,
                1e3 * (setup_s - (cpu_now() - t0)), r.dt_s);
    if (startup_count > 0) {
        startup(gen, startup_count, floor_text);
        return 0;
    }
    t0 = cpu_now();
    std::vector<double> a;
    for (std::size_t i = 0; i < motions; ++i) gen.generate(1, i, a);
    const double gen_s = (cpu_now() - t0) / motions;
    std::printf("generate: %zu samples, %.3f ms a motion, %.0f motions/s\n", gen.samples(), 1e3 * gen_s, 1.0 / gen_s);
    const auto source_of = std::make_shared<synthetic::ModelMotions>(gen, 1, motions);
    const SuiteSpec one = smatteo(source_of, false, 1, 1);
    const double one_s = run_cells(one) / motions;  // each cell makes its motion: subtract it
    std::printf("one run a motion (free, PGA 0.3 g): %.3f ms with its generation, integration %.3f ms: generation %.0f %% of it\n",
                1e3 * one_s, 1e3 * (one_s - gen_s), 100.0 * gen_s / (one_s - gen_s));
    const SuiteSpec suite = smatteo(source_of, true, levels, radii);
    const std::size_t per_motion = suite.cell_count() / motions;
    const double suite_s = run_cells(suite);
    std::printf("suite: %zu runs a motion (%zu levels x %zu sizes x 3 anchorages), %.1f runs/s on one core; making the motions "
                "(%zu chunks) %.1f %% of the time\n",
                per_motion, levels, radii, suite.cell_count() / suite_s, (suite.cell_count() + 63) / 64,
                100.0 * gen_s * ((suite.cell_count() + 63) / 64) / suite_s);
    return 0;
}
