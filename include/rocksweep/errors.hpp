#pragma once
/// Errors a user or a file can cause. `main` turns each into one message and exit status 2.
#include <stdexcept>
#include <string>

namespace rocksweep {

/// Bad input: names the field, the value given and what is allowed.
class InputError : public std::runtime_error {
public:
    InputError(const std::string& field, const std::string& value, const std::string& allowed)
        : std::runtime_error(field + " = " + value + " is invalid: " + allowed), field_(field) {}
    const std::string& field() const noexcept { return field_; }

private:
    std::string field_;
};

/// The message as a command line reads it: "--field = value is invalid: ..." when the field is
/// an option's name, the plain message otherwise (e.g. "spectra file = ...").
std::string cli_message(const InputError& e);

/// Throws InputError unless lo < x < hi (open bounds) — NaN is always rejected.
void require_open(const std::string& field, double x, double lo, double hi, const std::string& allowed);
/// Throws InputError unless lo <= x <= hi — NaN is always rejected.
void require_closed(const std::string& field, double x, double lo, double hi, const std::string& allowed);
std::string format_number(double x);

}  // namespace rocksweep
