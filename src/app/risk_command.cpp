// `rocksweep risk`: read the suite's fragility and the site's hazard, check they speak of the
// same measure, integrate, write, and say where the rate came from.
#include "rocksweep/app/risk_command.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>

#include "rocksweep/app/option_checks.hpp"
#include "rocksweep/app/run_support.hpp"
#include "rocksweep/core/errors.hpp"
#include "rocksweep/io/output_claim.hpp"
#include "rocksweep/io/risk_file.hpp"
#include "rocksweep/records/intensity.hpp"


namespace rocksweep {

namespace {

/// One line per scenario and block for overturning (the last state): what a conservator asks.
void print_summary(const RiskReport& r, std::ostream& out) {
    const SuiteFragilityTable& t = r.fragility;
    const HazardFile& hz = r.hazard;
    out << "hazard " << hazard_measure_name(hz.curve.measure(), hz.curve.period_s()) << " [" << hazard_measure_units(hz.curve.measure())
        << "], " << hz.curve.size() << " points " << hz.curve.intensity().front() << " .. " << hz.curve.intensity().back() << " ("
        << hz.format << (hz.format == "openquake" ? ", " + format_short(hz.investigation_time_years) + " yr" : std::string()) << ")";
    if (hz.dropped_low + hz.dropped_high > 0)
        out << "; left out: " << hz.dropped_low << " point(s) of probability 1 below, " << hz.dropped_high << " of rate 0 above";
    out << "\nbeyond its points the curve is extrapolated log-log with the end slopes (" << std::setprecision(3) << hz.curve.slope_below()
        << " below, " << hz.curve.slope_above() << " above)\n";
    const std::size_t state = t.states.size() - 1, per_state = t.alphas.size() * t.radii.size();
    out << t.states[state] << ", " << format_short(r.exposure_years) << " years:\n";
    std::size_t width = 22;  // "scenario@floor" names of a suite on several floors run longer
    for (const ScenarioRisk& k : r.risk.scenarios) width = std::max(width, k.name.size() + 2);
    out << std::left << std::setw(static_cast<int>(width)) << "scenario" << std::right << "alpha [rad]  R [m]   rate_fit [1/yr] (95 %)               P_fit      rate_emp   P_emp      beyond\n";
    for (std::size_t s = 0; s < r.risk.scenarios.size(); ++s) {
        const ScenarioRisk& k = r.risk.scenarios[s];
        for (std::size_t a = 0; a < t.alphas.size(); ++a)
            for (std::size_t j = 0; j < t.radii.size(); ++j) {
                const std::size_t b = state * per_state + a * t.radii.size() + j;
                const double beyond = (k.below_fit[b] + k.above_fit[b]) / k.rate_fit[b];
                out << std::left << std::setw(static_cast<int>(width)) << k.name << std::right << std::setprecision(4) << std::setw(11) << t.alphas[a]
                    << std::setw(7) << t.radii[j] << std::scientific << std::setprecision(2) << std::setw(11) << k.rate_fit[b] << " ("
                    << k.rate_fit_lo[b] << " .. " << k.rate_fit_hi[b] << ")" << std::setw(11)
                    << probability_in(k.rate_fit[b], r.exposure_years) << std::setw(11) << k.rate_empirical[b] << std::setw(11)
                    << probability_in(k.rate_empirical[b], r.exposure_years) << std::defaultfloat << std::setprecision(2)
                    << std::setw(9) << 100 * beyond << " %\n";
            }
    }
}

}  // namespace

CLI::App* add_risk_command(CLI::App& app, RiskCommand& cmd) {
    CLI::App* r = app.add_subcommand("risk", "A suite file's fragility over a site's hazard curve: annual rate, probability in "
                                             "an exposure time, return period and deaggregation per scenario, block and damage state");
    r->add_option("--suite-file", cmd.suite_file, "A complete suite file (rocksweep suite -o ...)")
        ->required()->check(existing_file("a suite file"));
    r->add_option("--hazard", cmd.hazard,
                  "The site's hazard curve: a CSV \"PGA [g],annual_rate [1/yr]\" (or PGV [m/s], SA(T) [g]) or OpenQuake's "
                  "hazard_curve CSV (docs/risk.md)")
        ->required()->check(existing_file("a hazard curve file"));
    r->add_option("--hazard-site", cmd.hazard_site, "Row of an OpenQuake file with several sites (0-based)")->check(integer_in(0, 10000000));
    r->add_option("--exposure-years", cmd.exposure_years, "Exposure time t of the probability 1 - exp(-rate t) [yr]")
        ->check(number_in(1e-3, 1e5, "yr"))->capture_default_str();
    r->add_option("-o,--output", cmd.output, "Output HDF5 file")->required();
    r->add_flag("--overwrite", cmd.overwrite, "Replace an existing output file");
    r->add_flag("-q,--quiet", cmd.quiet, "Print nothing on success");
    return r;
}

void check_risk_options(const CLI::App& app, const std::vector<std::string>& args) {
    std::vector<std::string> model;
    for (const CLI::Option* o : app.get_options())
        if (o != app.get_config_ptr() && !o->get_lnames().empty()) model.push_back("--" + o->get_lnames().front());
    refuse_typed(app, args, model, "an option of the commands that run a model; risk reads the suite file, which holds the block "
                                   "and anchorages it was run with");
}

bool risk_defines_run(const std::string& name) {
    return name == "suite-file" || name == "hazard" || name == "hazard-site" || name == "exposure-years";
}

int run_risk(const RiskCommand& cmd, const std::string& config_text) {
    const auto start = std::chrono::steady_clock::now();
    if (std::filesystem::path(cmd.output).extension() != ".h5") throw InputError("output", cmd.output, "a file name ending in .h5");
    RiskReport r{cmd.suite_file, cmd.hazard, read_hazard_file("hazard", cmd.hazard, cmd.hazard_site), "", "", 50, {}, {}};
    r.fragility = read_suite_fragility(cmd.suite_file);
    check_same_measure(r.hazard.curve, cmd.hazard, r.fragility);
    r.intensity_measure = r.fragility.measure;
    r.intensity_units = hazard_measure_units(r.hazard.curve.measure());
    r.exposure_years = cmd.exposure_years;
    const OutputClaim claim("output", cmd.output);
    if (claim.exists() && !cmd.overwrite) throw InputError("output", cmd.output, "a new file; it exists: pass --overwrite to replace it");
    r.risk = suite_risk(r.hazard.curve, r.fragility);
    Provenance prov{ROCKSWEEP_VERSION, config_text, utc_now(), 1, 0.0};
    prov.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    write_risk(cmd.output, r, prov);
    if (!cmd.quiet) {
        print_summary(r, std::cout);
        std::cout << "wrote " << cmd.output << "\n";
    }
    return 0;
}

}  // namespace rocksweep
