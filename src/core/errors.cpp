#include "rocksweep/core/errors.hpp"

#include <cmath>
#include <cstdio>

namespace rocksweep {

InputError::InputError(const std::string& field, const std::string& value, const std::string& allowed)
    : std::runtime_error(field + " = " + shorten(value) + " is invalid: " + allowed),
      field_(field),
      value_(shorten(value)),
      allowed_(allowed) {}

std::string format_number(double x) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.10g", x);
    return buf;
}

std::string format_short(double x, int digits) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*g", digits, x);
    // "1e+308" reads better, and is what a user types, as "1e308".
    std::string s = buf;
    const std::size_t e = s.find('e');
    if (e == std::string::npos) return s;
    std::size_t k = e + 1;
    if (s[k] == '+') s.erase(k, 1);
    else if (s[k] == '-') ++k;
    while (k + 1 < s.size() && s[k] == '0') s.erase(k, 1);
    return s;
}

std::string shorten(const std::string& text, std::size_t max_chars) {
    std::string out;
    std::size_t chars = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        const bool continuation = (c & 0xC0) == 0x80;  // counts with the character it continues
        if (!continuation && chars == max_chars) return out + "…";
        if (!continuation) ++chars;
        if (c < 0x20 || c == 0x7F) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\x%02X", c);
            out += buf;
        } else {
            out += static_cast<char>(c);
        }
    }
    return out;
}

std::string cli_message(const InputError& e) {
    const std::string& f = e.field();
    const bool option = f.find(' ') == std::string::npos && f.find('.') == std::string::npos && f.rfind("--", 0) != 0;
    return (option ? "--" : "") + std::string(e.what());
}

void require_open(const std::string& field, double x, double lo, double hi, const std::string& allowed) {
    if (!(x > lo && x < hi)) throw InputError(field, format_number(x), allowed);
}

void require_closed(const std::string& field, double x, double lo, double hi, const std::string& allowed) {
    if (!(x >= lo && x <= hi)) throw InputError(field, format_number(x), allowed);
}

}  // namespace rocksweep
