#pragma once
/// `rocksweep synth`: motions of the stochastic ground-motion model (docs/synthetic.md), its
/// parameters given or fitted to a record, written as two-column records that `simulate
/// --record` and `suite --suite` read, with a suite CSV listing them.
#include <CLI/CLI.hpp>

#include <cstdint>
#include <string>

#include "rocksweep/app/options.hpp"
#include "rocksweep/records/record.hpp"
#include "rocksweep/synthetic/ground_model.hpp"

namespace rocksweep {

/// Where the model's parameters come from and which motions: shared by `synth` and `suite`.
struct SyntheticSource {
    SingleOptions record;                 ///< --record and how to read it (record_source)
    synthetic::ModelParameters params;    ///< --arias ... --zeta, --fc
    double dt_s = 0.0;                    ///< 0: the record's, or 0.01 s
    double duration_s = 0.0;              ///< 0: default_duration_s
    std::uint64_t seed = 1;
    std::size_t count = 0;                ///< motions; 0 = none (suite: no synthetic source)
    bool any_pga = false;                 ///< --record-any-pga: fit a record whose PGA as read is implausible

    bool fitted() const { return !record.record.empty(); }
};

/// The model options: --arias, --d595, --tmid, --f-mid, --f-slope, --zeta, --fc, --dt,
/// --motion-duration, --seed, --count and, for a fit, --record with its reading options.
void add_synthetic_options(CLI::App& sub, SyntheticSource& source);

/// Refuses a source that is neither fitted nor fully given, or both (names the option typed).
void check_synthetic_options(const CLI::App& sub, const SyntheticSource& source);

/// The parameters and sampling of a checked source: fits when --record is given (printing the
/// fit to `log` unless null). Throws InputError for a record the model cannot take, and, unless
/// any_pga, for one whose PGA as read betrays a unit mistake (as simulate and suite do).
struct ResolvedSource {
    synthetic::ModelParameters params;
    double dt_s = 0.0, duration_s = 0.0;
};
ResolvedSource resolve(const SyntheticSource& source, std::ostream* log);

/// The model fitted to `record` as read (its horizontal component; the vertical is not the
/// model's), sampled at `source`'s --dt (default the record's) over its --motion-duration, with
/// its --fc: what resolve() gives for --record, and `suite --synthetic-per-record` for each
/// record of its suite. Throws InputError as fit_model does.
ResolvedSource fit_to_record(const Record& record, const SyntheticSource& source, std::ostream* log);

struct SynthCommand {
    SyntheticSource source;
    std::size_t first = 0;  ///< index of the first motion written
    std::string output;     ///< folder
    bool overwrite = false, quiet = false;
};

CLI::App* add_synth_command(CLI::App& app, SynthCommand& cmd);

/// Writes motions first .. first + count - 1 into the folder (made if missing) and its
/// suite.csv. Returns the exit status; throws InputError before writing anything.
int run_synth(const SynthCommand& cmd);

}  // namespace rocksweep
