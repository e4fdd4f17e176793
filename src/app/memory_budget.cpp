#include "rocksweep/app/memory_budget.hpp"

#include <unistd.h>

#include <cstdio>

#include "rocksweep/core/errors.hpp"

namespace rocksweep {

double memory_budget_bytes() {
    const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
    if (pages <= 0 || page <= 0) return 4e9;  // unknown: assume a small machine
    return 0.5 * static_cast<double>(pages) * static_cast<double>(page);
}

std::string format_bytes(double bytes) {
    const char* units[] = {"B", "kB", "MB", "GB", "TB", "PB", "EB", "ZB", "YB"};
    int u = 0;
    while (bytes >= 1000.0 && u < 8) {
        bytes /= 1000.0;
        ++u;
    }
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.3g %s", bytes, units[u]);
    return buf;
}

void require_memory(const std::string& field, const std::string& value, double bytes, const std::string& what) {
    const double budget = memory_budget_bytes();
    if (!(bytes <= budget))
        throw InputError(field, value,
                         what + " would need about " + format_bytes(bytes) + ", more than half of this machine's " +
                             format_bytes(2.0 * budget) + " of memory");
}

}  // namespace rocksweep
