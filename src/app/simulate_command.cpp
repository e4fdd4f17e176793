// `rocksweep simulate`: one time history of one cell, written to HDF5 or CSV.
#include <cmath>
#include <filesystem>
#include <iostream>
#include <tuple>

#include "rocksweep/app/cli.hpp"
#include "rocksweep/core/errors.hpp"
#include "rocksweep/physics/history.hpp"
#include "rocksweep/io/history_file.hpp"
#include "rocksweep/io/output_claim.hpp"
#include "rocksweep/motion/floor_filter.hpp"
#include "rocksweep/records/record.hpp"


namespace rocksweep {

int run_simulate(const Options& o, const SimulateCommand& cmd, const std::string& config_text) {
    const std::string& output = cmd.output;
    const bool quiet = cmd.quiet;
    Record record;
    const CellModel m = make_single_cell(o, &record);
    // Before any work: a record read in the wrong unit shows here, whatever comes of it.
    if (!quiet && !o.single.record.empty()) std::cout << "record " << o.single.record << ": " << record_facts(record) << "\n";
    const IntegratorSettings settings = make_settings(o.numerics);
    const std::string ext = std::filesystem::path(output).extension().string();
    if (ext != ".h5" && ext != ".csv") throw InputError("output", output, "a file name ending in .h5 or .csv");
    // Claimed before computing: a bad name, a locked or existing output fails at once.
    const OutputClaim claim("output", output);
    if (claim.exists() && !cmd.overwrite)
        throw InputError("output", output, "a new file; it exists: pass --overwrite to replace it");
    const double t_end = o.single.t_end_s > 0.0 ? o.single.t_end_s : default_t_end(m);
    const History h = sample_history(m, settings, o.single.output_dt_s, t_end);
    if (ext == ".csv") {
        write_history_csv(output, h);
    } else {
        std::vector<std::pair<std::string, std::string>> words{
            {"anchorage", o.single.anchorage}, {"pulse", o.single.record.empty() ? o.single.pulse : "record"},
            {"record", o.single.record}, {"floor", o.single.floor.empty() ? "ground" : motion::to_string(motion::parse_floor("floor", o.single.floor))}, {"adaptive_law", to_string(m.adaptive_law)}, {"method", to_string(settings.method)},
            {"equations", to_string(m.equations)}, {"config", config_text}, {"version", ROCKSWEEP_VERSION}};
        std::vector<std::pair<std::string, double>> numbers{
            {"p_rad_s", m.p()}, {"alpha_rad", m.alpha}, {"e", m.e}, {"steps_per_period", settings.steps_per_period},
            {"impact_threshold", o.numerics.impact_threshold}, {"output_dt_s", o.single.output_dt_s}};
        if (!o.single.record.empty()) numbers.emplace_back("tolerance", settings.tolerance);  // steps follow it under a record
        // Only what defined the run: a record-driven history carries no pulse, a free block no K ratios.
        const std::tuple<const char*, const char*, double> ratios[] = {
            {"omega_ratio", "omega-ratio", o.single.omega_ratio}, {"amplitude_ratio", "amplitude-ratio", o.single.amplitude_ratio},
            {"theta_f_ratio", "theta-f-ratio", o.single.theta_f_ratio}, {"kmin_ratio", "kmin-ratio", o.single.kmin_ratio}};
        for (const auto& [attribute, option, value] : ratios)
            if (defines_run("simulate", option, o)) numbers.push_back({attribute, value});
        write_history_h5(output, h, words, numbers);
    }
    if (!quiet) {
        const CellResult& r = h.result;
        std::cout << "outcome: " << to_string(r.outcome) << "\nimpacts: " << r.impacts << " (above " << o.numerics.impact_threshold
                  << " p alpha; " << r.impacts_total << " in all)\nmax |theta| / alpha: " << r.max_rotation << "\n";
        if (!std::isnan(r.t_overturn_s)) std::cout << "t_overturn: " << r.t_overturn_s << " s\n";
        if (!std::isnan(r.peak_force_ratio)) std::cout << "peak force / F_u: " << r.peak_force_ratio << "\n";
        if (m.anchorage == AnchorageKind::adaptive)  // 0 under the passive law, physics.md
            std::cout << "spring energy injected by K_min -> K_max switches: " << h.switch_energy_j << " J\n";
        std::cout << "friction needed to rock without sliding: " << r.mu_required;
        if (o.base.friction > 0.0)
            std::cout << (r.mu_required > o.base.friction ? " (more than" : " (within") << " mu_s = " << o.base.friction << ")";
        std::cout << (r.pivot_uplift ? "\nwarning: the pivot's vertical reaction went negative: the block would jump" : "") << "\n";
        std::cout << "wrote " << output << " (" << h.t.size() << " samples to t = " << h.t.back() << " s)\n";
    }
    return 0;
}

}  // namespace rocksweep
