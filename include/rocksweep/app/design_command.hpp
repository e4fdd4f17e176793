#pragma once
/// `rocksweep design`: the constant stiffness K and the adaptive K_min/K_max that keep the
/// largest share of a hazard region acceptable (docs/design.md). Each evaluation is a sweep.
#include <string>
#include <vector>

#include "rocksweep/app/cli.hpp"
#include "rocksweep/parallel/mpi_session.hpp"
#include "rocksweep/app/options.hpp"
#include "rocksweep/app/suite_command.hpp"

namespace CLI {
class App;
}

namespace rocksweep {

struct DesignCommand {
    SweepCommand run;                     ///< output, resume, overwrite, quiet, chunk, checkpoints, refine: as a sweep's
    std::vector<double> stiffness_range;  ///< K [N/m], LO HI; empty: the K of theta_f = 4 alpha (at most pi/2) to alpha/16
    std::vector<double> kmin_range{0.01, 1.0};  ///< K_min / K_max, LO HI
    std::size_t coarse_points = 9;        ///< first round, log-spaced, both ends included
    std::size_t points_per_side = 2;      ///< each later round, in each interval beside the best value
    int rounds = 4;                       ///< rounds after the coarse one
    double tolerance = 0.01;              ///< in log10 of the variable: an interval this narrow is not split
    double max_rotation_ratio = 0.0;      ///< acceptable: max |theta| / alpha at most this; 0: no limit
    double object_force_ratio = 0.0;      ///< the object's own force limit / (m g); 0: none (F_u only)
    double near_optimal = 0.005;          ///< values within this of the best criterion are reported as near-optimal
    bool keep_rounds = false;             ///< keep OUT.roundN.h5 once the design file is written (default: removed)
    /// --suite and its levels: the hazard is the records of a suite instead of the pulse region
    /// (hazard.suite empty: the region). Its run options are not used.
    SuiteCommand hazard;
    /// With --suite: a site's hazard curve; the criterion becomes the annual rate of the
    /// unacceptable state there (app/design_risk.hpp, docs/risk.md). Empty: the share of the runs.
    std::string hazard_curve;
    int hazard_site = -1;
    double exposure_years = 50;
};

/// The design command's own options (the run options are the sweep's, added by cli.cpp).
void add_design_options(CLI::App& design, DesignCommand& cmd);

/// The sweep's scenario options mean nothing to design, which chooses its scenarios, nor do
/// the region's with a suite as the hazard, or the suite's levels without one: refused when
/// typed on the command line (`args`, argv without the program name); a shared config's keys
/// are let through. Throws InputError.
void check_design_options(const CLI::App& app, const std::vector<std::string>& args, const DesignCommand& cmd);

/// Runs the search on every rank of `mpi`: one sweep (or suite) per round (rank 0 writes OUT.roundN.h5
/// beside the output, which --resume continues), then rank 0 writes `cmd.run.output`.
/// Returns the exit status (cli.hpp).
int run_design(const Options& opts, const DesignCommand& cmd, const std::string& config_text, const MpiSession& mpi);

}  // namespace rocksweep
