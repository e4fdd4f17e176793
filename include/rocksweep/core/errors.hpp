#pragma once
/// Errors a user or a file can cause. `main` turns each into one message and exit status 2.
#include <stdexcept>
#include <string>

namespace rocksweep {

/// Bad input: names the field, the value given and what is allowed.
///
/// `field` is an option's name without dashes ("output"), a phrase with a space ("spectra
/// file"), or a neutral physics id with a dot ("block.mass") that the app layer rewrites into
/// the option the user wrote (options.hpp). The value is shortened to shorten()'s length: a
/// message is one readable line whatever the user pasted.
class InputError : public std::runtime_error {
public:
    InputError(const std::string& field, const std::string& value, const std::string& allowed);
    const std::string& field() const noexcept { return field_; }
    const std::string& value() const noexcept { return value_; }
    const std::string& allowed() const noexcept { return allowed_; }

private:
    std::string field_, value_, allowed_;
};

/// The message as a command line reads it: "--field = value is invalid: ..." when the field is
/// an option's name, the plain message otherwise (e.g. "spectra file = ...").
std::string cli_message(const InputError& e);

/// `text` cut to `max_chars` characters followed by "…" if longer (never inside a UTF-8
/// sequence); control characters are shown as `\xNN` so that a message stays on one line.
/// 160 keeps a deep path whole and still cuts a pasted blob.
std::string shorten(const std::string& text, std::size_t max_chars = 160);

/// Throws InputError unless lo < x < hi (open bounds) — NaN is always rejected.
void require_open(const std::string& field, double x, double lo, double hi, const std::string& allowed);
/// Throws InputError unless lo <= x <= hi — NaN is always rejected.
void require_closed(const std::string& field, double x, double lo, double hi, const std::string& allowed);
/// `x` with 10 significant digits in C's form (1e+300, 1e-05), as messages have long shown it.
std::string format_number(double x);
/// `x` with `digits` significant digits, exponents as a user types them: 1e308, 2.5e-7.
std::string format_short(double x, int digits = 10);

}  // namespace rocksweep
