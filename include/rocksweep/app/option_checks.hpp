#pragma once
/// Validators for command-line and config values. Each message says which of three things is
/// wrong — not a number, not an integer, out of range — and what is allowed; the value is
/// shortened (errors.hpp). CLI11 prefixes the option's name; run_cli turns "--x: " into
/// "--x = " so that every bad value reads "--x = VALUE is invalid: WHY; allowed: RANGE".
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace rocksweep {

/// A finite number in [lo, hi]; `open_lo` / `open_hi` exclude an end. `unit` follows the range
/// ("m", "rad/s"; may be empty). --help shows "NUMBER in (0, 1e3] m".
CLI::Validator number_in(double lo, double hi, const std::string& unit, bool open_lo = false, bool open_hi = false);
/// A whole number in [lo, hi], written in decimal digits.
CLI::Validator integer_in(long long lo, long long hi);
/// A whole number from `allowed`.
CLI::Validator integer_of(std::vector<long long> allowed);
/// A word from `allowed` (exact, case-sensitive).
CLI::Validator one_of(std::vector<std::string> allowed);
/// The name of an existing regular file: not empty, not a directory. `what` names its content.
CLI::Validator existing_file(const std::string& what);
/// Notes every file named by an option checked with existing_file (of `app` and of the command
/// chosen) as an input of the run, which no output may then replace (io/run_inputs.hpp): a new
/// option naming a file is covered by its validator alone.
void note_file_inputs(CLI::App& app);

/// Throws InputError for the first of `options` ("--phase", ...) typed on the command line
/// (`args`, without the program name), with its value(s) and `why` it does not apply: a
/// command refuses what it would otherwise silently ignore. Values from a config file are not
/// typed and pass (a config shared between commands holds options of each).
void refuse_typed(const CLI::App& app, const std::vector<std::string>& args, const std::vector<std::string>& options,
                  const std::string& why);

/// The options that shape a sweep's pulses and their region: what commands that are not driven
/// by pulses (basin, suite, design --suite) refuse.
inline const std::vector<std::string> pulse_region_options{
    "--omega-ratio-range", "--omega-ratio-points", "--amplitude-ratio-range", "--amplitude-ratio-points", "--phase",
    "--vertical-amplitude", "--vertical-phase", "--cycles"};

/// 1e+12 -> "1e12", 0.001 -> "0.001", 3.14159265 -> "3.14159": how ranges are written.
std::string format_bound(double x);

}  // namespace rocksweep
