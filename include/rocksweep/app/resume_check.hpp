#pragma once
/// `--resume` continues a file only with the options that made it: every option the file's
/// /provenance/config records (the effective config of config_file.hpp) is compared with the
/// options of the run that resumes it, so that an option added to the program is checked without
/// being listed here. Sweep, suite and design resume through this one check; they differ only in
/// which options are free to differ.
#include <map>
#include <set>
#include <string>

namespace rocksweep {

/// The "key = value" lines of an effective config, by key ("design.refine" under [design]);
/// tables and comments are skipped, values kept as written.
std::map<std::string, std::string> config_values(const std::string& text);

/// Options that only cut up and save the work (lanes, chunk, checkpoint-interval): they never
/// change a bit of the results, so any resume may change them. A design frees these only: no
/// attribute of its own file checks its refinement, the config does.
const std::set<std::string>& work_options();

/// What a sweep or suite resume may change: work_options(), which part of the work a job does
/// (part, merge's parts), and what the file's own attributes compare more precisely than the
/// config's text can (refine and refine-axes, accepted in any order and for files from before
/// they were recorded; axis, by its values; scenario, by the scenario groups the file holds, so
/// that --scenario naming them all resumes; floor, sa-period and sa-damping, by the suite file's
/// floors and sa_oscillator in canonical form, so that "0.50" resumes a floor written "0.5" and
/// the refusal names them once).
const std::set<std::string>& resumable_freely();

/// Throws InputError(option, value now, "VALUE IN FILE, as PATH was computed with (...)") for the
/// first option not in `free` whose value in `now` (the resuming run's effective config) differs
/// from `stored` (the file's /provenance/config); an option in only one of them is "not given"
/// in the other, a flag is "given". A command's table is not part of the option (a merged file's
/// merge.pulse is sweep's pulse). Numbers compare as numbers (48 = 48.0). A file without a
/// stored config (from before it was recorded) is not checked.
void check_resumed_config(const std::string& path, const std::string& stored, const std::string& now,
                          const std::set<std::string>& free = resumable_freely());

}  // namespace rocksweep
