#pragma once
/// The options a file was computed with (its /provenance/config, the effective config of
/// config_file.hpp) against those of this run: what lets a run continue a file.
#include <map>
#include <string>

namespace rocksweep {

/// The "key = value" lines of an effective config, by key ("design.refine" under [design]);
/// tables and comments are skipped, values kept as written.
std::map<std::string, std::string> config_values(const std::string& text);

/// Throws InputError unless `config_text` holds the options `path` was computed with, but for
/// those that only cut up the work (--chunk, --lanes, --checkpoint-interval): the first that
/// differs is named as the user writes it, with this run's value and the file's
/// ("--strength-ratio = 0.5 is invalid: 0.4, as PATH was computed with ..."). `what` names the
/// kind of run in the message ("design"). A file without a readable /provenance/config is
/// refused as damaged or not rocksweep's.
void check_same_options(const std::string& path, const std::string& config_text, const std::string& what);

}  // namespace rocksweep
