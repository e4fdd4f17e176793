#include "rocksweep/synthetic/model_motions.hpp"

#include <cstdio>

#include "rocksweep/core/errors.hpp"

namespace rocksweep::synthetic {

std::string motion_name(std::uint64_t seed, std::size_t index) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "synthetic_s%llu_%06zu", static_cast<unsigned long long>(seed), index);
    return buf;
}

std::string ModelMotions::describe() const {
    return "Rezaeian & Der Kiureghian model (docs/synthetic.md): " + synthetic::describe(generator_.parameters()) +
           "; motions 0 to " + std::to_string(count_ - 1) + " of seed " + std::to_string(seed_) + ", dt " +
           format_short(generator_.dt_s()) + " s, " + std::to_string(generator_.samples()) + " samples";
}

}  // namespace rocksweep::synthetic
