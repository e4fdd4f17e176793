#pragma once
/// `rocksweep suite`: every record of a suite, scaled to each intensity level, on each block
/// size, for each anchorage scenario of the config; the results, the overturning spectra and
/// the fragility curves in one HDF5 file (docs/suite.md).
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "rocksweep/app/cli.hpp"
#include "rocksweep/app/options.hpp"
#include "rocksweep/app/synth_command.hpp"
#include "rocksweep/records/suite_sweep.hpp"

namespace rocksweep {

struct SuiteCommand {
    SweepCommand run;  ///< output, resume, chunks, checkpoints (refinement and parts: not here)
    std::string suite;            ///< CSV of records; may be empty with synthetic motions
    SyntheticSource synthetic;    ///< --synthetic-count N motions of the model (docs/synthetic.md)
    std::size_t synthetic_per_record = 0;  ///< --synthetic-per-record N: N motions fitted to each record of `suite`
    bool synthetic_only = false;           ///< --synthetic-only: sweep those alone, the records only fit the model
    std::string measure = "pga";
    std::vector<double> intensity_range{0.05, 1.5};
    std::size_t intensity_points = 30;
    std::vector<double> radius_range;  ///< empty: the block's own R
    std::size_t radius_points = 1;
    std::vector<double> alpha_range;  ///< empty: the block's own alpha
    std::size_t alpha_points = 1;
    std::vector<double> damage_states{0.1, 0.3, 0.5};  ///< theta_max / alpha; overturning is always added
    std::vector<std::string> floors;  ///< --floor, as written (motion/floor_filter.hpp); empty: the ground
    double sa_period_s = 1.0;         ///< T of the Sa measure [s]
    double sa_damping = 0.05;         ///< zeta of the Sa measure
    bool check_sensitivity = false;   ///< rerun each run perturbed and flag those that change (SensitivityCheck)
};

/// The options that say which records at which levels and where the block stands (--suite,
/// --intensity-measure, --intensity-range, --intensity-points, --floor, --sa-period,
/// --sa-damping): the hazard of `suite`, and of `design --suite`.
void add_suite_hazard_options(CLI::App& sub, SuiteCommand& cmd);

/// Adds `suite` and its own options to `app`; the model options are the app's (fallthrough).
CLI::App* add_suite_command(CLI::App& app, SuiteCommand& cmd);

/// Refuses, naming it, an option typed on the command line that the suite would ignore (the
/// pulse and the spectra grid, refinement), and the synthetic options' contradictions
/// (check_suite_synthetic_options). `suite` is the subcommand.
void check_suite_options(const CLI::App& app, const CLI::App& suite, const std::vector<std::string>& args,
                         const SuiteCommand& cmd);

/// The cells of the suite that `opts` (block, scenarios, numerics) and `cmd` describe: reads
/// the suite and its records; measures the made motions unless `made_measures` is none
/// (run_suite measures them over its ranks). Throws InputError naming the option.
SuiteSpec make_suite_spec(const Options& opts, const SuiteCommand& cmd,
                          SuiteMotions::Measures made_measures = SuiteMotions::Measures::all);

/// Runs the suite on every rank of `mpi`; rank 0 writes `cmd.run.output`. Returns the exit status.
int run_suite(const Options& opts, const SuiteCommand& cmd, const std::string& config_text, const MpiSession& mpi);

}  // namespace rocksweep
