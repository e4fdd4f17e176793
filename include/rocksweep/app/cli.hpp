#pragma once
/// The command line: `rocksweep sweep | simulate | info`, options from flags and TOML files.
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "rocksweep/parallel/mpi_session.hpp"
#include "rocksweep/app/options.hpp"

namespace rocksweep {

/// Exit statuses: 0 done, 2 bad input (nothing written), 1 failure while running,
/// 130 / 143 stopped by SIGINT / SIGTERM (the output file says which cells are done).
int run_cli(int argc, char** argv, const MpiSession& mpi);

struct SweepCommand {
    std::string output;
    bool resume = false, overwrite = false, quiet = false;
    std::size_t max_chunk = 512;
    double checkpoint_s = 5.0;
    std::size_t refine_stride = 0;  ///< 0: every cell; else boundary refinement from this spacing
    std::vector<std::string> refine_axes;  ///< the pair refinement works over; empty: amplitude_ratio, omega_ratio
    std::string part;  ///< "K/N": compute only part K of N (a job array); empty: every cell
};

/// How a command that sweeps runs: its output, resume, progress, chunks, refinement, checkpoints.
void add_run_options(CLI::App& sub, SweepCommand& cmd);

/// Runs a sweep on every rank of `mpi`; rank 0 writes `cmd.output`. Returns the exit status.
int run_sweep(const Options& opts, const SweepCommand& cmd, const std::string& config_text,
              const MpiSession& mpi);

struct MergeCommand {
    std::string output;
    std::vector<std::string> parts;  ///< files of `sweep --part K/N` runs (or any partial runs)
    bool overwrite = false, quiet = false;
};

/// Joins the part files of one sweep (the config's) into `cmd.output`, on this rank. Throws
/// InputError naming the file that is not a part of that sweep, or two parts that disagree.
int run_merge(const Options& opts, const MergeCommand& cmd, const std::string& config_text);

struct SimulateCommand {
    std::string output;
    bool quiet = false;
    bool overwrite = false;  ///< replace an existing output file (refused otherwise)
};

/// One history on this rank (call it on one rank only); writes `cmd.output`. Returns the exit
/// status.
int run_simulate(const Options& opts, const SimulateCommand& cmd, const std::string& config_text);

}  // namespace rocksweep
