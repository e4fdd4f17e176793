#pragma once
/// `--resume` continues a file only with the options that made it: every option the file's
/// /provenance/config records is compared with the options of the run that resumes it, so that
/// an option added to the program is checked without being listed here. Only what cannot change
/// a stored field or a result is free to differ (resumable_freely).
#include <set>
#include <string>

namespace rocksweep {

/// Options a resume may change: how the work is spread and saved (lanes, chunk,
/// checkpoint-interval), which part of it a job does (part, merge's parts), and what the file's
/// own attributes compare more precisely than the config's text can (refine and refine-axes,
/// accepted in any order and for files from before they were recorded; axis, by its values;
/// scenario, by the scenario groups the file holds, so that --scenario naming them all resumes;
/// floor, sa-period and sa-damping, by the suite file's floors and sa_oscillator in canonical
/// form, so that "0.50" resumes a floor written "0.5" and the refusal names them once).
const std::set<std::string>& resumable_freely();

/// Throws InputError(option, value now, "VALUE IN FILE, as PATH was computed with (...)") for the
/// first option whose value in `now` (the resuming run's effective config, config_file.hpp)
/// differs from `stored` (the file's /provenance/config); an option in only one of them is "not
/// given" in the other. Numbers compare as numbers (48 = 48.0). A file without a stored config
/// (from before it was recorded) is not checked.
void check_resumed_config(const std::string& path, const std::string& stored, const std::string& now);

}  // namespace rocksweep
