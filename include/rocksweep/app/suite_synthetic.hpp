#pragma once
/// The motions a suite makes on its ranks (docs/synthetic.md): N of one model, given or fitted
/// to one record (--synthetic-count), or N of the model fitted to each record of --suite
/// (--synthetic-per-record; with --synthetic-only the records themselves are not swept).
#include <CLI/CLI.hpp>

#include <memory>
#include <string>
#include <vector>

#include "rocksweep/app/suite_command.hpp"
#include "rocksweep/records/record_suite.hpp"
#include "rocksweep/synthetic/fitted_suite_motions.hpp"

namespace rocksweep {

/// --synthetic-count, --synthetic-per-record, --synthetic-only and the model's options.
void add_suite_synthetic_options(CLI::App& suite, SuiteCommand& cmd);

/// Refuses, naming the option as written: neither --suite nor --synthetic-count; the model's
/// options without a synthetic source; a model neither given nor fitted, or both
/// (--synthetic-count); --synthetic-per-record with --synthetic-count, with the model's own
/// parameters or --record, or without --suite; --synthetic-only without --synthetic-per-record.
void check_suite_synthetic_options(const CLI::App& app, const CLI::App& suite, const std::vector<std::string>& args,
                                   const SuiteCommand& cmd);

/// Refuses record `entry` of the suite `suite_path` when its PGA as read betrays a unit mistake,
/// unless `any_pga` (--record-any-pga).
void check_suite_record_pga(const std::string& suite_path, const SuiteRecord& entry, const Record& record, bool any_pga);

struct MadeMotions {
    std::shared_ptr<const MotionSource> source;                  ///< null: none
    std::shared_ptr<const synthetic::FittedSuiteMotions> fitted;  ///< the same, with --synthetic-per-record
    RecordSuite suite;  ///< with --synthetic-per-record, the suite whose records were fitted
};

/// The made motions of `cmd`. With --synthetic-per-record reads --suite and each record as the
/// suite reads it (its unit, dt, column and scale), refuses an implausible PGA as the suite
/// does, and fits the model to each (its horizontal component); every rank does the same, so
/// every rank has the same motions. Throws InputError naming the suite line of a record the
/// model cannot take.
MadeMotions make_suite_motions(const SuiteCommand& cmd);

/// With --synthetic-per-record, each fitted motion in `spec` carries its record's metadata
/// (event, station, ...); with --synthetic-only the spec, which read no record, gets the suite
/// file's name and metadata columns.
void label_fitted_motions(SuiteSpec& spec, const SuiteCommand& cmd, const MadeMotions& made);

}  // namespace rocksweep
