// `rocksweep basin`: for each scenario, free rocking from a grid of initial states, the
// integrated outcome beside the energy argument's, written to one HDF5 file.
#include "rocksweep/app/basin_command.hpp"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>

#include "rocksweep/io/basin_file.hpp"
#include "rocksweep/core/errors.hpp"
#include "rocksweep/app/memory_budget.hpp"
#include "rocksweep/app/option_checks.hpp"
#include "rocksweep/io/output_claim.hpp"


namespace rocksweep {

namespace {

/// How many boundary points per curve: an even count, so that a symmetric range does not put
/// one on theta = 0, where the boundaries of the two sides meet.
constexpr std::size_t curve_points = 1000;
/// Clear cells lie farther than this fraction of each axis's span from every predicted boundary.
constexpr double comparison_margin = 0.01;

Axis basin_axis(const std::string& name, const std::vector<double>& range, std::size_t points) {
    const std::string shown = format_short(range.at(0)) + " " + format_short(range.at(1));
    const double lo = range[0], hi = range[1];
    if (hi < lo) throw InputError(name + "-range", shown, "LO <= HI (the grid is reversed)");
    if ((hi == lo) != (points == 1))
        throw InputError(name + "-range", shown, "LO = HI exactly when --" + name + "-points is 1");
    return Axis{lo, hi, points};
}

}  // namespace

CLI::App* add_basin_command(CLI::App& app, BasinCommand& cmd) {
    CLI::App* b = app.add_subcommand("basin", "Basins of attraction: free rocking from a grid of states (theta, theta_dot), "
                                              "simulated and predicted by energy, per scenario");
    b->fallthrough();
    b->add_option("-o,--output", cmd.output, "Output HDF5 file")->required();
    b->add_option("--theta-ratio-range", cmd.theta_range, "Initial theta / alpha from LO to HI (|theta| < pi/2)")
        ->expected(2)->check(number_in(-1e3, 1e3, ""))->capture_default_str();
    b->add_option("--theta-ratio-points", cmd.theta_points, "Points on the theta / alpha axis, both ends included")
        ->check(integer_in(1, 20000))->capture_default_str();
    b->add_option("--theta-dot-ratio-range", cmd.theta_dot_range, "Initial theta_dot / p from LO to HI")
        ->expected(2)->check(number_in(-100, 100, ""))->capture_default_str();
    b->add_option("--theta-dot-ratio-points", cmd.theta_dot_points, "Points on the theta_dot / p axis")
        ->check(integer_in(1, 20000))->capture_default_str();
    b->add_flag("--overwrite", cmd.overwrite, "Replace an existing output file");
    b->add_flag("-q,--quiet", cmd.quiet, "Print nothing on success");
    return b;
}

void check_basin_options(const CLI::App& app, const std::vector<std::string>& args) {
    std::vector<std::string> refused = pulse_region_options;
    refused.push_back("--friction-coefficient");
    refuse_typed(app, args, refused, "an option of sweep; basin starts free rocking with the ground at rest");
}

int run_basin(const Options& o, const BasinCommand& cmd, const std::string& config_text) {
    const auto start = std::chrono::steady_clock::now();
    const SweepSpec spec = make_sweep_spec(o);
    BasinFile f;
    f.block = spec.block;
    f.equations = spec.equations;
    f.settings = make_settings(o.numerics);
    f.impact_threshold = spec.impact_threshold;
    f.margin = comparison_margin;
    f.grid.theta_ratio = basin_axis("theta-ratio", cmd.theta_range, cmd.theta_points);
    f.grid.theta_dot_ratio = basin_axis("theta-dot-ratio", cmd.theta_dot_range, cmd.theta_dot_points);
    const double alpha = f.block.alpha_rad, limit = M_PI / 2 / alpha;
    if (!(std::max(std::abs(cmd.theta_range[0]), std::abs(cmd.theta_range[1])) < limit))
        throw InputError("theta-ratio-range", format_short(cmd.theta_range[0]) + " " + format_short(cmd.theta_range[1]),
                         "|theta / alpha| < pi / (2 alpha) = " + format_short(limit, 4) + " for this block (the block lies on its side there)");
    f.curve_theta_ratio = Axis{f.grid.theta_ratio.lo, f.grid.theta_ratio.hi, curve_points};
    // Per scenario, one cell model and result per grid state at a time, and two maps per scenario kept.
    const double cells = static_cast<double>(f.grid.size());
    require_memory("theta-ratio-points", std::to_string(cmd.theta_points),
                   cells * (sizeof(CellModel) + sizeof(CellResult) + 2.0 * static_cast<double>(spec.scenarios.size())),
                   "with --theta-dot-ratio-points " + std::to_string(cmd.theta_dot_points) + ", " + format_short(cells) +
                       " states of " + std::to_string(spec.scenarios.size()) + " scenario(s)");
    if (std::filesystem::path(cmd.output).extension() != ".h5") throw InputError("output", cmd.output, "a file name ending in .h5");
    const OutputClaim claim("output", cmd.output);  // before computing: a bad or locked output fails at once
    if (claim.exists() && !cmd.overwrite)
        throw InputError("output", cmd.output, "a new file; it exists: pass --overwrite to replace it");

    for (const Scenario& sc : spec.scenarios) {
        BasinScenario s;
        s.scenario = sc;
        s.cell = free_rocking_cell(f.block, sc.anchorage, f.equations, f.impact_threshold);
        const BasinEnergy energy(s.cell);
        s.simulated = simulate_basin(s.cell, f.grid, f.settings, o.numerics.lanes);
        s.predicted = predict_basin(energy, s.cell, f.grid);
        s.comparison = compare_basin(energy, s.cell, f.grid, s.simulated, s.predicted, f.margin);
        for (double r : f.curve_theta_ratio.values()) {
            const BasinBoundary b = energy.boundary(r * alpha);
            s.no_impact.push_back(b.no_impact / s.cell.p());
            s.impact.push_back(b.impact / s.cell.p());
        }
        f.scenarios.push_back(std::move(s));
    }
    f.config_text = config_text;
    f.version = ROCKSWEEP_VERSION;
    write_basin_file(cmd.output, f);

    if (!cmd.quiet) {
        const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::cout << "scenario              rest basin (simulated / energy)  cells differing: clear / near a boundary\n";
        for (const BasinScenario& s : f.scenarios) {
            const BasinComparison& c = s.comparison;
            std::cout << std::left << std::setw(22) << s.scenario.name << std::right << std::fixed << std::setprecision(4)
                      << std::setw(8) << rest_fraction(s.simulated) << " / " << std::setw(6) << rest_fraction(s.predicted)
                      << std::setw(22) << c.clear_disagree << " of " << c.clear << " / " << c.near_disagree << " of " << c.near << "\n";
        }
        std::cout << std::defaultfloat << "wrote " << cmd.output << " (" << f.scenarios.size() << " scenarios x "
                  << f.grid.size() << " states, " << std::setprecision(3) << wall << " s)\n";
    }
    return 0;
}

}  // namespace rocksweep
