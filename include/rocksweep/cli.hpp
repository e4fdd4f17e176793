#pragma once
/// The command line: `rocksweep sweep | simulate | info`, options from flags and TOML files.
#include <string>

#include "rocksweep/mpi_session.hpp"
#include "rocksweep/options.hpp"

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
};

/// Runs a sweep on every rank of `mpi`; rank 0 writes `cmd.output`. Returns the exit status.
int run_sweep(const Options& opts, const SweepCommand& cmd, const std::string& config_text,
              const MpiSession& mpi);

struct SimulateCommand {
    std::string output;
    bool quiet = false;
    bool overwrite = false;  ///< replace an existing output file (refused otherwise)
};

/// One history on this rank (call it on one rank only); writes `cmd.output`. Returns the exit
/// status.
int run_simulate(const Options& opts, const SimulateCommand& cmd, const std::string& config_text);

}  // namespace rocksweep
