#include "rocksweep/errors.hpp"

#include <cmath>
#include <cstdio>

namespace rocksweep {

std::string format_number(double x) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.10g", x);
    return buf;
}

std::string cli_message(const InputError& e) {
    const bool option = e.field().find(' ') == std::string::npos;
    return (option ? "--" : "") + std::string(e.what());
}

void require_open(const std::string& field, double x, double lo, double hi, const std::string& allowed) {
    if (!(x > lo && x < hi)) throw InputError(field, format_number(x), allowed);
}

void require_closed(const std::string& field, double x, double lo, double hi, const std::string& allowed) {
    if (!(x >= lo && x <= hi)) throw InputError(field, format_number(x), allowed);
}

}  // namespace rocksweep
