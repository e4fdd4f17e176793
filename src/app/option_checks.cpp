#include "rocksweep/app/option_checks.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "rocksweep/core/errors.hpp"
#include "rocksweep/io/run_inputs.hpp"

namespace rocksweep {

namespace {

/// The message body CLI11 puts after "--option: ".
std::string invalid(const std::string& value, const std::string& why, const std::string& allowed) {
    return (value.empty() ? std::string("\"\"") : shorten(value)) + " is invalid: " + why + "; allowed: " + allowed;
}

/// The whole of `in` as a double, or false: no leading blanks, no trailing characters.
bool parse_double(const std::string& in, double& x) {
    if (in.empty() || std::isspace(static_cast<unsigned char>(in[0]))) return false;
    char* end = nullptr;
    errno = 0;
    x = std::strtod(in.c_str(), &end);
    return end == in.c_str() + in.size();
}

/// Decimal digits with an optional sign: what a user means by a whole number.
bool looks_integer(const std::string& in) {
    std::size_t k = (!in.empty() && (in[0] == '-' || in[0] == '+')) ? 1 : 0;
    if (k == in.size()) return false;
    for (; k < in.size(); ++k)
        if (in[k] < '0' || in[k] > '9') return false;
    return true;
}

std::string join(const std::vector<std::string>& v) {
    std::string out;
    for (const std::string& s : v) out += (out.empty() ? "" : ", ") + s;
    return out;
}

}  // namespace

std::string format_bound(double x) {
    if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
    return format_short(x, 6);
}

CLI::Validator number_in(double lo, double hi, const std::string& unit, bool open_lo, bool open_hi) {
    const std::string range = std::string(open_lo ? "(" : "[") + format_bound(lo) + ", " + format_bound(hi) +
                              (open_hi ? ")" : "]") + (unit.empty() ? "" : " " + unit);
    return CLI::Validator(
        [=](std::string& in) -> std::string {
            double x;
            if (!parse_double(in, x)) return invalid(in, "not a number", "a number in " + range);
            if (!std::isfinite(x)) return invalid(in, "not a finite number", "a number in " + range);
            const bool ok = (open_lo ? x > lo : x >= lo) && (open_hi ? x < hi : x <= hi);
            if (!ok) return invalid(in, "out of range", "a number in " + range);
            return {};
        },
        "NUMBER in " + range, "number_in");
}

CLI::Validator integer_in(long long lo, long long hi) {
    const std::string range = "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
    return CLI::Validator(
        [=](std::string& in) -> std::string {
            double x;
            if (!looks_integer(in)) {
                if (!parse_double(in, x)) return invalid(in, "not a number", "an integer in " + range);
                return invalid(in, "not an integer", "an integer in " + range);
            }
            errno = 0;
            const long long v = std::strtoll(in.c_str(), nullptr, 10);
            if (errno == ERANGE || v < lo || v > hi) return invalid(in, "out of range", "an integer in " + range);
            return {};
        },
        "INTEGER in " + range, "integer_in");
}

CLI::Validator integer_of(std::vector<long long> allowed) {
    std::vector<std::string> words;
    for (long long v : allowed) words.push_back(std::to_string(v));
    const std::string list = join(words);
    return CLI::Validator(
        [=](std::string& in) -> std::string {
            double x;
            if (!looks_integer(in))
                return invalid(in, parse_double(in, x) ? "not an integer" : "not a number", "one of " + list);
            errno = 0;
            const long long v = std::strtoll(in.c_str(), nullptr, 10);
            for (long long a : allowed)
                if (errno != ERANGE && v == a) return {};
            return invalid(in, "not one of the allowed values", "one of " + list);
        },
        "ONE OF " + list, "integer_of");
}

CLI::Validator one_of(std::vector<std::string> allowed) {
    const std::string list = join(allowed);
    return CLI::Validator(
        [=](std::string& in) -> std::string {
            for (const std::string& a : allowed)
                if (in == a) return {};
            return invalid(in, "not a known word", "one of " + list);
        },
        "ONE OF " + list, "one_of");
}

CLI::Validator existing_file(const std::string& what) {
    return CLI::Validator(
        [=](std::string& in) -> std::string {
            namespace fs = std::filesystem;
            std::error_code ec;
            if (in.empty()) return invalid(in, "an empty file name", "the name of " + what);
            if (fs::is_directory(in, ec)) return invalid(in, "a directory", "the name of " + what + ", not a directory");
            if (!fs::exists(in, ec)) return invalid(in, "no such file", "the name of an existing file (" + what + ")");
            if (!fs::is_regular_file(in, ec)) return invalid(in, "not a regular file", "the name of " + what);
            return {};
        },
        "FILE", "existing_file");
}

void note_file_inputs(CLI::App& app) {
    forget_inputs();
    std::vector<CLI::App*> apps{&app};
    for (CLI::App* sub : app.get_subcommands()) apps.push_back(sub);
    for (CLI::App* a : apps)
        for (CLI::Option* opt : a->get_options()) {
            bool names_file = false;
            try {
                names_file = opt->get_validator("existing_file") != nullptr;
            } catch (const CLI::OptionNotFound&) {
            }
            if (!names_file) continue;
            const std::string what = opt->get_lnames().empty() ? "one of the " + opt->get_name() + " given"
                                                               : "the --" + opt->get_lnames().front() + " file";
            for (const std::string& path : opt->results()) note_input(what, path);
        }
}

void refuse_typed(const CLI::App& app, const std::vector<std::string>& args, const std::vector<std::string>& options,
                  const std::string& why) {
    for (const std::string& name : options) {
        const bool typed = std::any_of(args.begin(), args.end(),
                                       [&](const std::string& a) { return a == name || a.rfind(name + "=", 0) == 0; });
        if (!typed) continue;
        // The option is the app's (model options) or a subcommand's own.
        const CLI::Option* opt = app.get_option_no_throw(name);
        // Subcommands may share a name (simulate's and suite's --floor): the one typed holds the value.
        for (const CLI::App* sub : app.get_subcommands({}))
            if (const CLI::Option* o = sub->get_option_no_throw(name); o && (!opt || (opt->count() == 0 && o->count() > 0))) opt = o;
        std::string value;
        if (opt)
            for (const std::string& r : opt->results()) value += (value.empty() ? "" : " ") + r;
        throw InputError(name.substr(2), value, why);
    }
}

}  // namespace rocksweep
