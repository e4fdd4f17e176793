#pragma once
/// `rocksweep risk`: a finished suite file's fragility integrated over a site's hazard curve,
/// for every anchorage scenario, block and damage state: the annual rate, its probability in an
/// exposure time, the return period and the deaggregation, in one HDF5 file (docs/risk.md).
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace rocksweep {

struct RiskCommand {
    std::string suite_file, hazard, output;
    int hazard_site = -1;  ///< OpenQuake row; -1: the file's only site
    double exposure_years = 50;
    bool overwrite = false, quiet = false;
};

/// Adds `risk` and its options to `app`.
CLI::App* add_risk_command(CLI::App& app, RiskCommand& cmd);

/// Refuses, naming it, a model option typed on the command line (block, anchorage, grid,
/// numerics): risk reads them from nothing, the suite file holds what was run. Throws InputError.
void check_risk_options(const CLI::App& app, const std::vector<std::string>& args);

/// The options a replay of `risk` needs (its own, not the block's or the run's): the provenance.
bool risk_defines_run(const std::string& name);

/// Reads, integrates and writes (one rank). Returns the exit status; throws InputError for bad
/// input before anything is written (a hazard curve of another measure than the suite's
/// included).
int run_risk(const RiskCommand& cmd, const std::string& config_text);

}  // namespace rocksweep
