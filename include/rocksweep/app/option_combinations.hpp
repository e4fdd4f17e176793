#pragma once
/// Options that mean nothing together, or one without another: refused, naming both, because
/// silently ignoring one of them is how a user's intent gets lost.
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "rocksweep/app/options.hpp"

namespace rocksweep {

/// Where an option's value came from.
enum class Source { unset, config, command_line };

/// After `app` parsed `args` (argv without the program name) into `o`, with `subcommand` the one
/// chosen ("sweep", "simulate" or "info"). Throws InputError(option, value, "not together with
/// --other (why)") or (..., "only with --other ..."). Between a config file and the command
/// line, a value from the command line wins over a config's irrelevant key without complaint:
/// a shared config (configs/smatteo.toml serves sweep and simulate) stays usable.
void check_combinations(const CLI::App& app, const std::string& subcommand, const Options& o,
                        const std::vector<std::string>& args);

}  // namespace rocksweep
